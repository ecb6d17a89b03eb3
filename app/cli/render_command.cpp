// `facet render`: load a scene, render it with the fast path, write a PNG.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "delayed_progress.hpp"
#include "exit_code.hpp"
#include "facet/image_io.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "lab_render.hpp"
#include "render_command.hpp"
#include "render_options.hpp"

namespace facet::app {
namespace {

int runRender(const RenderOptions& o, const std::string& rendererName) {
    Scene scene;
    RenderSettings settings;
    // Quiet for a second, then the phase on stderr: a 16384² frame takes tens of seconds.
    std::optional<DelayedProgress> progress(std::in_place, "facet render");
    if (const int code = prepareRender(o, "facet render", scene, settings, &*progress); code != kOk)
        return code;
    if (rendererName == "lab") {
        progress.reset();  // the lab's pipeline reports nothing
        return renderLab(scene, settings, o.output);
    }

    Renderer renderer;
    Framebuffer frame;
    RenderStats stats;
    std::vector<double> ms;
    const int frames = std::max(1, o.frames);
    for (int i = 0; i < frames; ++i) {
        if (frames == 1)
            progress->phase("drawing " + std::to_string(scene.camera.width) + "x" +
                            std::to_string(scene.camera.height));
        else
            progress->phase(
                "drawing frame " + std::to_string(i + 1) + " of " + std::to_string(frames),
                static_cast<float>(i) / static_cast<float>(frames));
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
    progress->phase("encoding " + (o.output == "-" ? std::string("to standard output") : o.output),
                    0.0f);
    const auto e0 = std::chrono::steady_clock::now();
    const Status written = writeOutput(frame, o.output, progress->control());
    const double encodeMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - e0).count();
    progress.reset();  // the line is cleared before the report
    if (!written) {
        std::fprintf(stderr, "facet render: %s\n", written.error().what().c_str());
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
        std::fprintf(info, "hierarchical depth: %zu triangle parts rejected\n", stats.hiZTriangles);
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
        std::fprintf(info, "png: %.3f ms to encode and write\n", encodeMs);
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
                     "pixels, affine between; N = 16 by default)",
                     RenderCommand::engine);
    auto rendererName = std::make_shared<std::string>("engine");
    cmd->add_option("--renderer", *rendererName,
                    "engine (facet's), or lab: the course's pipeline through the lab's steps "
                    "(docs/lab.md)")
        ->check(CLI::IsMember({"engine", "lab"}));
    cmd->callback([opts, rendererName, &exitCode] { exitCode = runRender(*opts, *rendererName); });
}

}  // namespace facet::app
