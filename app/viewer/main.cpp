// facet-view: the facet software rasterizer in a window. The engine renders each frame on the
// CPU; OpenGL only shows it (one texture, one triangle) with Dear ImGui panels on top.

#include <cstdio>
#include <memory>
#include <utility>

#include "options.hpp"
#include "viewer_app.hpp"

int main(int argc, char** argv) {
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
