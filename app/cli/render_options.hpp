#pragma once
// The options `facet render` and `facet render-gl` share: one list registered on both
// sub-commands, one function that turns them into a loaded scene and RenderSettings, and one
// timing summary, so the two commands draw the same picture from the same command line. The
// options the viewer takes too come from the one option table (render_option_table.hpp).

#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "delayed_progress.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"
#include "render_option_table.hpp"

namespace facet::app {

/// The options of the render commands as the user typed them: the ones the viewer shares
/// (RenderOptionValues, declared once in the option table) and the command line's own.
struct RenderOptions : RenderOptionValues {
    std::string output;
    std::string eye;         ///< --eye X,Y,Z: the camera position, replacing the scene's
    std::string look;        ///< --look X,Y,Z: the look-at point, replacing the scene's
    std::string writeScene;  ///< --write-scene: save the scene (after --size, --texture) here
    std::string background = "5C5C5C";
    double normalLength = 0.0;
    bool legend = false;
    bool stats = false;
    double nearPlane = 0.0;
    int pointSize = 5;
    int frames = 1;
    int threads = 0;
    int subPixelBits = kMaxSubPixelBits;
    int supersample = 1;  ///< samples per pixel axis (supersampling), 1…4
    int msaa = 1;         ///< samples per pixel of multisampling: 1, 2, 4 or 8
    /// Options this command takes no notice of: registered out of --help so that giving one is
    /// refused with why (prepareRender), instead of CLI11's bare "not expected".
    std::vector<std::pair<const CLI::Option*, std::string>> unused;
};

/// Which command the options are for: each lists only the options it uses.
enum class RenderCommand {
    engine,  ///< facet render: every option
    openGl,  ///< facet render-gl: no --threads, --subpixel-bits, --supersample or --view
    inspect  ///< facet inspect: what decides one pixel's history; no output, timing or overlays
};

/// Registers the options `command` uses on `cmd`; `interpHelp` describes --interp for it.
void addRenderOptions(CLI::App& cmd, RenderOptions& options, const std::string& interpHelp,
                      RenderCommand command);

/// Refuses an option the command does not use, then loads the scene or bare mesh (and
/// --texture), applies --size, fills `settings` and writes --write-scene. On bad input prints one
/// line prefixed with `command` on stderr and returns kBadInput (kFailed when the scene cannot be
/// written); kOk otherwise.
/// `progress` (optional) shows the loading phase.
int prepareRender(const RenderOptions& options, const char* command, Scene& scene,
                  RenderSettings& settings, DelayedProgress* progress = nullptr);

/// Prints `median X ms (min, max) over N frames` to `out` when more than one frame was timed.
void printFrameTimes(std::vector<double> ms, std::FILE* out = stdout);

/// Writes the frame to -o: a PNG file, or the PNG's bytes on standard output for "-".
/// `control` (optional) hears the rows encoded.
Status writeOutput(const Framebuffer& frame, const std::string& output,
                   const LoadControl* control = nullptr);

/// Where a command's report goes: stderr when -o - puts the image on stdout.
std::FILE* reportStream(const std::string& output);

}  // namespace facet::app
