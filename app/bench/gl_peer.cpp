// The peer process: `facet bench --peer`, run by gl_peer_process.cpp with LP_NUM_THREADS set.
// Everything it says goes to stdout as "facet-peer <event> ..." lines (gl_peer.hpp); a line
// without the prefix (a driver's chatter) is ignored by the parent.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "../commands.hpp"
#include "bench_suite.hpp"
#include "bench_timing.hpp"
#include "facet/image_io.hpp"
#include "gl_context.hpp"
#include "gl_peer.hpp"
#include "gl_renderer.hpp"

namespace facet::app {
namespace {

/// One protocol line, flushed at once so the parent's progress follows the work.
void say(const std::string& line) {
    std::printf("facet-peer %s\n", line.c_str());
    std::fflush(stdout);
}

int fail(const std::string& message) {
    say("error " + message);
    return kFailed;
}

}  // namespace

int runGlPeer(const BenchOptions& o) {
    Result<BenchSuite> suite = buildSuite(o);
    if (!suite) return fail(suite.error().what());
    Result<GlContext> context = GlContext::createHeadless();
    if (!context) return fail(context.error().what());
    Result<GlRenderer> renderer = GlRenderer::create();
    if (!renderer) return fail(renderer.error().what());
    say("info " + context->description());

    const char* lp = std::getenv("LP_NUM_THREADS");
    const std::string tag = std::string("opengl_t") + (lp ? lp : "default");
    const FramePlan plan = framePlan(o);
    Framebuffer frame;
    for (const BenchCase& c : suite->cases)
        for (const BenchConfig& config : suite->configs) {
            say("start " + c.name + " " + config.name);
            std::string error;
            const FrameTimes t = timeFrames(plan, [&] {
                const Result<GlStats> stats = renderer->render(c.scene, config.settings, frame);
                if (!stats) error = stats.error().what();
                return stats.ok();
            });
            if (!error.empty()) return fail(c.name + " " + config.name + ": " + error);
            say("result " + c.name + " " + config.name + " " + std::to_string(t.frames) + " " +
                std::to_string(t.median) + " " + std::to_string(t.min) + " " +
                std::to_string(t.max));
            if (!o.images.empty()) {
                const auto path = std::filesystem::path(o.images) /
                                  (c.name + "_" + config.name + "_" + tag + ".png");
                if (Status st = writePng(frame, path.string()); !st) return fail(st.error().what());
            }
        }
    return kOk;
}

}  // namespace facet::app
