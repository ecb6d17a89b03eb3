#include "twin_view.hpp"

#include <cstdio>
#include <utility>

#include "frame_stats.hpp"
#include "viewer_app.hpp"

namespace facet::view {
namespace {

bool twinFailed(App& app, const Error& error) {
    const std::string message = error.what();
    app.loop.rendererLog.error = message;
    std::fprintf(stderr, "facet-view: OpenGL twin: %s\n", message.c_str());
    showError(app.popups, "The OpenGL twin cannot draw this",
              message + "\n\nBack to the CPU engine; choose the twin again in the Render panel.");
    selectRenderer(app.model.rendererChoice, RendererChoice::Cpu, app.compare.settings);
    return false;
}

}  // namespace

bool renderTwin(App& app) {
    TwinView& t = app.twin;
    if (isLab(app.model.rendererChoice)) {
        const auto l0 = Clock::now();
        t.labReport = t.lab.render(app.model.scene, app.model.settings, t.frame);
        t.ms = ms(l0, Clock::now());
        t.stats = {};
        ++app.loop.rendererLog.twinFrames;
        return true;
    }
    if (!t.renderer) {
        // First use: the shaders are read now (variants compile on their first frame), so a
        // viewer that never chooses the twin never pays for it or fails on it.
        Result<GlRenderer> made = GlRenderer::create();
        if (!made) return twinFailed(app, made.error());
        t.renderer.emplace(std::move(made).value());
        app.loop.rendererLog.device = t.renderer->device();
    }
    const auto t0 = Clock::now();
    const Result<GlStats> stats = t.renderer->render(app.model.scene, app.model.settings, t.frame);
    t.ms = ms(t0, Clock::now());
    if (!stats) return twinFailed(app, stats.error());
    t.stats = stats.value();
    ++app.loop.rendererLog.twinFrames;
    return true;
}

const Framebuffer& composeSideBySide(App& app) {
    const CompareSettings& c = app.compare.settings;
    CompareView& s = app.compare.sides;
    if (app.model.rendererChoice == RendererChoice::LabSplit)
        s.diff = composeSides(app.twin.frame, app.loop.display, c.display, c.divider, c.heatScale,
                              s.shown);
    else
        s.diff = composeSides(app.loop.display, app.twin.frame, c.display, c.divider, c.heatScale,
                              s.shown);
    return s.shown;
}

}  // namespace facet::view
