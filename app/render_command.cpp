// `facet render`: load a scene, render it with the fast path, write a PNG.

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
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"

namespace facet::app {
namespace {

struct RenderOptions {
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
    double normalLength = 0.0;
    bool stats = false;
    double nearPlane = 0.0;
    int pointSize = 5;
    int frames = 1;
};

/// Parses "WxH" into positive integers within the scene limits.
bool parseSize(const std::string& text, int& w, int& h) {
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos) return false;
    const char* b = text.data();
    const char* e = b + text.size();
    auto r1 = std::from_chars(b, b + x, w);
    auto r2 = std::from_chars(b + x + 1, e, h);
    return r1.ec == std::errc{} && r1.ptr == b + x && r2.ec == std::errc{} && r2.ptr == e &&
           w >= 1 && h >= 1 && w <= 16384 && h <= 16384;
}

/// Parses RRGGBB (an optional leading # or 0x is accepted).
bool parseHexColor(std::string text, std::uint32_t& rgb) {
    if (text.rfind("#", 0) == 0) text.erase(0, 1);
    if (text.rfind("0x", 0) == 0 || text.rfind("0X", 0) == 0) text.erase(0, 2);
    if (text.size() != 6) return false;
    auto r = std::from_chars(text.data(), text.data() + 6, rgb, 16);
    return r.ec == std::errc{} && r.ptr == text.data() + 6;
}

/// The engine's names for a setting, as CLI11 wants them; one list serves parsing and --help.
std::vector<std::string> choices(const std::vector<std::string_view>& names) {
    return {names.begin(), names.end()};
}

int bad(const std::string& message) {
    std::fprintf(stderr, "facet render: %s\n", message.c_str());
    return kBadInput;
}

int runRender(const RenderOptions& o) {
    RenderSettings settings;
    // CLI11 has already checked the names against the engine's lists (choices below).
    settings.mode = *parseDrawMode(o.mode);
    settings.shader = *parseShader(o.shader);
    const std::optional<InterpSpec> interp = parseInterpSpec(o.interp);
    if (!interp)
        return bad("--interp wants affine, perspective, subdivided or subdivided:N (N in 2.." +
                   std::to_string(kMaxSubdivision) + "), got '" + o.interp + "'");
    settings.interp = interp->interp;
    settings.subdivision = interp->subdivision;
    settings.lighting = *parseLighting(o.lighting);
    settings.filter = *parseFilter(o.filter);
    settings.combine = o.combine;
    settings.showNormals = o.normals || o.normalLength > 0.0;
    settings.normalLength = o.normalLength;
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
        return bad(o.scene +
                   ": the texture shader needs a texture: the scene names none (line 10 "
                   "or an OBJ map_Kd); give one with --texture IMAGE");
    if (settings.shader == ShaderKind::Texture && !scene.mesh.hasUvs())
        std::fprintf(stderr,
                     "facet render: warning: %s has no texture coordinates; every pixel samples "
                     "uv = (0, 0)\n",
                     scene.meshPath.c_str());
    if (!o.size.empty()) {
        int w = 0, h = 0;
        if (!parseSize(o.size, w, h))
            return bad("--size wants WxH with 1..16384 each, got '" + o.size + "'");
        // Scaling f with the width keeps the horizontal field of view.
        scene.camera.focal *= static_cast<double>(w) / scene.camera.width;
        scene.camera.width = w;
        scene.camera.height = h;
    }

    Renderer renderer;
    Framebuffer frame;
    RenderStats stats;
    std::vector<double> ms;
    for (int i = 0; i < std::max(1, o.frames); ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        stats = renderer.render(scene, settings, frame);
        const auto t1 = std::chrono::steady_clock::now();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    if (Status st = writePng(frame, o.output)) {
        std::fprintf(stderr, "facet render: %s\n", st->what().c_str());
        return kFailed;
    }
    std::printf("wrote %s (%dx%d, %s, %s, %s, lighting %s%s%s)\n", o.output.c_str(), frame.width,
                frame.height, o.mode.c_str(), o.shader.c_str(), o.interp.c_str(),
                o.lighting.c_str(),
                settings.shader == ShaderKind::Texture
                    ? (std::string(", ") + o.filter + (o.combine ? ", combined" : "")).c_str()
                    : "",
                o.cull ? ", culled" : "");
    if (o.frames > 1) {
        std::vector<double> sorted = ms;
        std::sort(sorted.begin(), sorted.end());
        const std::size_t n = sorted.size();
        const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
        std::printf("median %.3f ms (min %.3f, max %.3f) over %zu frames\n", median, sorted.front(),
                    sorted.back(), n);
    }
    if (o.stats) {
        std::printf("mesh: %zu vertices, %zu triangles%s%s\n", scene.mesh.vertexCount(),
                    scene.mesh.triangleCount(), scene.mesh.hasColors() ? ", colours" : "",
                    scene.mesh.hasUvs() ? ", uv" : "");
        std::printf("triangles: %zu in, %zu culled, %zu clipped, %zu rasterized\n",
                    stats.trianglesIn, stats.trianglesCulled, stats.trianglesClipped,
                    stats.trianglesRasterized);
        std::printf("lines: %zu, points: %zu, normals: %zu, fragments: %zu\n", stats.linesDrawn,
                    stats.pointsDrawn, stats.normalsDrawn, stats.fragments);
        std::printf("per vertex: %zu bytes; varyings: %d floats (%.*s)\n", stats.vertexBytes,
                    stats.varyings, static_cast<int>(stats.varyingNames.size()),
                    stats.varyingNames.data());
        if (scene.texture)
            std::printf("texture: %s, %dx%d, %d mip levels\n", scene.texturePath.c_str(),
                        scene.texture->width(), scene.texture->height(),
                        scene.texture->levelCount());
        if (settings.shader == ShaderKind::Depth)
            std::printf("depth range: %.6g .. %.6g (near dark, far bright)\n", stats.depthNear,
                        stats.depthFar);
        std::printf(
            "time: %.3f ms (last frame: clear %.3f, vertices %.3f, raster + shade %.3f, "
            "post %.3f)\n",
            ms.back(), stats.clearMs, stats.vertexMs, stats.rasterMs, stats.postMs);
    }
    return kOk;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto opts = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render a .scene file to a PNG image");
    cmd->add_option("scene", opts->scene, "The .scene file")->required();
    cmd->add_option("-o,--output", opts->output, "Output PNG path")->required();
    cmd->add_option("--mode", opts->mode, "Draw mode")
        ->check(CLI::IsMember(choices(drawModeNames())))
        ->capture_default_str();
    cmd->add_option("--shader", opts->shader, "Shader")
        ->check(CLI::IsMember(choices(shaderNames())))
        ->capture_default_str();
    cmd->add_option("--interp", opts->interp,
                    "Attribute interpolation: affine, perspective, subdivided[:N] (exact every N "
                    "pixels, affine between; N = 16 by default)")
        ->capture_default_str();
    cmd->add_option("--lighting", opts->lighting,
                    "Lighting: off, gouraud (per vertex) or phong (per pixel)")
        ->check(CLI::IsMember(choices(lightingNames())))
        ->capture_default_str();
    cmd->add_option("--texture", opts->texture,
                    "Texture image (PNG, JPEG, BMP, TGA), replacing the scene's");
    cmd->add_option("--filter", opts->filter, "Texture filter")
        ->check(CLI::IsMember(choices(filterNames())))
        ->capture_default_str();
    cmd->add_flag("--combine", opts->combine,
                  "Texture shader: multiply the texel by the (lit) vertex colour");
    cmd->add_flag("--normals", opts->normals, "Draw vertex normals as red segments");
    cmd->add_flag("--legend", opts->legend,
                  "Depth shader: draw a legend bar with the near and far depth it maps");
    cmd->add_option("--normal-length", opts->normalLength,
                    "Length of the normal segments in world units (implies --normals; default: "
                    "bounding-box diagonal / 100)")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--cull", opts->cull, "Drop back-facing triangles");
    cmd->add_option("--size", opts->size, "Image size WxH (focal length scales with the width)");
    cmd->add_option("--background", opts->background, "Background colour, hex RRGGBB")
        ->capture_default_str();
    cmd->add_option("--near", opts->nearPlane,
                    "Near plane distance (default: 1/1000 of the mesh size)")
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--point-size", opts->pointSize, "Side of the vertex squares in pixels")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    cmd->add_option("--frames", opts->frames, "Render N frames and print the median time")
        ->check(CLI::Range(1, 100000));
    cmd->add_flag("--stats", opts->stats, "Print mesh and draw statistics");
    cmd->callback([opts, &exitCode] { exitCode = runRender(*opts); });
}

}  // namespace facet::app
