// `facet render`: load a scene, render it with the fast path, write a PNG.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "facet/image_io.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "lab_render.hpp"
#include "render_options.hpp"

namespace facet::app {
namespace {

int runRender(const RenderOptions& o, const std::string& rendererName) {
    Scene scene;
    RenderSettings settings;
    if (const int code = prepareRender(o, "facet render", scene, settings); code != kOk)
        return code;
    if (rendererName == "lab") return renderLab(scene, settings, o.output);

    Renderer renderer;
    Framebuffer frame;
    RenderStats stats;
    std::vector<double> ms;
    for (int i = 0; i < std::max(1, o.frames); ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        Result<RenderStats> rendered = renderer.render(scene, settings, frame);
        const auto t1 = std::chrono::steady_clock::now();
        if (!rendered) {
            std::fprintf(stderr, "facet render: %s\n", rendered.error().what().c_str());
            return kBadInput;
        }
        stats = rendered.value();
        ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    std::FILE* info = reportStream(o.output);  // stderr when the PNG goes to stdout
    if (Status st = writeOutput(frame, o.output); !st) {
        std::fprintf(stderr, "facet render: %s\n", st.error().what().c_str());
        return kFailed;
    }
    std::fprintf(info, "wrote %s (%dx%d, %s, %s, %s, lighting %s%s%s)\n", o.output.c_str(),
                 frame.width, frame.height, o.mode.c_str(),
                 std::string(toString(settings.shader)).c_str(), o.interp.c_str(),
                 std::string(toString(settings.lighting)).c_str(),
                 settings.shader == ShaderKind::Texture
                     ? (std::string(", ") + std::string(toString(settings.filter)) +
                        (settings.combine ? ", combined" : ""))
                           .c_str()
                     : "",
                 o.cull ? ", culled" : "");
    printFrameTimes(ms, info);
    if (o.stats) {
        std::fprintf(info, "mesh: %zu vertices, %zu triangles%s%s\n", scene.mesh->vertexCount(),
                     scene.mesh->triangleCount(), scene.mesh->hasColors() ? ", colours" : "",
                     scene.mesh->hasUvs() ? ", uv" : "");
        std::fprintf(info, "triangles: %zu in, %zu culled, %zu clipped, %zu rasterized\n",
                     stats.trianglesIn, stats.trianglesCulled, stats.trianglesClipped,
                     stats.trianglesRasterized);
        std::fprintf(info, "lines: %zu, points: %zu, normals: %zu, fragments: %zu\n",
                     stats.linesDrawn, stats.pointsDrawn, stats.normalsDrawn, stats.fragments);
        std::fprintf(info, "per vertex: %zu bytes; varyings: %d floats (%.*s)\n", stats.vertexBytes,
                     stats.varyings, static_cast<int>(stats.varyingNames.size()),
                     stats.varyingNames.data());
        if (scene.texture)
            std::fprintf(info, "texture: %s, %dx%d, %d mip levels\n", scene.texturePath.c_str(),
                         scene.texture->width(), scene.texture->height(),
                         scene.texture->levelCount());
        if (settings.shader == ShaderKind::Depth)
            std::fprintf(info, "depth range: %.6g .. %.6g (near dark, far bright)\n",
                         stats.depthNear, stats.depthFar);
        std::fprintf(info,
                     "time: %.3f ms (last frame: clear %.3f, vertices %.3f, raster + shade %.3f, "
                     "post %.3f)\n",
                     ms.back(), stats.clearMs, stats.vertexMs, stats.rasterMs, stats.postMs);
    }
    return kOk;
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
    auto opts = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render", "Render a .scene file or a bare .off/.obj mesh to a PNG image");
    addRenderOptions(*cmd, *opts,
                     "Attribute interpolation: affine, perspective, subdivided[:N] (exact every N "
                     "pixels, affine between; N = 16 by default)");
    auto rendererName = std::make_shared<std::string>("engine");
    cmd->add_option("--renderer", *rendererName,
                    "engine (facet's), or lab: the course's pipeline through the lab's steps "
                    "(docs/lab.md)")
        ->check(CLI::IsMember({"engine", "lab"}));
    cmd->callback([opts, rendererName, &exitCode] { exitCode = runRender(*opts, *rendererName); });
}

}  // namespace facet::app
