// `facet render-gl`: the same scene and settings as `facet render`, drawn by the OpenGL twin
// (app/gl) in a headless EGL context, for comparing the two pictures and timings by eye.

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "facet/image_io.hpp"
#include "facet/scene_io.hpp"
#include "gl_context.hpp"
#include "gl_renderer.hpp"

namespace facet::app {
namespace {

struct GlRenderOptions {
    std::string scene;
    std::string output;
    std::string mode = "solid";
    std::string shader = "painter";
    std::string interp = "perspective";
    std::string lighting = "off";
    std::string filter = "bilinear";
    std::string texture;
    std::string size;
    std::string background = "5C5C5C";
    bool cull = false;
    bool combine = false;
    bool normals = false;
    bool legend = false;
    bool stats = false;
    double nearPlane = 0.0;
    int pointSize = 5;
    int frames = 1;
};

int bad(const std::string& message) {
    std::fprintf(stderr, "facet render-gl: %s\n", message.c_str());
    return kBadInput;
}

int failed(const std::string& message) {
    std::fprintf(stderr, "facet render-gl: %s\n", message.c_str());
    return kFailed;
}

/// "WxH" with both sides in 1…16384, as `facet render` reads it.
bool parseSize(const std::string& text, int& w, int& h) {
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos) return false;
    const char* b = text.data();
    const char* e = b + text.size();
    const auto r1 = std::from_chars(b, b + x, w);
    const auto r2 = std::from_chars(b + x + 1, e, h);
    return r1.ec == std::errc{} && r1.ptr == b + x && r2.ec == std::errc{} && r2.ptr == e &&
           w >= 1 && h >= 1 && w <= 16384 && h <= 16384;
}

/// RRGGBB, optionally after # or 0x.
bool parseHexColor(std::string text, std::uint32_t& rgb) {
    if (text.rfind('#', 0) == 0) text.erase(0, 1);
    if (text.rfind("0x", 0) == 0 || text.rfind("0X", 0) == 0) text.erase(0, 2);
    if (text.size() != 6) return false;
    const auto r = std::from_chars(text.data(), text.data() + 6, rgb, 16);
    return r.ec == std::errc{} && r.ptr == text.data() + 6;
}

std::vector<std::string> choices(const std::vector<std::string_view>& names) {
    return {names.begin(), names.end()};
}

int runGlRender(const GlRenderOptions& o) {
    RenderSettings settings;
    settings.mode = *parseDrawMode(o.mode);  // CLI11 has checked the names
    settings.shader = *parseShader(o.shader);
    const std::optional<InterpSpec> interp = parseInterpSpec(o.interp);
    if (!interp) return bad("--interp wants affine, perspective or subdivided[:N]");
    settings.interp = interp->interp;
    settings.subdivision = interp->subdivision;
    settings.lighting = *parseLighting(o.lighting);
    settings.filter = *parseFilter(o.filter);
    settings.combine = o.combine;
    settings.showNormals = o.normals;
    settings.depthLegend = o.legend;
    settings.cullBackFaces = o.cull;
    settings.nearPlane = o.nearPlane;
    settings.pointSize = o.pointSize;
    if (!parseHexColor(o.background, settings.background))
        return bad("--background wants a hex colour RRGGBB, got '" + o.background + "'");

    Result<Scene> loaded = loadScene(o.scene);
    if (!loaded) return bad(loaded.error().what());
    Scene& scene = loaded.value();
    if (!o.texture.empty()) {
        if (Status st = loadSceneTexture(scene, o.texture)) return bad(st->what());
    }
    if (settings.shader == ShaderKind::Texture && !scene.texture)
        return bad(o.scene + ": the texture shader needs a texture; give one with --texture");
    if (!o.size.empty()) {
        int w = 0, h = 0;
        if (!parseSize(o.size, w, h))
            return bad("--size wants WxH with 1..16384 each, got '" + o.size + "'");
        scene.camera.focal *= static_cast<double>(w) / scene.camera.width;  // same field of view
        scene.camera.width = w;
        scene.camera.height = h;
    }

    Result<GlContext> context = GlContext::createHeadless();
    if (!context) return failed(context.error().what());
    Result<GlRenderer> renderer = GlRenderer::create();
    if (!renderer) return failed(renderer.error().what());
    Framebuffer frame;
    GlStats last;
    std::vector<double> ms;
    for (int i = 0; i < std::max(1, o.frames); ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        const Result<GlStats> stats = renderer->render(scene, settings, frame);
        const auto t1 = std::chrono::steady_clock::now();
        if (!stats) return failed(stats.error().what());
        last = stats.value();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    if (Status st = writePng(frame, o.output)) return failed(st->what());
    std::printf("wrote %s (%dx%d, %s, %s, %s, lighting %s) with %s\n", o.output.c_str(),
                frame.width, frame.height, o.mode.c_str(), o.shader.c_str(), o.interp.c_str(),
                o.lighting.c_str(), context->description().c_str());
    if (ms.size() > 1) {
        std::sort(ms.begin(), ms.end());
        const std::size_t n = ms.size();
        const double median = n % 2 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
        std::printf("median %.3f ms (min %.3f, max %.3f) over %zu frames\n", median, ms.front(),
                    ms.back(), n);
    }
    if (o.stats) {
        std::printf(
            "submitted: %zu triangles, %zu lines, %zu points, %zu normals; %zu bytes sent\n",
            last.trianglesIn, last.linesDrawn, last.pointsDrawn, last.normalsDrawn,
            last.uploadBytes);
        std::printf("last frame: upload %.3f ms, draw %.3f ms, readback %.3f ms\n", last.uploadMs,
                    last.drawMs, last.readbackMs);
        if (settings.shader == ShaderKind::Depth)
            std::printf("depth range: %.6g .. %.6g\n", last.depthNear, last.depthFar);
    }
    return kOk;
}

}  // namespace

void addGlRenderCommand(CLI::App& app, int& exitCode) {
    auto opts = std::make_shared<GlRenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render-gl", "Render a .scene file with the OpenGL twin (headless EGL) to a PNG image");
    cmd->add_option("scene", opts->scene, "The .scene file")->required();
    cmd->add_option("-o,--output", opts->output, "Output PNG path")->required();
    cmd->add_option("--mode", opts->mode, "Draw mode")
        ->check(CLI::IsMember(choices(drawModeNames())))
        ->capture_default_str();
    cmd->add_option("--shader", opts->shader, "Shader")
        ->check(CLI::IsMember(choices(shaderNames())))
        ->capture_default_str();
    cmd->add_option("--interp", opts->interp,
                    "affine or perspective (subdivided[:N] is drawn perspective-correct)")
        ->capture_default_str();
    cmd->add_option("--lighting", opts->lighting, "Lighting: off, gouraud or phong")
        ->check(CLI::IsMember(choices(lightingNames())))
        ->capture_default_str();
    cmd->add_option("--texture", opts->texture, "Texture image, replacing the scene's");
    cmd->add_option("--filter", opts->filter, "Texture filter")
        ->check(CLI::IsMember(choices(filterNames())))
        ->capture_default_str();
    cmd->add_flag("--combine", opts->combine, "Texture shader: texel × (lit) vertex colour");
    cmd->add_flag("--normals", opts->normals, "Draw vertex normals as red segments");
    cmd->add_flag("--legend", opts->legend, "Depth shader: draw the near/far legend bar");
    cmd->add_flag("--cull", opts->cull, "Drop back-facing triangles");
    cmd->add_option("--size", opts->size, "Image size WxH (focal length scales with the width)");
    cmd->add_option("--background", opts->background, "Background colour, hex RRGGBB")
        ->capture_default_str();
    cmd->add_option("--near", opts->nearPlane, "Near plane distance (default: mesh size/1000)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--point-size", opts->pointSize, "Side of the vertex squares in pixels")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    cmd->add_option("--frames", opts->frames, "Render N frames and print the median time")
        ->check(CLI::Range(1, 100000));
    cmd->add_flag("--stats", opts->stats, "Print what was submitted and where the time went");
    cmd->callback([opts, &exitCode] { exitCode = runGlRender(*opts); });
}

}  // namespace facet::app
