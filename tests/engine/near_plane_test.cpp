// A camera flying through the bunny: every frame crosses the near plane somewhere. The fast path
// must stay finite and agree with the double-precision reference frame by frame.

#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "facet/evaluation/reference_compare.hpp"
#include "facet/procedural.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "shared_data.hpp"

namespace facet {
namespace {

TEST(NearPlane, CameraThroughTheBunnyStaysFiniteAndMatchesTheReference) {
    const std::string path = test::sharedData("scenes/bunny_1280x720.scene");
    REQUIRE_SHARED_DATA(path);
    Result<Scene> loaded = loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().what();
    Scene scene = loaded.value();
    // Colour the vertices by position so interpolation errors show up as colour differences.
    scene.mesh = std::make_shared<const Mesh>(colouredByPosition(*scene.mesh));
    const Bounds b = computeBounds(*scene.mesh);
    scene.camera.width = 160;
    scene.camera.height = 90;
    scene.camera.focal = 150.0;

    // From in front of the bunny, through its body, out of the back, looking along the path.
    const glm::dvec3 centre = 0.5 * glm::dvec3(b.min + b.max);
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.3, -0.2, -1.0));
    const double extent = b.diagonal();
    Renderer renderer;
    Framebuffer fb;
    std::size_t clippedFrames = 0;
    const auto near = static_cast<float>(resolveNearPlane(RenderSettings{}, *scene.mesh));
    for (int frame = 0; frame < 100; ++frame) {
        const double t = -0.6 + 0.85 * frame / 99.0;
        scene.camera.eye = centre + t * extent * dir;
        scene.camera.look = scene.camera.eye + dir;
        for (Interp interp : {Interp::Perspective, Interp::Affine}) {
            RenderSettings s;
            s.interp = interp;
            const RenderStats stats = renderer.render(scene, s, fb).value();
            clippedFrames += stats.trianglesClipped > 0;
            for (float d : fb.depth) ASSERT_FALSE(std::isnan(d)) << "frame " << frame;
            for (float d : fb.depth)
                ASSERT_TRUE(d == kEmptyDepth || d >= 0.999f * near)
                    << "frame " << frame << " depth " << d;
            const reference::Image ref = reference::render(scene, s).value();
            const ReferenceDiff c = compareWithReference(fb, ref, s.shader, s.background);
            EXPECT_EQ(c.coverageDiffers, 0u)
                << "frame " << frame << " " << toString(interp) << c.examples;
            EXPECT_LE(c.maxColorDiff, 1) << "frame " << frame << " " << toString(interp);
        }
    }
    EXPECT_GT(clippedFrames, 20u);  // the path really crossed the geometry
}

}  // namespace
}  // namespace facet
