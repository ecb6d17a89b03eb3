// A camera flying through the bunny: every frame crosses the near plane somewhere. The fast path
// must stay finite and agree with the double-precision reference frame by frame.

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "facet/evaluation/reference_compare.hpp"
#include "facet/procedural.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "pipeline/vertex_stage.hpp"
#include "shared_data.hpp"

namespace facet {
namespace {

/// Whether two bounds hold the same bits (NaN and the sign of zero included).
bool sameBits(const Bounds& a, const Bounds& b) {
    return std::memcmp(&a, &b, sizeof(Bounds)) == 0;
}

// The vertex transform's bounds (which the fast path takes the near plane from) are
// computeBounds()' bit for bit at any thread count: the parts each thread folds are merged in
// order, a NaN counts only where the first position has it, and ties keep the first value.
TEST(NearPlane, TransformBoundsAreComputeBoundsAtAnyThreadCount) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    Mesh mesh;
    for (int i = 0; i < 50000; ++i) {  // over the transform's threshold for threads
        const float t = static_cast<float>(i);
        mesh.positions.emplace_back(std::sin(t) * 3.0f, std::cos(0.7f * t) * 2.0f, 0.001f * t);
    }
    mesh.positions[20000] = {-50.0f, 1.0f, 1.0f};  // an extreme only one part of 4 holds
    mesh.positions[30000] = {kNaN, -9.0f, kNaN};   // a NaN inside a later thread's part
    mesh.positions[12500] = {kNaN, 0.0f, 0.0f};    // at the start of a part of 4
    mesh.positions[35000] = {1.0f, 1.0f, -0.0f};   // ties: +0 (12500) comes first and stays
    const glm::dmat4 clipFromWorld(1.0);
    for (const bool nanFirst : {false, true}) {
        if (nanFirst) mesh.positions[0] = {1.0f, kNaN, 2.0f};
        const Bounds expected = computeBounds(mesh);
        for (const int threads : {1, 2, 3, 4}) {
            detail::VertexStage stage;
            Bounds got;
            const auto clip = stage.transform(mesh, clipFromWorld, threads, got);
            EXPECT_TRUE(sameBits(got, expected))
                << "threads " << threads << " nanFirst " << nanFirst;
            ASSERT_EQ(clip.size(), mesh.positions.size());
            EXPECT_EQ(std::memcmp(&clip[12345], &mesh.positions[12345], sizeof(glm::vec3)), 0);
        }
        RenderSettings settings;
        detail::VertexStage stage;
        Bounds got;
        (void)stage.transform(mesh, clipFromWorld, 2, got);
        EXPECT_EQ(resolveNearPlane(settings, got), resolveNearPlane(settings, mesh));
    }
    detail::VertexStage stage;
    Bounds got;
    (void)stage.transform(Mesh{}, glm::dmat4(1.0), 2, got);
    EXPECT_TRUE(sameBits(got, computeBounds(Mesh{})));
}

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
