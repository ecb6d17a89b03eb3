// The peer process: `facet bench --peer`, started by gl_peer_process.cpp with LP_NUM_THREADS
// set. Everything it says goes to stdout as "facet-peer <event> ..." lines (gl_peer.hpp); a line
// without the prefix (a driver's chatter) is ignored by the parent.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>

#include "../exit_code.hpp"
#include "bench_suite.hpp"
#include "bench_timing.hpp"
#include "facet/image_io.hpp"
#include "gl_context.hpp"
#include "gl_peer.hpp"
#include "gl_renderer.hpp"

namespace facet::app {
namespace {

/// One protocol line, flushed at once so the parent reads it while the peer waits.
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
    for (std::string line; std::getline(std::cin, line);) {
        std::istringstream in(line);
        std::string command, caseName, configName;
        in >> command >> caseName >> configName;
        const BenchCase* c = nullptr;
        const BenchConfig* config = nullptr;
        for (const BenchCase& x : suite->cases)
            if (x.name == caseName) c = &x;
        for (const BenchConfig& x : suite->configs)
            if (x.name == configName) config = &x;
        if (command != "run" || !c || !config) return fail("cannot run '" + line + "'");

        const std::string what = c->name + " " + config->name;
        GlStats stats;
        if (Status st = renderer->upload(c->scene, config->settings, stats); !st)
            return fail(what + ": " + st.error().what());
        std::string error;
        const FrameTimes t = timeFrames(plan, [&] {
            const Status st = renderer->draw(c->scene, config->settings, stats);
            if (!st) error = st.error().what();
            return bool(st);
        });
        if (!error.empty()) return fail(what + ": " + error);
        // The picture for --images: one readback, untimed.
        if (!o.images.empty()) {
            if (Status st = renderer->readBack(c->scene, config->settings, frame, stats); !st)
                return fail(what + ": " + st.error().what());
            const auto path = std::filesystem::path(o.images) /
                              (c->name + "_" + config->name + "_" + tag + ".png");
            if (Status st = writePng(frame, path.string()); !st) return fail(st.error().what());
        }
        // Last: the parent goes on to its next measurement as soon as it reads this line.
        say("result " + what + " " + std::to_string(t.frames) + " " + std::to_string(t.median) +
            " " + std::to_string(t.min) + " " + std::to_string(t.max));
    }
    return kOk;
}

}  // namespace facet::app
