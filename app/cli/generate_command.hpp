#pragma once
// The `facet generate` sub-command: registers its options on the parent app; the exit status goes
// to `exitCode` (exit_code.hpp).

#include <CLI/CLI.hpp>

namespace facet::app {

/// `facet generate KIND -o OUT.off [options]`.
void addGenerateCommand(CLI::App& app, int& exitCode);

}  // namespace facet::app
