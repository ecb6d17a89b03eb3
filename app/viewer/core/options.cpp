#include "options.hpp"

#include <CLI/CLI.hpp>

#include "renderer_choice.hpp"

namespace facet::view {

ParsedOptions parseOptions(int argc, const char* const* argv) {
    ParsedOptions out;
    ViewerOptions& o = out.options;
    o.up = "y";  // the viewer always has an up axis: a scene saved from a bare mesh keeps it
    CLI::App cli{
        "facet-view: the facet rasterizer in a window. Drag with the left button to orbit, the "
        "right or middle one to pan, turn the wheel to zoom; F1 or ? lists every key, F12 or P "
        "saves a screenshot, Esc closes what is open, Ctrl+Q quits."};
    // The render options `facet render` shares, from the one table; two worded for a window.
    const app::RegisteredOptions shared = app::addRenderOptionTable(cli, o);
    shared.at("scene")->description(
        "The .scene file or bare .off/.obj mesh to open (default: assets/default.scene)");
    shared.at("--size")->description("Window size WxH (default: the scene's, within the screen)");
    cli.add_flag("--keep-scene-size", o.keepSceneSize,
                 "Render at the scene's size, letterboxed, instead of following the window");
    cli.add_option("--frames", o.frames, "Exit after N frames (default: when the window closes)")
        ->check(CLI::NonNegativeNumber);
    cli.add_option("--screenshot", o.screenshot, "At exit, write the engine frame to this PNG");
    cli.add_option("--window-shot", o.windowShot,
                   "At exit, write the whole window (frame and panels) to this PNG");
    cli.add_option("--state", o.statePath,
                   "At exit, write the camera, light and material to this text file");
    cli.add_flag("--no-vsync", o.noVsync, "Do not wait for the display between frames");
    cli.add_flag("--fps-report", o.fpsReport,
                 "At exit, print the median fps and how the frame time splits");
    cli.add_option("--renderer", o.renderer,
                   "Who draws the frame: cpu (the engine), gl (the OpenGL twin, in this window's "
                   "context) or split (CPU left, OpenGL right); G cycles them")
        ->check(CLI::IsMember(app::choices(rendererNames())))
        ->capture_default_str();
    cli.add_flag("--compare", o.compare, "Start in the Compare view (affine | perspective)");
    cli.add_flag("--difference", o.difference,
                 "Start in the Compare view (or --renderer split) showing the per-pixel "
                 "difference as a heat map");
    cli.add_flag("--hide-panels", o.hidePanels, "Start with the panels hidden (Tab shows them)");
    cli.add_flag("--serial", o.serial,
                 "Render the next frame only after drawing this one (default: at the same time)");
    cli.add_option("--ui-scale", o.uiScale,
                   "Scale of the panels' fonts and widgets (default: the monitor's content scale)")
        ->check(CLI::Range(0.5, 4.0));
    try {
        cli.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        out.exit = true;
        out.text = cli.help();
        return out;
    } catch (const CLI::ParseError& e) {
        out.exit = true;
        out.exitCode = 2;
        out.text = std::string("facet-view: ") + e.what() + " (see 'facet-view --help')";
        return out;
    }
    if (Status checked = app::checkRenderOptions(o); !checked) {
        out.exit = true;
        out.exitCode = 2;
        out.text = "facet-view: " + checked.error().what();
        return out;
    }
    if (!o.size.empty()) app::parseSize(o.size, o.width, o.height);
    // The interpolation Compare and the CPU | OpenGL view share one divider: one at a time.
    if (o.compare && o.renderer != "cpu") {
        out.exit = true;
        out.exitCode = 2;
        out.text = "facet-view: --compare compares two CPU renders; it cannot go with --renderer " +
                   o.renderer + " (--renderer split already compares CPU and OpenGL)";
        return out;
    }
    if (o.difference && o.renderer == "cpu") o.compare = true;
    return out;
}

}  // namespace facet::view
