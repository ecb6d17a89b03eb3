#pragma once
// Sub-commands of the `facet` tool. Each registers its options on the parent app and returns
// the exit status through the callback result it stores.

#include <CLI/CLI.hpp>

namespace facet::app {

/// Exit codes shared by every command: 0 success, 1 failure while working, 2 bad input.
enum ExitCode : int { kOk = 0, kFailed = 1, kBadInput = 2 };

/// `facet render SCENE -o OUT.png [options]`.
void addRenderCommand(CLI::App& app, int& exitCode);

/// `facet generate KIND -o OUT.off [options]`.
void addGenerateCommand(CLI::App& app, int& exitCode);

/// `facet render-gl SCENE -o OUT.png [options]`: the OpenGL twin, headless through EGL.
void addGlRenderCommand(CLI::App& app, int& exitCode);

/// `facet bench [--threads N] [--csv F] [--chart F.png] [--scaling] [--quick] ...`.
void addBenchCommand(CLI::App& app, int& exitCode);

/// `facet accuracy SCENE... [-o DIR] [--samples N] [--frames N] [--quick] [--no-chart]`.
void addAccuracyCommand(CLI::App& app, int& exitCode);

/// `facet sweeps [-o DIR] [--only NAME,...] [--quick] [--no-chart]`: the stability sweeps.
void addSweepsCommand(CLI::App& app, int& exitCode);

/// `facet inspect SCENE X Y [render options]`: one pixel's history, fragment by fragment.
void addInspectCommand(CLI::App& app, int& exitCode);

}  // namespace facet::app
