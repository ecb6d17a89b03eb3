#pragma once
// The `facet inspect` sub-command: registers its options on the parent app; the exit status goes
// to `exitCode` (exit_code.hpp).

#include <CLI/CLI.hpp>

namespace facet::app {

/// `facet inspect SCENE X Y [render options]`: one pixel's history, fragment by fragment.
void addInspectCommand(CLI::App& app, int& exitCode);

}  // namespace facet::app
