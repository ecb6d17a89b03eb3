// Supersampling (RenderSettings::supersample): the frame rendered at N×N the size and averaged.
// Its sub-sample centres are the ground truth's (both scale width, height and focal by N), so on
// flat colour its coverage must be the ground truth's coverage, to the 8-bit rounding.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>

#include <glm/geometric.hpp>

#include "facet/camera.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "world_at.hpp"

namespace {

using facet::Framebuffer;
using facet::RenderSettings;
using facet::Scene;

using facet::test::worldAt;

// White triangles through pixel positions, at depth 2, on a black 24×16 image.
Scene triangles(const std::vector<glm::dvec2>& corners) {
    Scene scene;
    scene.camera.width = 24;
    scene.camera.height = 16;
    scene.camera.focal = 20.0;
    facet::Mesh mesh;
    for (const glm::dvec2 p : corners) {
        mesh.positions.push_back(worldAt(scene.camera, p.x, p.y, 2.0));
        mesh.colors.emplace_back(1.0f);
    }
    for (std::uint32_t i = 0; i < corners.size(); ++i) mesh.indices.push_back(i);
    scene.mesh = std::make_shared<const facet::Mesh>(std::move(mesh));
    return scene;
}

Scene knot() {
    facet::Result<Scene> s = facet::loadScene(std::string(FACET_ASSETS_DIR) + "/default.scene");
    EXPECT_TRUE(s.ok()) << s.error().what();
    Scene scene = std::move(s).value();
    scene.camera = facet::resizedCamera(scene.camera, 160, 120);
    return scene;
}

TEST(Supersample, OneSampleIsTheOrdinaryFrame) {
    const Scene scene = knot();
    RenderSettings s;
    s.lighting = facet::Lighting::Gouraud;
    facet::Renderer renderer;
    Framebuffer a, b;
    renderer.render(scene, s, a);
    s.supersample = 1;
    renderer.render(scene, s, b);
    EXPECT_EQ(a.color, b.color);
    s.supersample = -3;  // clamped to 1
    renderer.render(scene, s, b);
    EXPECT_EQ(a.color, b.color);
}

// Coverage per pixel from N×N samples equals the ground truth's at the same N: slanted edges,
// a sliver and a small triangle, N = 2, 3, 4.
TEST(Supersample, CoverageIsTheGroundTruthsAtTheSameSamples) {
    const Scene scene = triangles({{2.3, 1.1},
                                   {21.7, 3.4},
                                   {6.2, 14.6},  // a big slanted one
                                   {14.1, 9.05},
                                   {23.3, 15.2},
                                   {14.9, 15.8},  // a sliver-ish one
                                   {19.2, 1.2},
                                   {20.9, 1.7},
                                   {19.6, 3.1}});  // a small one
    RenderSettings s;
    s.shader = facet::ShaderKind::Simple;
    s.background = 0x000000;
    facet::Renderer renderer;
    for (int n : {2, 3, 4}) {
        s.supersample = n;
        Framebuffer frame;
        renderer.render(scene, s, frame);
        ASSERT_EQ(frame.width, 24);
        ASSERT_EQ(frame.height, 16);
        const facet::GroundTruth truth = facet::renderGroundTruth(scene, s, n).value();
        int partial = 0;
        for (std::size_t i = 0; i < frame.color.size(); ++i) {
            const int got = static_cast<int>((frame.color[i] >> 8) & 0xFF);
            const double want = 255.0 * truth.color[i].g;
            // Exact fractions k/N² of 255, rounded: within half a step.
            EXPECT_LE(std::abs(got - want), 0.5 + 1e-6) << "N " << n << " pixel " << i;
            partial += got > 0 && got < 255;
        }
        EXPECT_GT(partial, 20) << n;
    }
}

// Supersampling approaches the ground truth: on the knot (Gouraud, 160×120) the error against an
// 8×8 ground truth falls with every step, mostly along the silhouettes.
TEST(Supersample, ErrorAgainstGroundTruthFallsWithSamples) {
    const Scene scene = knot();
    RenderSettings s;
    s.lighting = facet::Lighting::Phong;
    const facet::GroundTruth truth = facet::renderGroundTruth(scene, s, 8).value();
    facet::Renderer renderer;
    double previous = 1e9;
    for (int n : {1, 2, 4}) {
        s.supersample = n;
        Framebuffer frame;
        renderer.render(scene, s, frame);
        const facet::ImageError e = facet::measureError(frame, truth);
        std::printf("[supersample] N=%d RMSE %.3f, max %.1f, %.2f %% over 2 LSB\n", n, e.rmse,
                    e.maxError, 100.0 * e.over2Lsb);
        EXPECT_LT(e.rmse, previous) << n;
        previous = e.rmse;
        if (n == 4) {
            EXPECT_LT(e.rmse, 0.8);  // measured 3.21, 1.08, 0.43 for N = 1, 2, 4
        }
    }
}

// The depth legend is drawn on the final frame (so at its size), lines and points are not
// supersampled, and every thread count gives the same image.
TEST(Supersample, LegendLinesAndThreads) {
    const Scene scene = knot();
    facet::Renderer renderer;
    RenderSettings s;
    s.shader = facet::ShaderKind::Depth;
    s.depthLegend = true;
    Framebuffer one, four;
    renderer.render(scene, s, one);
    s.supersample = 4;
    renderer.render(scene, s, four);
    // The legend's box sits in the same pixels: count pure white pixels (its text and frame; the
    // colour map's near end may add one or two). Drawn at 4×4 the size and averaged down, its
    // 1-pixel strokes would turn grey and the count would collapse.
    auto whites = [](const Framebuffer& f) {
        int n = 0;
        for (std::uint32_t c : f.color) n += (c & 0xFFFFFF) == 0xFFFFFF;
        return n;
    };
    EXPECT_GT(whites(one), 50);
    EXPECT_NEAR(whites(one), whites(four), 3);

    s = RenderSettings{};
    s.mode = facet::DrawMode::Wireframe;
    renderer.render(scene, s, one);
    s.supersample = 4;
    renderer.render(scene, s, four);
    EXPECT_EQ(one.color, four.color);

    s = RenderSettings{};
    s.lighting = facet::Lighting::Gouraud;
    s.supersample = 3;
    s.threads = 1;
    renderer.render(scene, s, one);
    s.threads = 2;
    renderer.render(scene, s, four);
    EXPECT_EQ(one.color, four.color);
    EXPECT_EQ(one.depth, four.depth);
}

}  // namespace
