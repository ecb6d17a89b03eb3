// Multisampling (RenderSettings::msaa): the standard sample positions, coverage and depth per
// sample exactly as the reference path's (outside its ambiguity mask), no cracks and no double
// coverage per sample on shared edges, the box-filter resolve, and MSAA 1 as the ordinary frame.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "facet/advanced/draw.hpp"
#include "facet/camera.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/evaluation/reference_compare.hpp"
#include "facet/framebuffer.hpp"
#include "facet/limits.hpp"
#include "facet/multisample.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "shared_data.hpp"
#include "world_at.hpp"

namespace {

using facet::Framebuffer;
using facet::RenderSettings;
using facet::Scene;
using facet::test::worldAt;

// Triangles through pixel positions at depth `z` each (three corners, one colour per corner).
Scene triangles(const std::vector<glm::dvec3>& corners, int w = 24, int h = 16) {
    Scene scene;
    scene.camera.width = w;
    scene.camera.height = h;
    scene.camera.focal = 20.0;
    facet::Mesh mesh;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 p = corners[i];
        mesh.positions.push_back(worldAt(scene.camera, p.x, p.y, p.z));
        mesh.colors.emplace_back(i % 3 == 0 ? 1.0f : 0.2f, i % 3 == 1 ? 1.0f : 0.3f,
                                 i % 3 == 2 ? 1.0f : 0.1f);
    }
    for (std::uint32_t i = 0; i < corners.size(); ++i) mesh.indices.push_back(i);
    scene.mesh = std::make_shared<const facet::Mesh>(std::move(mesh));
    return scene;
}

// Slanted edges, a sliver, a tiny triangle, two triangles crossing in depth and a shared edge.
Scene testTriangles() {
    return triangles({{2.3, 1.1, 2.0},
                      {21.7, 3.4, 3.0},
                      {6.2, 14.6, 2.5},  // big, slanted
                      {14.1, 9.05, 2.0},
                      {23.3, 15.2, 2.0},
                      {14.9, 15.8, 2.0},  // sliver-ish
                      {19.2, 1.2, 2.0},
                      {20.9, 1.7, 2.0},
                      {19.6, 3.1, 2.0},  // tiny
                      {1.0, 8.0, 1.5},
                      {12.0, 6.5, 4.0},
                      {5.0, 15.5, 4.0},  // crosses the big one
                      {12.0, 6.5, 4.0},
                      {16.0, 12.0, 1.8},
                      {5.0, 15.5, 4.0}});  // shares its edge
}

Scene knot(int w, int h) {
    facet::Result<Scene> s = facet::loadScene(std::string(FACET_ASSETS_DIR) + "/default.scene");
    EXPECT_TRUE(s.ok()) << s.error().what();
    Scene scene = std::move(s).value();
    scene.camera = facet::resizedCamera(scene.camera, w, h);
    return scene;
}

// The engine's per-sample buffer against the reference's image of samples: no coverage
// difference outside the ambiguity mask, colours within 1 LSB.
void expectSamplesMatchReference(const Scene& scene, const RenderSettings& s,
                                 const std::string& what, std::size_t minCovered) {
    facet::Renderer renderer;
    Framebuffer frame;
    renderer.render(scene, s, frame);
    const Framebuffer& samples = facet::sampleBuffer(renderer);
    const facet::SampleBlock b = facet::sampleBlock(s.msaa);
    ASSERT_EQ(samples.width, scene.camera.width * b.x) << what;
    ASSERT_EQ(samples.height, scene.camera.height * b.y) << what;
    const facet::reference::Image ref = facet::reference::renderSamples(scene, s).value();
    ASSERT_EQ(ref.width, samples.width) << what;
    const facet::ReferenceDiff d =
        facet::compareWithReference(samples, ref, s.shader, s.background);
    std::printf(
        "[msaa] %-28s samples compared=%zu covered=%zu ambiguous=%zu differing=%zu "
        "maxdiff=%d\n",
        what.c_str(), d.compared, d.comparedCovered, d.ambiguous, d.coverageDiffers,
        d.maxColorDiff);
    EXPECT_EQ(d.coverageDiffers, 0u) << what << d.examples;
    EXPECT_LE(d.maxColorDiff, 1) << what << d.examples;
    EXPECT_GE(d.comparedCovered, minCovered) << what;
    // And the resolved frames: the same box filter in 8 bits on both sides.
    const facet::reference::Image resolved = facet::reference::render(scene, s).value();
    const facet::ReferenceDiff r =
        facet::compareWithReference(frame, resolved, s.shader, s.background);
    EXPECT_EQ(r.coverageDiffers, 0u) << what << r.examples;
    EXPECT_LE(r.maxColorDiff, 1) << what << r.examples;
}

TEST(Msaa, StandardSamplePositions) {
    // Direct3D 11's standard patterns in 1/16 px; Vulkan's standard locations are (x+8)/16.
    const std::vector<facet::SampleOffset> two{{4, 4}, {-4, -4}};
    const std::vector<facet::SampleOffset> four{{-2, -6}, {6, -2}, {-6, 2}, {2, 6}};
    const std::vector<facet::SampleOffset> eight{{1, -3}, {-1, 3},  {5, 1}, {-3, -5},
                                                 {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
    auto vec = [](int n) {
        const auto p = facet::samplePositions(n);
        return std::vector<facet::SampleOffset>(p.begin(), p.end());
    };
    EXPECT_EQ(vec(2), two);
    EXPECT_EQ(vec(4), four);
    EXPECT_EQ(vec(8), eight);
    EXPECT_EQ(vec(1), (std::vector<facet::SampleOffset>{{0, 0}}));
    // Vulkan's 4-sample table, written from the pixel's corner.
    const double vk4[4][2] = {{0.375, 0.125}, {0.875, 0.375}, {0.125, 0.625}, {0.625, 0.875}};
    for (int k = 0; k < 4; ++k) {
        EXPECT_EQ((four[k].x + 8) / 16.0, vk4[k][0]);
        EXPECT_EQ((four[k].y + 8) / 16.0, vk4[k][1]);
    }
    EXPECT_EQ(facet::msaaSamples(0), 1);
    EXPECT_EQ(facet::msaaSamples(3), 2);
    EXPECT_EQ(facet::msaaSamples(6), 4);
    EXPECT_EQ(facet::msaaSamples(100), 8);
    EXPECT_EQ(facet::sampleBlock(2), (facet::SampleBlock{2, 1}));
    EXPECT_EQ(facet::sampleBlock(4), (facet::SampleBlock{2, 2}));
    EXPECT_EQ(facet::sampleBlock(8), (facet::SampleBlock{4, 2}));
}

// A sample exactly on a vertical left edge is inside, on the right edge outside (top-left rule
// per sample), and samples land where the table says.
TEST(Msaa, SamplesSitAtTheirPositionsWithTheTopLeftRule) {
    // An axis-aligned rectangle (two triangles) from x = 10 + 6/16 to x = 10 + 10/16 wide, all
    // rows: with 4 samples, x offsets −6, 6, −2, 2 (/16) from 10.5: at 10.125, 10.875, 10.375,
    // 10.625. The left edge at 10.375 passes through sample 3 ({-2, -6} is sample 0: x 10.375).
    const double l = 10.375, r = 10.625;
    const Scene scene = triangles({{l, -1.0, 2.0},
                                   {r, -1.0, 2.0},
                                   {l, 20.0, 2.0},
                                   {r, -1.0, 2.0},
                                   {r, 20.0, 2.0},
                                   {l, 20.0, 2.0}});
    facet::Renderer renderer;
    RenderSettings s;
    s.shader = facet::ShaderKind::Simple;
    s.msaa = 4;
    std::vector<std::uint16_t> counts;
    // Clip positions of the scene's mesh (the vertex stage's transform) for countCoverage.
    const facet::Mesh& mesh = *scene.mesh;
    std::vector<glm::vec4> clip;
    const glm::dmat4 m = facet::clipFromWorld(scene.camera);
    for (const glm::vec3& p : mesh.positions) clip.push_back(glm::vec4(m * glm::dvec4(p, 1.0)));
    facet::DrawInput in;
    in.clip = clip;
    in.indices = mesh.indices;
    facet::countCoverage(renderer, in, s, 24, 16, counts);
    ASSERT_EQ(counts.size(), 24u * 16u * 4u);
    const facet::SampleBlock b = facet::sampleBlock(4);
    const auto positions = facet::samplePositions(4);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 24; ++x) {
            for (int k = 0; k < 4; ++k) {
                const double sx = x + 0.5 + positions[k].x / 16.0;
                const bool inside = sx >= l && sx < r;  // left edge in, right edge out
                const std::size_t i = static_cast<std::size_t>(y * b.y + k / b.x) * 48 +
                                      static_cast<std::size_t>(x * b.x + k % b.x);
                EXPECT_EQ(counts[i], inside ? 1 : 0) << x << "," << y << " sample " << k;
            }
        }
    }
}

TEST(Msaa, OneSampleIsTheOrdinaryFrame) {
    const Scene scene = knot(160, 120);
    RenderSettings s;
    s.lighting = facet::Lighting::Gouraud;
    facet::Renderer renderer;
    Framebuffer a, b;
    renderer.render(scene, s, a);
    for (const int n : {1, 0, -3}) {
        s.msaa = n;
        renderer.render(scene, s, b);
        EXPECT_EQ(a.color, b.color) << n;
        EXPECT_EQ(a.depth, b.depth) << n;
    }
}

TEST(Msaa, PerSampleCoverageMatchesTheReference) {
    const Scene scene = testTriangles();
    for (const int n : facet::kMsaaCounts) {
        for (const facet::ShaderKind shader :
             {facet::ShaderKind::Simple, facet::ShaderKind::Painter}) {
            for (const facet::Interp interp : {facet::Interp::Affine, facet::Interp::Perspective}) {
                RenderSettings s;
                s.shader = shader;
                s.interp = interp;
                s.background = 0x000000;
                s.msaa = n;
                expectSamplesMatchReference(scene, s,
                                            "triangles msaa" + std::to_string(n) + " " +
                                                std::string(facet::toString(shader)) + " " +
                                                std::string(facet::toString(interp)),
                                            100);
            }
        }
    }
}

TEST(Msaa, KnotMatchesTheReferencePerSample) {
    const Scene scene = knot(160, 120);
    for (const int n : facet::kMsaaCounts) {
        for (const facet::Lighting lighting : {facet::Lighting::Gouraud, facet::Lighting::Phong}) {
            RenderSettings s;
            s.lighting = lighting;
            s.msaa = n;
            expectSamplesMatchReference(
                scene, s,
                "knot msaa" + std::to_string(n) + " " + std::string(facet::toString(lighting)),
                1000);
        }
        RenderSettings depth;
        depth.shader = facet::ShaderKind::Depth;
        depth.msaa = n;
        expectSamplesMatchReference(scene, depth, "knot depth msaa" + std::to_string(n), 1000);
        RenderSettings sub;
        sub.interp = facet::Interp::Subdivided;
        sub.lighting = facet::Lighting::Gouraud;
        sub.subdivision = 8;
        sub.msaa = n;
        expectSamplesMatchReference(scene, sub, "knot subdivided msaa" + std::to_string(n), 1000);
    }
}

TEST(Msaa, TexturedSpotMatchesTheReferencePerSample) {
    const std::string path = facet::test::sharedData("scenes/spot_1280x720.scene");
    REQUIRE_SHARED_DATA(path);
    facet::Result<Scene> loaded = facet::loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().what();
    Scene scene = std::move(loaded).value();
    scene.camera = facet::resizedCamera(scene.camera, 160, 90);
    for (const facet::TextureFilter filter :
         {facet::TextureFilter::Bilinear, facet::TextureFilter::Trilinear}) {
        RenderSettings s;
        s.shader = facet::ShaderKind::Texture;
        s.filter = filter;
        s.msaa = 4;
        expectSamplesMatchReference(scene, s, "spot msaa4 " + std::string(facet::toString(filter)),
                                    1000);
    }
}

// A plane of triangles sharing every edge, covering more than the image, its inner vertices
// jittered: every sample of every pixel is covered exactly once (no crack, no double).
TEST(Msaa, SharedEdgesCoverEverySampleOnce) {
    const int w = 40, h = 30, cols = 9, rows = 7;
    Scene base;
    base.camera.width = w;
    base.camera.height = h;
    base.camera.focal = 30.0;
    facet::Mesh mesh;
    mesh.positions = facet::test::jitteredGrid(base.camera, cols, rows, 2.0, 2.3, 12345u,
                                               [](int i, int) { return 2.0 + 0.1 * i; });
    facet::test::appendGridTriangles(mesh.indices, cols, rows);
    const glm::dmat4 m = facet::clipFromWorld(base.camera);
    std::vector<glm::vec4> clip;
    for (const glm::vec3& p : mesh.positions) clip.push_back(glm::vec4(m * glm::dvec4(p, 1.0)));
    facet::DrawInput in;
    in.clip = clip;
    in.indices = mesh.indices;
    facet::Renderer renderer;
    for (const int bits : {8, 4, 2}) {
        for (const int n : facet::kMsaaCounts) {
            RenderSettings s;
            s.msaa = n;
            s.subPixelBits = bits;
            std::vector<std::uint16_t> counts;
            facet::countCoverage(renderer, in, s, w, h, counts);
            ASSERT_EQ(counts.size(), static_cast<std::size_t>(w * h * n));
            std::size_t wrong = 0;
            for (const std::uint16_t c : counts) wrong += c != 1;
            EXPECT_EQ(wrong, 0u) << "msaa " << n << ", " << bits << " bits";
        }
    }
}

// The resolve is a box filter in 8 bits: each pixel the rounded mean of its samples' bytes,
// depth the nearest; a white triangle on black gives k/N of 255 where k samples are covered.
TEST(Msaa, ResolveIsTheRoundedMeanOfTheSamples) {
    Scene scene = triangles({{2.3, 1.1, 2.0}, {21.7, 3.4, 3.0}, {6.2, 14.6, 2.5}});
    facet::Mesh white = *scene.mesh;
    for (glm::vec3& c : white.colors) c = glm::vec3(1.0f);
    scene.mesh = std::make_shared<const facet::Mesh>(std::move(white));
    for (const int n : facet::kMsaaCounts) {
        RenderSettings s;
        s.background = 0x000000;
        s.msaa = n;
        facet::Renderer renderer;
        Framebuffer frame;
        renderer.render(scene, s, frame);
        const Framebuffer& samples = facet::sampleBuffer(renderer);
        const facet::SampleBlock b = facet::sampleBlock(n);
        int partial = 0;
        for (int y = 0; y < frame.height; ++y) {
            for (int x = 0; x < frame.width; ++x) {
                int covered = 0;
                float nearest = facet::kEmptyDepth;
                for (int k = 0; k < n; ++k) {
                    const std::size_t i = samples.index(x * b.x + k % b.x, y * b.y + k / b.x);
                    covered += (samples.color[i] & 0xFF) == 0xFF;
                    nearest = std::min(nearest, samples.depth[i]);
                }
                const std::uint32_t want = (255u * static_cast<std::uint32_t>(covered) +
                                            static_cast<std::uint32_t>(n / 2)) /
                                           static_cast<std::uint32_t>(n);
                const std::size_t p = frame.index(x, y);
                EXPECT_EQ(frame.color[p] & 0xFF, want) << x << "," << y;
                EXPECT_EQ(frame.depth[p], nearest) << x << "," << y;
                partial += covered > 0 && covered < n;
            }
        }
        EXPECT_GT(partial, 20) << n;
    }
}

// What MSAA buys: on the knot's silhouettes the error against an 8×8 ground truth falls with
// the samples; every thread count gives the same image.
TEST(Msaa, ErrorFallsWithSamplesAndThreadsAgree) {
    const Scene scene = knot(160, 120);
    RenderSettings s;
    s.lighting = facet::Lighting::Gouraud;
    const facet::GroundTruth truth = facet::renderGroundTruth(scene, s, 8).value();
    facet::Renderer renderer;
    double previous = 1e9;
    for (const int n : {1, 2, 4, 8}) {
        s.msaa = n;
        s.threads = 0;
        Framebuffer frame, one;
        renderer.render(scene, s, frame);
        const facet::ImageError e = facet::measureError(frame, truth);
        std::printf("[msaa] N=%d RMSE %.3f, max %.1f\n", n, e.rmse, e.maxError);
        EXPECT_LT(e.rmse, previous) << n;
        previous = e.rmse;
        s.threads = 1;
        renderer.render(scene, s, one);
        EXPECT_EQ(frame.color, one.color) << n;
    }
}

// Lines and points stay one sample; the legend is drawn on the resolved frame.
TEST(Msaa, LinesAndPointsStayOneSample) {
    const Scene scene = knot(160, 120);
    facet::Renderer renderer;
    for (const facet::DrawMode mode : {facet::DrawMode::Wireframe, facet::DrawMode::Vertices}) {
        RenderSettings s;
        s.mode = mode;
        Framebuffer one, eight;
        renderer.render(scene, s, one);
        s.msaa = 8;
        renderer.render(scene, s, eight);
        EXPECT_EQ(one.color, eight.color) << facet::toString(mode);
    }
}

TEST(Msaa, FrameMemoryCountsTheSamples) {
    EXPECT_FALSE(facet::frameMemoryProblem(1920, 1080, 1, 8));
    EXPECT_EQ(facet::frameBytes(100, 100, 1, 4), 8u * 10000u * (1u + 4u));
    EXPECT_EQ(facet::frameBytes(100, 100, 2, 4), 8u * 10000u * (5u + 16u));
    const auto problem = facet::frameMemoryProblem(16384, 16384, 1, 8);
    ASSERT_TRUE(problem);
    EXPECT_NE(problem->find("MSAA 8x"), std::string::npos) << *problem;
}

}  // namespace
