// Coverage of the fast path's rasterizer: the fill rule, watertightness and guard band, measured
// with a per-pixel coverage count (every pixel inside a tiling must be covered exactly once).

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "facet/advanced/draw.hpp"
#include "facet/camera.hpp"
#include "facet/procedural.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "shared_data.hpp"
#include "test_scenes.hpp"

namespace facet {
namespace {

/// Coverage counts of screen-space triangles given as pixel coordinates with w = 1.
std::vector<std::uint16_t> countScreen(const std::vector<glm::vec2>& pts, int w, int h,
                                       bool cull = false) {
    std::vector<glm::vec4> clip;
    std::vector<std::uint32_t> idx;
    for (const auto& p : pts) {
        idx.push_back(static_cast<std::uint32_t>(clip.size()));
        clip.emplace_back(p.x, p.y, 1.0f, 1.0f);
    }
    Renderer r;
    RenderSettings s;
    s.cullBackFaces = cull;
    std::vector<std::uint16_t> counts;
    facet::countCoverage(r, {.clip = clip, .indices = idx, .nearPlane = 0.5f}, s, w, h, counts);
    return counts;
}

int total(const std::vector<std::uint16_t>& c) {
    int n = 0;
    for (auto v : c) n += v;
    return n;
}

TEST(FillRule, Direct3DWorkedExamples) {
    // Direct3D 11's rasterization rules: these two triangles cover 15 and 10 pixels.
    const auto a = countScreen({{0, 0}, {5, 0}, {5, 5}}, 8, 8);
    EXPECT_EQ(total(a), 15);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) EXPECT_EQ(a[y * 8 + x], x >= y ? 1 : 0) << x << "," << y;
    const auto b = countScreen({{0, 5}, {0, 0}, {5, 5}}, 8, 8);
    EXPECT_EQ(total(b), 10);
    for (int y = 0; y < 5; ++y)
        for (int x = 0; x < 5; ++x) EXPECT_EQ(b[y * 8 + x], x < y ? 1 : 0) << x << "," << y;
    // The winding does not change coverage.
    EXPECT_EQ(countScreen({{0, 0}, {5, 5}, {5, 0}}, 8, 8), a);
    EXPECT_EQ(countScreen({{0, 5}, {5, 5}, {0, 0}}, 8, 8), b);
}

TEST(FillRule, CentresOnEdgesGoToTopAndLeftEdgesOnly) {
    // A 4×4 square split along its diagonal, corners on pixel centres: top and left edges are in,
    // bottom and right are out, the diagonal goes to exactly one of the two triangles.
    const auto c = countScreen(
        {{0.5f, 0.5f}, {4.5f, 0.5f}, {4.5f, 4.5f}, {0.5f, 0.5f}, {4.5f, 4.5f}, {0.5f, 4.5f}}, 6, 6);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 6; ++x)
            EXPECT_EQ(c[y * 6 + x], (x < 4 && y < 4) ? 1 : 0) << x << "," << y;
}

TEST(FillRule, CullingDropsBackFacesOnly) {
    // Counter-clockwise on a y-up screen (clockwise in y-down pixel space) is front-facing.
    EXPECT_EQ(total(countScreen({{0, 5}, {5, 5}, {0, 0}}, 8, 8, true)), 10);
    EXPECT_EQ(total(countScreen({{0, 5}, {0, 0}, {5, 5}}, 8, 8, true)), 0);
}

/// A lattice of quads (two triangles each, diagonals alternating) rotated by `angle`, shifted by
/// a sub-pixel offset and scaled so it covers the whole screen; each vertex optionally gets a
/// random w (the same pixel position, projected). Like dEQP's fill-rule cases.
struct Tiling {
    std::vector<glm::vec4> clip;
    std::vector<std::uint32_t> indices;
};

Tiling rotatedQuadGrid(int n, float cell, float angle, glm::vec2 offset, bool randomW,
                       std::uint32_t seed, glm::vec2 centre) {
    Tiling t;
    const float c = std::cos(angle), s = std::sin(angle);
    std::uint32_t state = seed;
    auto unit = [&] {
        state = state * 1664525u + 1013904223u;
        return static_cast<float>(state >> 8) / 16777216.0f;
    };
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const glm::vec2 g((static_cast<float>(i) - static_cast<float>(n) / 2.0f) * cell,
                              (static_cast<float>(j) - static_cast<float>(n) / 2.0f) * cell);
            const glm::vec2 p = centre + offset + glm::vec2(c * g.x - s * g.y, s * g.x + c * g.y);
            const float w = randomW ? 0.1f + 3.9f * unit() : 1.0f;
            t.clip.emplace_back(p.x * w, p.y * w, w, w);
        }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const auto v = [&](int ii, int jj) {
                return static_cast<std::uint32_t>(jj * (n + 1) + ii);
            };
            if ((i + j) % 2)
                t.indices.insert(t.indices.end(), {v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j),
                                                   v(i + 1, j + 1), v(i, j + 1)});
            else
                t.indices.insert(t.indices.end(), {v(i, j), v(i + 1, j), v(i, j + 1), v(i + 1, j),
                                                   v(i + 1, j + 1), v(i, j + 1)});
        }
    return t;
}

class QuadGrid : public ::testing::TestWithParam<int> {};

TEST_P(QuadGrid, AdditiveHalfGreyNeverExceedsHalfAndLeavesNoHole) {
    // Additive 0.5 grey = coverage count × 0.5: "no pixel brighter than 0.5" is count <= 1 and
    // "none left empty inside" is count >= 1 over a screen the lattice covers entirely.
    const int seed = GetParam();
    const float angle = static_cast<float>(seed) * 0.37f;
    const glm::vec2 offset(0.13f * static_cast<float>(seed % 7),
                           0.29f * static_cast<float>(seed % 5));
    for (bool randomW : {false, true}) {
        const Tiling t = rotatedQuadGrid(24, 9.7f, angle, offset, randomW,
                                         99u + static_cast<std::uint32_t>(seed), {64.0f, 48.0f});
        Renderer r;
        std::vector<std::uint16_t> counts;
        facet::countCoverage(r, {.clip = t.clip, .indices = t.indices, .nearPlane = 0.05f},
                             RenderSettings{}, 128, 96, counts);
        int holes = 0, doubles = 0;
        for (auto v : counts) {
            holes += v == 0;
            doubles += v > 1;
        }
        EXPECT_EQ(holes, 0) << "angle " << angle << (randomW ? " random w" : "");
        EXPECT_EQ(doubles, 0) << "angle " << angle << (randomW ? " random w" : "");
    }
}

INSTANTIATE_TEST_SUITE_P(Angles, QuadGrid, ::testing::Range(0, 12));

TEST(FillRule, QuadMuchLargerThanTheScreenCoversEachPixelOnce) {
    // Far beyond the guard band: both triangles are clipped in 2D and still tile exactly.
    for (float size : {100.0f, 5e4f, 3e6f}) {
        const auto c = countScreen({{-size, -size},
                                    {size, -size * 0.7f},
                                    {size * 1.1f, size},
                                    {-size, -size},
                                    {size * 1.1f, size},
                                    {-size * 0.9f, size}},
                                   64, 48);
        for (std::size_t i = 0; i < c.size(); ++i)
            ASSERT_EQ(c[i], 1) << "size " << size << " pixel " << i;
    }
}

TEST(FillRule, JitteredPlaneInPerspectiveCoversItsOutlineExactlyOnce) {
    const Mesh grid = makeJitteredGrid(60, 60, 0.2f, 7u);  // 7200 triangles, boundary not jittered
    for (double angleDeg : {0.0, 35.0, 60.0, 80.0}) {
        const double a = angleDeg * std::numbers::pi / 180.0;
        const glm::dvec3 look{0.5, 0.5, 0.0};
        const Camera cam = test::lookAt(
            look + 1.6 * glm::dvec3(0.0, -std::sin(a), -std::cos(a)) + glm::dvec3(0.07, 0.0, 0.0),
            look, 300.0, 320, 240);
        const std::vector<glm::vec4> clip = test::clipPositions(cam, grid.positions);
        Renderer r;
        std::vector<std::uint16_t> counts;
        facet::countCoverage(r, {.clip = clip, .indices = grid.indices, .nearPlane = 0.01f},
                             RenderSettings{}, cam.width, cam.height, counts);

        // The outline is the projected unit square; classify each centre against it in double.
        glm::dvec2 q[4];
        const glm::dvec3 corners[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
        for (int k = 0; k < 4; ++k) q[k] = glm::dvec2(projectToPixel(cam, corners[k]));
        int inside = 0, wrong = 0;
        for (int y = 0; y < cam.height; ++y)
            for (int x = 0; x < cam.width; ++x) {
                const glm::dvec2 p(x + 0.5, y + 0.5);
                double minDist = 1e9;
                int sign = 0;
                for (int k = 0; k < 4; ++k) {
                    const glm::dvec2 e = q[(k + 1) % 4] - q[k];
                    const double d = (e.x * (p.y - q[k].y) - e.y * (p.x - q[k].x)) / glm::length(e);
                    minDist = std::min(minDist, std::abs(d));
                    sign += d > 0 ? 1 : -1;
                }
                const std::uint16_t c = counts[static_cast<std::size_t>(y * cam.width + x)];
                if (c > 1) ++wrong;  // never drawn twice, not even on the outline
                if (minDist < 1.0 / 256.0) continue;
                const bool in = sign == 4 || sign == -4;
                inside += in;
                if (c != (in ? 1 : 0)) {
                    ++wrong;
                    std::printf("pixel %d,%d count %d in %d dist %g\n", x, y, c, in, minDist);
                }
            }
        EXPECT_GT(inside, 1000) << angleDeg;
        EXPECT_EQ(wrong, 0) << "at " << angleDeg << " degrees";
    }
}

/// For a closed, consistently wound surface seen from outside, every pixel centre is crossed as
/// often by front faces as by back faces: total coverage = 2 × front coverage, exactly.
void expectClosedSurfaceBalanced(const Mesh& mesh, const Camera& cam, const std::string& what) {
    const std::vector<glm::vec4> clip = test::clipPositions(cam, mesh.positions);
    Renderer r;
    std::vector<std::uint16_t> all, front;
    RenderSettings s;
    const DrawInput in{.clip = clip, .indices = mesh.indices, .nearPlane = 0.001f};
    facet::countCoverage(r, in, s, cam.width, cam.height, all);
    s.cullBackFaces = true;
    facet::countCoverage(r, in, s, cam.width, cam.height, front);
    int covered = 0, unbalanced = 0;
    for (std::size_t i = 0; i < all.size(); ++i) {
        covered += front[i] > 0;
        unbalanced += all[i] != 2 * front[i];
    }
    EXPECT_GT(covered, 500) << what;
    EXPECT_EQ(unbalanced, 0) << what;
}

Camera orbitCamera(double yawDeg, double pitchDeg, double distance, int w, int h, double focal) {
    const double yaw = yawDeg * std::numbers::pi / 180.0,
                 pitch = pitchDeg * std::numbers::pi / 180.0;
    const glm::dvec3 eye = distance * glm::dvec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                                 std::cos(pitch) * std::cos(yaw));
    return test::lookAt(eye, {0.0, 0.0, 0.0}, focal, w, h);
}

TEST(Watertight, ClosedMeshesHaveNoCracksOrDoubleEdges) {
    const Mesh knot = makeTorusKnot(2, 3, 160, 16);
    const Mesh sphere = makeUvSphere(24, 48);
    for (double yaw : {0.0, 33.0, 121.0}) {
        for (double pitch : {-50.0, 10.0, 70.0}) {
            expectClosedSurfaceBalanced(knot, orbitCamera(yaw, pitch, 4.0, 200, 150, 180.0),
                                        "knot");
            expectClosedSurfaceBalanced(sphere, orbitCamera(yaw, pitch, 4.0, 200, 150, 180.0),
                                        "sphere");
        }
    }
}

TEST(Watertight, BunnyLeavesNoBackgroundPixelInsideItsSilhouette) {
    // The silhouette comes from the double-precision reference; a crack in the fast path would
    // show as background where the reference, away from any edge, says the bunny is.
    const std::string path = test::sharedData("scenes/bunny_1280x720.scene");
    REQUIRE_SHARED_DATA(path);
    Result<Scene> scene = loadScene(path);
    ASSERT_TRUE(scene.ok()) << scene.error().what();
    RenderSettings s;
    s.background = 0x000000;
    Renderer r;
    Framebuffer fb;
    r.render(*scene, s, fb);
    const reference::Image ref = reference::render(*scene, s).value();
    int inside = 0, holes = 0;
    for (std::size_t i = 0; i < fb.depth.size(); ++i) {
        if (!std::isfinite(ref.depth[i]) || ref.ambiguous[i]) continue;
        ++inside;
        holes += fb.depth[i] == kEmptyDepth;
    }
    EXPECT_GT(inside, 200000);
    EXPECT_EQ(holes, 0);
}

}  // namespace
}  // namespace facet
