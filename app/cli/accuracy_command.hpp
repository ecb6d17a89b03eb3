#pragma once
// The `facet accuracy` sub-command: registers its options on the parent app; the exit status goes
// to `exitCode` (exit_code.hpp).

#include <CLI/CLI.hpp>

namespace facet::app {

/// `facet accuracy SCENE... [-o DIR] [--samples N] [--frames N] [--quick] [--no-chart]`.
void addAccuracyCommand(CLI::App& app, int& exitCode);

}  // namespace facet::app
