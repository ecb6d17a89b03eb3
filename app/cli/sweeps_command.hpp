#pragma once
// The `facet sweeps` sub-command: registers its options on the parent app; the exit status goes
// to `exitCode` (exit_code.hpp).

#include <CLI/CLI.hpp>

namespace facet::app {

/// `facet sweeps [-o DIR] [--only NAME,...] [--quick] [--no-chart]`: the stability sweeps.
void addSweepsCommand(CLI::App& app, int& exitCode);

}  // namespace facet::app
