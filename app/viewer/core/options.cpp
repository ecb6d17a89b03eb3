#include "options.hpp"

#include <charconv>
#include <vector>

#include <CLI/CLI.hpp>

#include "facet/camera.hpp"
#include "renderer_choice.hpp"

namespace facet::view {
namespace {

std::vector<std::string> choices(const std::vector<std::string_view>& names) {
    return {names.begin(), names.end()};
}

}  // namespace

bool parseSize(const std::string& text, int& width, int& height) {
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos) return false;
    const char* b = text.data();
    const char* e = b + text.size();
    int w = 0, h = 0;
    const auto r1 = std::from_chars(b, b + x, w);
    const auto r2 = std::from_chars(b + x + 1, e, h);
    if (r1.ec != std::errc{} || r1.ptr != b + x || r2.ec != std::errc{} || r2.ptr != e)
        return false;
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide) return false;
    width = w;
    height = h;
    return true;
}

ParsedOptions parseOptions(int argc, const char* const* argv) {
    ParsedOptions out;
    ViewerOptions& o = out.options;
    std::string size;
    CLI::App app{
        "facet-view: the facet rasterizer in a window. Drag with the left button to orbit, the "
        "right or middle one to pan, turn the wheel to zoom; F1 or ? lists every key, F12 or P "
        "saves a screenshot, Esc closes what is open, Ctrl+Q quits."};
    app.add_option("scene", o.scene,
                   "The .scene file or bare .off/.obj mesh to open (default: "
                   "assets/default.scene)");
    app.add_option("--size", size, "Window size WxH (default: the scene's, within the screen)");
    app.add_flag("--keep-scene-size", o.keepSceneSize,
                 "Render at the scene's size, letterboxed, instead of following the window");
    app.add_option("--frames", o.frames, "Exit after N frames (default: when the window closes)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--screenshot", o.screenshot, "At exit, write the engine frame to this PNG");
    app.add_option("--window-shot", o.windowShot,
                   "At exit, write the whole window (frame and panels) to this PNG");
    app.add_option("--state", o.statePath,
                   "At exit, write the camera, light and material to this text file");
    app.add_flag("--no-vsync", o.noVsync, "Do not wait for the display between frames");
    app.add_flag("--fps-report", o.fpsReport,
                 "At exit, print the median fps and how the frame time splits");
    app.add_option("--renderer", o.renderer,
                   "Who draws the frame: cpu (the engine), gl (the OpenGL twin, in this window's "
                   "context) or split (CPU left, OpenGL right); G cycles them")
        ->check(CLI::IsMember(choices(rendererNames())))
        ->capture_default_str();
    app.add_flag("--compare", o.compare, "Start in the Compare view (affine | perspective)");
    app.add_flag("--difference", o.difference,
                 "Start in the Compare view (or --renderer split) showing the per-pixel "
                 "difference as a heat map");
    app.add_flag("--hide-panels", o.hidePanels, "Start with the panels hidden (Tab shows them)");
    app.add_flag("--serial", o.serial,
                 "Render the next frame only after drawing this one (default: at the same time)");
    app.add_option("--texture", o.texture, "Texture image replacing the scene's");
    app.add_option("--up", o.up,
                   "World axis shown up for a bare mesh, x, y or z (default y; Z-up scans and CAD "
                   "models want z); framing and orbiting use it, a saved scene keeps it");
    app.add_option("--ui-scale", o.uiScale,
                   "Scale of the panels' fonts and widgets (default: the monitor's content scale)")
        ->check(CLI::Range(0.5, 4.0));
    app.add_option("--mode", o.mode, "Draw mode")
        ->check(CLI::IsMember(choices(drawModeNames())))
        ->capture_default_str();
    app.add_option("--shader", o.shader,
                   "Shader (default: texture for a textured mesh with uv, else painter)")
        ->check(CLI::IsMember(choices(shaderNames())));
    app.add_option("--interp", o.interp, "Interpolation: affine, perspective, subdivided[:N]")
        ->capture_default_str();
    app.add_option("--lighting", o.lighting,
                   "Lighting (default: gouraud for a textured mesh or a bare mesh, else off)")
        ->check(CLI::IsMember(choices(lightingNames())));
    app.add_option("--filter", o.filter, "Texture filter")
        ->check(CLI::IsMember(choices(filterNames())))
        ->capture_default_str();
    app.add_flag("--combine", o.combine, "Texture shader: texel times the (lit) vertex colour");
    app.add_option("--view", o.view, "Debug view instead of the shaded image (README, Debug views)")
        ->check(CLI::IsMember(choices(debugViewNames())))
        ->capture_default_str();
    app.add_flag("--cull", o.cull, "Drop back faces");
    app.add_flag("--normals", o.normals, "Draw the vertex normals");
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        out.exit = true;
        out.text = app.help();
        return out;
    } catch (const CLI::ParseError& e) {
        out.exit = true;
        out.exitCode = 2;
        out.text = std::string("facet-view: ") + e.what() + " (see 'facet-view --help')";
        return out;
    }
    if (!size.empty() && !parseSize(size, o.width, o.height)) {
        out.exit = true;
        out.exitCode = 2;
        out.text = "facet-view: --size wants WxH with 1.." + std::to_string(kMaxImageSide) +
                   " each, got '" + size + "'";
        return out;
    }
    // The interpolation Compare and the CPU | OpenGL view share one divider: one at a time.
    if (o.compare && o.renderer != "cpu") {
        out.exit = true;
        out.exitCode = 2;
        out.text = "facet-view: --compare compares two CPU renders; it cannot go with --renderer " +
                   o.renderer + " (--renderer split already compares CPU and OpenGL)";
        return out;
    }
    if (o.difference && o.renderer == "cpu") o.compare = true;
    if (!parseInterpSpec(o.interp)) {
        out.exit = true;
        out.exitCode = 2;
        out.text =
            "facet-view: --interp wants affine, perspective or subdivided[:N] with N in "
            "2..256, got '" +
            o.interp + "'";
    }
    return out;
}

Status applyOptions(const ViewerOptions& o, RenderSettings& settings) {
    const auto mode = parseDrawMode(o.mode);
    const auto shader = o.shader.empty() ? std::optional(settings.shader) : parseShader(o.shader);
    const auto interp = parseInterpSpec(o.interp);
    const auto lighting =
        o.lighting.empty() ? std::optional(settings.lighting) : parseLighting(o.lighting);
    const auto filter = parseFilter(o.filter);
    const auto view = parseDebugView(o.view);
    if (!mode || !shader || !interp || !lighting || !filter || !view)
        return Error{{}, "unknown mode, shader, interpolation, lighting, filter or view name"};
    settings.mode = *mode;
    settings.shader = *shader;
    settings.interp = interp->interp;
    settings.subdivision = interp->subdivision;
    settings.lighting = *lighting;
    settings.filter = *filter;
    settings.combine = settings.combine || o.combine;
    settings.cullBackFaces = o.cull;
    settings.showNormals = o.normals;
    settings.view = *view;
    return {};
}

}  // namespace facet::view
