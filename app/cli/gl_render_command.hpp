#pragma once
// The `facet render-gl` sub-command: registers its options on the parent app; the exit status goes
// to `exitCode` (exit_code.hpp).

#include <CLI/CLI.hpp>

namespace facet::app {

/// `facet render-gl SCENE -o OUT.png [options]`: the OpenGL twin, headless through EGL.
void addGlRenderCommand(CLI::App& app, int& exitCode);

}  // namespace facet::app
