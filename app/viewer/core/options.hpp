#pragma once
// facet-view's command line: the scene to open, the start-up settings, and the few options that
// make the viewer scriptable for tests and benchmarks (--frames, --screenshot, --state...).

#include <string>

#include "facet/error.hpp"
#include "facet/settings.hpp"

namespace facet::view {

/// Everything the command line can say; empty strings and zeros mean "not given".
struct ViewerOptions {
    std::string scene;             ///< .scene file or bare mesh; empty: the default scene
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
    std::string texture;           ///< image replacing the scene's texture
    std::string up = "y";          ///< --up: the world axis a bare mesh opens with up
    double uiScale = 0.0;          ///< --ui-scale: fonts and widgets (0: the monitor's scale)

    // Start-up render settings, as `facet render` spells them (already checked when parsed).
    // Shader and lighting left empty: the scene decides (applyOpeningSettings, spec §9).
    std::string mode = "solid";
    std::string shader;
    std::string interp = "perspective";
    std::string lighting;
    std::string filter = "bilinear";
    std::string view = "none";  ///< --view: a debug view (debugViewNames())
    bool combine = false;
    bool cull = false;
    bool normals = false;
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

/// Parses "WxH" with 1…kMaxImageSide each.
bool parseSize(const std::string& text, int& width, int& height);

/// Applies the start-up settings to `settings` (shader and lighting only when given, combine
/// only when set); an unknown name gives an error (parseOptions already rejects them, this
/// guards direct callers).
Status applyOptions(const ViewerOptions& options, RenderSettings& settings);

}  // namespace facet::view
