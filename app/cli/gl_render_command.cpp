// `facet render-gl`: the same scene and settings as `facet render`, drawn by the OpenGL twin
// (app/gl) in a headless EGL context, for comparing the two pictures and timings by eye.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "exit_code.hpp"
#include "facet/image_io.hpp"
#include "facet/scene_io.hpp"
#include "gl_context.hpp"
#include "gl_render_command.hpp"
#include "gl_renderer.hpp"
#include "render_options.hpp"

namespace facet::app {
namespace {

int failed(const std::string& message) {
    std::fprintf(stderr, "facet render-gl: %s\n", message.c_str());
    return kFailed;
}

int runGlRender(const RenderOptions& o) {
    Scene scene;
    RenderSettings settings;
    if (const int code = prepareRender(o, "facet render-gl", scene, settings); code != kOk)
        return code;

    Result<GlContext> context = GlContext::createHeadless();
    if (!context) return failed(context.error().what());
    Result<GlRenderer> renderer = GlRenderer::create();
    if (!renderer) return failed(renderer.error().what());
    // As an application with a static mesh: upload once, then per frame only the draw (up to
    // glFinish), which is what the frame times measure, and one readback for the picture.
    Framebuffer frame;
    GlStats stats;
    if (Status st = renderer->upload(scene, settings, stats); !st) return failed(st.error().what());
    std::vector<double> ms;
    for (int i = 0; i < std::max(1, o.frames); ++i) {
        const double before = stats.drawMs;
        if (Status st = renderer->draw(scene, settings, stats); !st)
            return failed(st.error().what());
        ms.push_back(stats.drawMs - before);
    }
    if (Status st = renderer->readBack(scene, settings, frame, stats); !st)
        return failed(st.error().what());
    std::FILE* info = reportStream(o.output);  // stderr when the PNG goes to stdout
    if (Status st = writeOutput(frame, o.output); !st) return failed(st.error().what());
    std::fprintf(info, "wrote %s (%dx%d, %s, %s, %s, lighting %s) with %s\n", o.output.c_str(),
                 frame.width, frame.height, o.mode.c_str(),
                 std::string(toString(settings.shader)).c_str(), o.interp.c_str(),
                 std::string(toString(settings.lighting)).c_str(), context->description().c_str());
    if (ms.size() > 1)
        std::fprintf(info, "frame times: the draw up to glFinish, the mesh resident\n");
    printFrameTimes(ms, info);
    if (o.stats) {
        std::fprintf(
            info,
            "submitted: %zu triangles, %zu lines, %zu points, %zu normals; %zu bytes sent once\n",
            stats.trianglesIn, stats.linesDrawn, stats.pointsDrawn, stats.normalsDrawn,
            stats.uploadBytes);
        std::fprintf(
            info,
            "upload once %.3f ms (normals, buffers, texture), draw %.3f ms (last of %zu, up to "
            "glFinish), readback once %.3f ms (colour and depth)\n",
            stats.uploadMs, ms.back(), ms.size(), stats.readbackMs);
        if (settings.shader == ShaderKind::Depth)
            std::fprintf(info, "depth range: %.6g .. %.6g\n", stats.depthNear, stats.depthFar);
    }
    return kOk;
}

}  // namespace

void addGlRenderCommand(CLI::App& app, int& exitCode) {
    auto opts = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render-gl",
        "Render a .scene file or a mesh with the OpenGL twin (headless EGL) to a PNG image");
    addRenderOptions(*cmd, *opts,
                     "affine or perspective (subdivided[:N] is drawn perspective-correct)",
                     RenderCommand::openGl);
    cmd->callback([opts, &exitCode] { exitCode = runGlRender(*opts); });
}

}  // namespace facet::app
