#pragma once
// The `facet render` sub-command: registers its options on the parent app; the exit status goes
// to `exitCode` (exit_code.hpp).

#include <CLI/CLI.hpp>

namespace facet::app {

/// `facet render SCENE -o OUT.png [options]`.
void addRenderCommand(CLI::App& app, int& exitCode);

}  // namespace facet::app
