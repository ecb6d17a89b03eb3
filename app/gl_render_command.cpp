// `facet render-gl`: the same scene and settings as `facet render`, drawn by the OpenGL twin
// (app/gl) in a headless EGL context, for comparing the two pictures and timings by eye.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "facet/image_io.hpp"
#include "facet/scene_io.hpp"
#include "gl_context.hpp"
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
    if (settings.view != DebugView::None) {
        std::fprintf(stderr,
                     "facet render-gl: --view is drawn by the CPU engine only (facet "
                     "render)\n");
        return kBadInput;
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
    std::FILE* info = reportStream(o.output);  // stderr when the PNG goes to stdout
    if (Status st = writeOutput(frame, o.output); !st) return failed(st.error().what());
    std::fprintf(info, "wrote %s (%dx%d, %s, %s, %s, lighting %s) with %s\n", o.output.c_str(),
                 frame.width, frame.height, o.mode.c_str(),
                 std::string(toString(settings.shader)).c_str(), o.interp.c_str(),
                 std::string(toString(settings.lighting)).c_str(), context->description().c_str());
    printFrameTimes(ms, info);
    if (o.stats) {
        std::fprintf(
            info, "submitted: %zu triangles, %zu lines, %zu points, %zu normals; %zu bytes sent\n",
            last.trianglesIn, last.linesDrawn, last.pointsDrawn, last.normalsDrawn,
            last.uploadBytes);
        std::fprintf(info, "last frame: upload %.3f ms, draw %.3f ms, readback %.3f ms\n",
                     last.uploadMs, last.drawMs, last.readbackMs);
        if (settings.shader == ShaderKind::Depth)
            std::fprintf(info, "depth range: %.6g .. %.6g\n", last.depthNear, last.depthFar);
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
                     "affine or perspective (subdivided[:N] is drawn perspective-correct)");
    cmd->callback([opts, &exitCode] { exitCode = runGlRender(*opts); });
}

}  // namespace facet::app
