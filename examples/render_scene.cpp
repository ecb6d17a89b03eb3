// Example: render a .scene file (or a bare .off/.obj mesh) to a PNG, as `facet render` does
// with no options.
//
//   render_scene scene.scene out.png

#include <cstdio>

#include "facet/image_io.hpp"
#include "facet/render.hpp"
#include "facet/scene_defaults.hpp"
#include "facet/scene_io.hpp"
#include "facet/version.hpp"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s SCENE OUT.png   (facet %s)\n", argv[0],
                     facet::kVersionString);
        return 2;
    }
    // Every failure is a value: Result<T> holds the product or an Error naming file and line.
    facet::Result<facet::Scene> scene = facet::openSceneFile(argv[1]);
    if (!scene) {
        std::fprintf(stderr, "%s\n", scene.error().what().c_str());
        return 2;
    }
    // What a scene opens with (texture, lighting) by the same rule as the CLI and the viewer.
    facet::RenderSettings settings;
    facet::applyOpeningSettings(scene.value(), settings);

    facet::Renderer renderer;
    facet::Framebuffer frame;
    facet::Result<facet::RenderStats> stats = renderer.render(scene.value(), settings, frame);
    if (!stats) {
        std::fprintf(stderr, "%s\n", stats.error().what().c_str());
        return 2;
    }
    if (facet::Status written = facet::writePng(frame, argv[2]); !written) {
        std::fprintf(stderr, "%s\n", written.error().what().c_str());
        return 1;
    }
    std::printf("%s: %dx%d, %zu triangles drawn\n", argv[2], frame.width, frame.height,
                stats.value().trianglesRasterized);
    return 0;
}
