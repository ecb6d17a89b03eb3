#pragma once
// The `facet bench` sub-command: registers its options on the parent app; the exit status goes
// to `exitCode` (exit_code.hpp).

#include <CLI/CLI.hpp>

namespace facet::app {

/// `facet bench [--threads N] [--csv F] [--chart F.png] [--scaling] [--quick] ...`.
void addBenchCommand(CLI::App& app, int& exitCode);

}  // namespace facet::app
