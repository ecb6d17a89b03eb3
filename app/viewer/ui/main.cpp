// facet-view: the facet software rasterizer in a window. The engine renders each frame on the
// CPU; OpenGL only shows it (one texture, one triangle) with Dear ImGui panels on top.

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <utility>

#include <unistd.h>

#include "options.hpp"
#include "viewer_app.hpp"

namespace {

/// OpenMP's threads (the engine's tiles) spin while they wait for work by default. In the viewer
/// they would spin against the engine's own worker, the GUI thread and llvmpipe's threads on the
/// same cores: measured on 2 cores, 28 fps instead of 78. libgomp reads its wait policy once,
/// before main, so the viewer restarts itself once with the policy set to sleep instead.
void useSleepingOpenMpThreads(char** argv) {
    if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;  // the user's (or our) choice
    if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0) return;
    execv("/proc/self/exe", argv);  // returns only on failure: then run as we are
}

}  // namespace

int main(int argc, char** argv) {
    useSleepingOpenMpThreads(argv);
    facet::view::ParsedOptions parsed = facet::view::parseOptions(argc, argv);
    if (parsed.exit) {
        std::fprintf(parsed.exitCode ? stderr : stdout, "%s\n", parsed.text.c_str());
        return parsed.exitCode;
    }
    // The App is large (frames, renderers): keep it off the stack.
    auto app = std::make_unique<facet::view::App>();
    app->options = std::move(parsed.options);
    return app->run();
}
