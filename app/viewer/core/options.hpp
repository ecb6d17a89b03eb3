#pragma once
// facet-view's command line: the scene to open, the start-up settings, and the few options that
// make the viewer scriptable for tests and benchmarks (--frames, --screenshot, --state...).

#include <string>

#include "render_option_table.hpp"

namespace facet::view {

/// Everything the command line can say; empty strings and zeros mean "not given". The render
/// options `facet render` shares (scene, --size, --texture, --up, --shader...) are the option
/// table's (RenderOptionValues); applyRenderOptions applies them to the settings.
struct ViewerOptions : app::RenderOptionValues {
    int width = 0;                 ///< --size: window width (0: the scene's, within the screen)
    int height = 0;                ///< --size: window height
    bool keepSceneSize = false;    ///< render at the scene's size, letterboxed
    int frames = 0;                ///< exit after this many frames (0: when the window closes)
    std::string screenshot;        ///< at exit: the engine frame as PNG
    std::string windowShot;        ///< at exit: the whole window as PNG
    std::string statePath;         ///< at exit: camera, light and material as text
    bool noVsync = false;          ///< swap without waiting for the display
    bool fpsReport = false;        ///< at exit: median fps and stage split on stdout
    std::string renderer = "cpu";  ///< --renderer: cpu, gl (the OpenGL twin) or split
    bool compare = false;          ///< start in the Compare view (two CPU interpolations)
    bool difference = false;       ///< start in the difference heat map (Compare or split)
    bool hidePanels = false;       ///< start with the panels hidden (Tab shows them)
    bool serial = false;           ///< render and draw one after the other (for measuring)
    double uiScale = 0.0;          ///< --ui-scale: fonts and widgets (0: the monitor's scale)
};

/// Result of parsing: options to run with, or an exit code and text to print (help, errors).
struct ParsedOptions {
    ViewerOptions options;
    bool exit = false;  ///< true: print `text` and stop with `exitCode`
    int exitCode = 0;   ///< 0 after --help, 2 for bad input
    std::string text;   ///< help (stdout) or one error line (stderr)
};

/// Parses argv (argv[0] is the program name).
ParsedOptions parseOptions(int argc, const char* const* argv);

}  // namespace facet::view
