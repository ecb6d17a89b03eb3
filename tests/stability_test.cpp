// Stability sweeps (issue 6, part 3): where each method fails, and that nothing crashes, hangs or
// produces NaN on the way there. Five groups, each against the double-precision reference path
// or against a closed-form expectation:
//   1. extreme triangles (1e-4 px to 1e6 px, slivers, ±1e7 px, the near plane, NaN and ±inf);
//   2. camera paths (through Spot and the bunny, grazing the near plane, the degenerate look-at,
//      sub-pixel meshes far away);
//   3. depth precision (the smallest gap δ/d two parallel planes need to resolve);
//   4. view angle (affine / subdivided:16 / perspective on the brick wall, 0° to 89°);
//   5. tessellation and highlights (Gouraud's peak against Phong's on UV spheres).
// The measured curves are printed as "[stability] ..." lines; each asserted bound carries the
// numbers it was measured from in a comment.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/procedural.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "image_compare.hpp"

namespace facet {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// A generous bound per case: it catches a hang or a loop over a 1e6-pixel bounding box, never a
// slow machine (the cases take well under 10 ms each in Release).
constexpr double kCaseBudgetMs = 2000.0;

// ---------------------------------------------------------------------------------------------
// 1. Extreme triangles

/// Fast coverage (countCoverage) against the reference's coverage of the same float clip-space
/// input, outside the pixels the reference flags as rounding-dependent.
struct CoverageCheck {
    std::size_t fast = 0;       ///< pixels the fast path covers
    std::size_t ref = 0;        ///< pixels the reference covers
    std::size_t differ = 0;     ///< non-ambiguous pixels where the two disagree
    std::size_t overdrawn = 0;  ///< pixels counted more than once (one triangle: never)
    double fastMs = 0.0, refMs = 0.0;
};

CoverageCheck checkCoverage(const std::vector<glm::vec4>& clip,
                            const std::vector<std::uint32_t>& indices, int w, int h,
                            float nearPlane = 1e-3f) {
    CoverageCheck c;
    Renderer renderer;
    RenderSettings settings;
    std::vector<std::uint16_t> counts;
    Clock::time_point t0 = Clock::now();
    renderer.countCoverage({.clip = clip, .indices = indices, .nearPlane = nearPlane}, settings, w,
                           h, counts);
    c.fastMs = msSince(t0);
    // The reference sees exactly the floats the fast path sees, so any difference is the
    // rasterizer's, not the input's rounding.
    std::vector<glm::dvec4> clipD(clip.begin(), clip.end());
    t0 = Clock::now();
    const reference::Image ref = reference::draw(
        {.clip = clipD, .indices = indices, .nearPlane = nearPlane}, settings, w, h);
    c.refMs = msSince(t0);
    for (std::size_t i = 0; i < counts.size(); ++i) {
        const bool fast = counts[i] > 0;
        const bool refCovered = std::isfinite(ref.depth[i]);
        c.fast += fast;
        c.ref += refCovered;
        c.overdrawn += counts[i] > 1;
        if (!ref.ambiguous[i] && fast != refCovered) ++c.differ;
    }
    return c;
}

/// Screen-space points (pixels) at depth w, as clip coordinates.
glm::vec4 atPixel(double x, double y, double w = 1.0) {
    return {static_cast<float>(x * w), static_cast<float>(y * w), static_cast<float>(w),
            static_cast<float>(w)};
}

void expectSameCoverage(const CoverageCheck& c, const char* label) {
    std::printf("[stability] coverage %-28s fast=%zu ref=%zu differ=%zu fast=%.2fms ref=%.2fms\n",
                label, c.fast, c.ref, c.differ, c.fastMs, c.refMs);
    EXPECT_EQ(c.differ, 0u) << label;
    EXPECT_EQ(c.overdrawn, 0u) << label;
    EXPECT_LT(c.fastMs, kCaseBudgetMs) << label;
    EXPECT_LT(c.refMs, kCaseBudgetMs) << label;
}

// Sizes from a ten-thousandth of a pixel to a million pixels: the snapped fixed-point edge
// functions must neither lose tiny triangles' exact coverage nor overflow on huge ones (beyond
// the 32768 px guard band the triangle is clipped in 2D).
TEST(ExtremeTriangles, CoverageMatchesReferenceFromTenThousandthToMillionPixels) {
    const int w = 64, h = 48;
    for (double size : {1e-4, 1e-3, 1e-2, 0.3, 1.0, 7.0, 40.0, 1e3, 3e4, 1e5, 1e6}) {
        // Centred on a pixel centre so even the tiny ones cover (or just miss) something.
        for (const glm::dvec2 centre : {glm::dvec2(20.5, 17.5), glm::dvec2(31.37, 22.81)}) {
            std::vector<glm::vec4> clip;
            for (double a : {0.3, 2.4, 4.3})
                clip.push_back(atPixel(centre.x + size * std::cos(a), centre.y + size * std::sin(a),
                                       1.0 + 0.5 * std::sin(3.0 * a)));
            char label[64];
            std::snprintf(label, sizeof label, "size %g at (%.2f,%.2f)", size, centre.x, centre.y);
            expectSameCoverage(checkCoverage(clip, {0, 1, 2}, w, h), label);
        }
    }
}

// Slivers with an aspect ratio of 1e6 (long edge / width): the edge functions' cross products
// are near zero, the worst case for any rounding in setup.
TEST(ExtremeTriangles, SliversOfAspectMillionMatchReference) {
    const int w = 64, h = 48;
    struct Sliver {
        double length, width, angle;
    };
    for (const Sliver s :
         {Sliver{100.0, 1e-4, 0.37}, Sliver{1e3, 1e-3, 1.1}, Sliver{1e6, 1.0, 0.61},
          Sliver{1e6, 1.0, 0.0}, Sliver{3e4, 3e-2, std::numbers::pi / 4}}) {
        const glm::dvec2 dir(std::cos(s.angle), std::sin(s.angle));
        const glm::dvec2 normal(-dir.y, dir.x);
        const glm::dvec2 mid(30.5, 20.5);
        const glm::dvec2 a = mid - 0.5 * s.length * dir, b = mid + 0.5 * s.length * dir;
        const glm::dvec2 c = mid + s.width * normal;
        const std::vector<glm::vec4> clip = {atPixel(a.x, a.y), atPixel(b.x, b.y),
                                             atPixel(c.x, c.y)};
        char label[64];
        std::snprintf(label, sizeof label, "sliver %gx%g @%.2f", s.length, s.width, s.angle);
        expectSameCoverage(checkCoverage(clip, {0, 1, 2}, w, h), label);
    }
}

// Vertices at ±1e7 px (a float's spacing there is a whole pixel): triangles crossing the
// screen from far outside the guard band, with and without varying w.
TEST(ExtremeTriangles, VerticesAtTenMillionPixelsMatchReference) {
    const int w = 64, h = 48;
    const double big = 1e7;
    struct Case {
        const char* name;
        std::vector<glm::vec4> clip;
    };
    const std::vector<Case> cases = {
        {"covers all", {atPixel(-big, -big), atPixel(big, -0.3 * big), atPixel(-0.2 * big, big)}},
        {"wedge through",
         {atPixel(-big, -0.5 * big + 20), atPixel(big, 0.5 * big + 20),
          atPixel(big, 0.5 * big + 29)}},
        {"one far vertex", {atPixel(10.25, 5.5), atPixel(50.75, 40.5), atPixel(-big, big)}},
        {"edge along screen", {atPixel(-big, 24.5), atPixel(big, 24.5), atPixel(0.0, big)}},
        {"all outside", {atPixel(-big, -big), atPixel(-big, big), atPixel(-0.5 * big, 0)}},
        {"far w", {atPixel(-big, -big, 1e4), atPixel(big, -big, 0.5), atPixel(0, big, 3.0)}},
    };
    for (const Case& c : cases) expectSameCoverage(checkCoverage(c.clip, {0, 1, 2}, w, h), c.name);
}

// On and across the near plane: vertices behind the camera, exactly on the plane, just in front
// of it, and huge pixel positions produced by tiny w.
TEST(ExtremeTriangles, NearPlaneCrossingsMatchReference) {
    const int w = 64, h = 48;
    const float n = 0.01f;
    struct Case {
        const char* name;
        std::vector<glm::vec4> clip;
    };
    const std::vector<Case> cases = {
        {"one behind", {atPixel(10, 10, 2.0), atPixel(50, 12, 1.0), atPixel(30, 40, -1.0)}},
        {"two behind", {atPixel(10, 10, 2.0), atPixel(50, 12, -0.5), atPixel(30, 40, -3.0)}},
        {"all behind", {atPixel(10, 10, -2.0), atPixel(50, 12, -0.5), atPixel(30, 40, -3.0)}},
        {"vertex on plane", {atPixel(10, 10, 2.0), atPixel(50, 12, 1.0), atPixel(30, 40, n)}},
        {"edge on plane", {atPixel(10, 10, n), atPixel(50, 12, n), atPixel(30, 40, 1.0)}},
        {"all on plane", {atPixel(10, 10, n), atPixel(50, 12, n), atPixel(30, 40, n)}},
        {"just in front", {atPixel(1e5, 10, 1.0001 * n), atPixel(50, 12, 1.0), atPixel(30, 40, 3)}},
        {"tiny w behind", {atPixel(1e7, 1e7, 1e-7), atPixel(50, 12, 1.0), atPixel(-30, 40, 2.0)}},
        {"w = 0", {glm::vec4(1e3f, 5e2f, 0.0f, 0.0f), atPixel(50, 12, 1.0), atPixel(3, 40, 2.0)}},
        {"huge w", {atPixel(10, 10, 1e30), atPixel(50, 12, 1.0), atPixel(30, 40, 1e-2)}},
    };
    for (const Case& c : cases)
        expectSameCoverage(checkCoverage(c.clip, {0, 1, 2}, w, h, n), c.name);
}

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// NaN and ±inf clip coordinates reaching the rasterizer directly: such a triangle has no
// position, so it must cover nothing, and it must not disturb a good triangle in the same draw.
TEST(ExtremeTriangles, NonFiniteClipCoordinatesCoverNothingAndSpareTheRest) {
    const int w = 64, h = 48;
    const std::vector<glm::vec4> bad = {
        {kNaN, 1, 1, 1},          {1, kNaN, 1, 1},           {1, 1, 1, kNaN}, {kInf, 1, 1, 1},
        {-kInf, 1, 1, 1},         {1, kInf, 1, 1},           {1, 1, 1, kInf}, {1, 1, 1, -kInf},
        {kInf, kInf, kInf, kInf}, {-kInf, -kInf, kInf, kInf}};
    // The good triangle alone, for reference.
    const std::vector<glm::vec4> good = {atPixel(5, 5, 1.0), atPixel(60, 8, 2.0),
                                         atPixel(20, 44, 0.5)};
    Renderer renderer;
    RenderSettings settings;
    std::vector<std::uint16_t> alone, counts;
    renderer.countCoverage({.clip = good, .indices = std::vector<std::uint32_t>{0, 1, 2}}, settings,
                           w, h, alone);
    // clip.z is never read (depth is 1/(interpolated 1/w)): a NaN there leaves a well-defined
    // position, and the triangle draws exactly as with a finite z.
    {
        const std::vector<glm::vec4> nanZ = {{5, 5, kNaN, 1}, good[1], good[2]};
        renderer.countCoverage({.clip = nanZ, .indices = std::vector<std::uint32_t>{0, 1, 2}},
                               settings, w, h, counts);
        std::vector<glm::vec4> finiteZ = nanZ;
        finiteZ[0].z = 1.0f;
        std::vector<std::uint16_t> expected;
        renderer.countCoverage({.clip = finiteZ, .indices = std::vector<std::uint32_t>{0, 1, 2}},
                               settings, w, h, expected);
        EXPECT_EQ(counts, expected);
    }
    for (std::size_t k = 0; k < bad.size(); ++k) {
        // Bad vertex first, then two good ones: a triangle 0-3-4 with one bad vertex, and the
        // good triangle 1-2-3 after it.
        const std::vector<glm::vec4> clip = {bad[k], good[0], good[1], good[2], atPixel(33, 33)};
        for (int position = 0; position < 3; ++position) {
            std::vector<std::uint32_t> idx = {1, 2, 4};
            idx[static_cast<std::size_t>(position)] = 0;
            idx.insert(idx.end(), {1, 2, 3});
            const Clock::time_point t0 = Clock::now();
            renderer.countCoverage({.clip = clip, .indices = idx}, settings, w, h, counts);
            EXPECT_LT(msSince(t0), kCaseBudgetMs);
            EXPECT_EQ(counts, alone)
                << "bad vertex " << k << " (" << bad[k].x << "," << bad[k].y << "," << bad[k].z
                << "," << bad[k].w << ") at corner " << position;
            // The same through draw(), every interpolation: no NaN reaches the depth buffer.
            for (Interp interp : {Interp::Perspective, Interp::Affine, Interp::Subdivided}) {
                RenderSettings s;
                s.interp = interp;
                Framebuffer fb;
                fb.resize(w, h);
                fb.clear(rgbaFromHex(s.background));
                renderer.draw({.clip = clip, .indices = idx}, s, fb);
                for (float d : fb.depth) ASSERT_FALSE(std::isnan(d)) << "bad vertex " << k;
            }
        }
    }
}

/// A small scene: camera at -z looking at the origin, 64×48.
Scene smallScene(Mesh mesh) {
    Scene scene;
    scene.mesh = std::move(mesh);
    scene.camera.eye = {0.0, 0.0, -4.0};
    scene.camera.look = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, -1.0, 0.0};
    scene.camera.width = 64;
    scene.camera.height = 48;
    scene.camera.focal = 60.0;
    return scene;
}

// NaN and ±inf positions in a mesh (the loaders reject them, but a program can build such a mesh
// and the viewer edits meshes live): the triangles touching them vanish, the others draw exactly
// as without them, under every lighting (Gouraud's area-weighted normals and Phong's
// interpolated ones must not pick up NaN from the bad faces).
TEST(ExtremeTriangles, NonFiniteMeshPositionsDropOnlyTheirTriangles) {
    Mesh good = makeUvSphere(6, 8);
    const std::size_t goodVertices = good.positions.size();
    const std::size_t goodIndices = good.indices.size();
    Mesh withBad = good;
    for (const glm::vec3 p : {glm::vec3(kNaN, 0, 0), glm::vec3(0, kInf, 0),
                              glm::vec3(-kInf, kInf, 1), glm::vec3(0, 0, -kInf)}) {
        const auto base = static_cast<std::uint32_t>(withBad.positions.size());
        withBad.positions.insert(withBad.positions.end(), {p, {0.5f, 0.5f, -0.5f}, {0, 1, -1}});
        withBad.colors.insert(withBad.colors.end(), 3, glm::vec3(1, 0, 0));
        withBad.uvs.insert(withBad.uvs.end(), 3, glm::vec2(0.5f, 0.5f));
        withBad.indices.insert(withBad.indices.end(), {base, base + 1, base + 2});
    }
    ASSERT_EQ(withBad.positions.size(), goodVertices + 12);
    ASSERT_EQ(withBad.indices.size(), goodIndices + 12);
    const Scene clean = smallScene(good);
    const Scene dirty = smallScene(withBad);
    Renderer renderer;
    Framebuffer a, b;
    for (Lighting lighting : {Lighting::Off, Lighting::Gouraud, Lighting::Phong}) {
        for (ShaderKind shader : {ShaderKind::Painter, ShaderKind::Depth, ShaderKind::Texture}) {
            RenderSettings s;
            s.lighting = lighting;
            s.shader = shader;
            s.combine = true;
            // The automatic near plane comes from the bounds; the bad vertices would make it
            // infinite or NaN, so both draws use the clean mesh's.
            s.nearPlane = resolveNearPlane(RenderSettings{}, good);
            renderer.render(clean, s, a);
            const Clock::time_point t0 = Clock::now();
            renderer.render(dirty, s, b);
            EXPECT_LT(msSince(t0), kCaseBudgetMs);
            for (float d : b.depth) ASSERT_FALSE(std::isnan(d));
            EXPECT_EQ(a.depth, b.depth) << toString(lighting) << " " << toString(shader);
            EXPECT_EQ(a.color, b.color) << toString(lighting) << " " << toString(shader);
        }
    }
}

// The automatic near plane of a mesh holding a non-finite vertex: whatever it resolves to, a
// render must neither crash nor write NaN depth.
TEST(ExtremeTriangles, NonFiniteMeshWithAutomaticNearPlaneStaysFinite) {
    Mesh mesh = makeUvSphere(6, 8);
    mesh.positions[3] = glm::vec3(kNaN, 0.0f, 0.0f);
    mesh.positions[7] = glm::vec3(kInf, -kInf, 0.0f);
    const Scene scene = smallScene(mesh);
    const double nearPlane = resolveNearPlane(RenderSettings{}, mesh);
    std::printf("[stability] auto near plane with NaN/inf vertices: %g\n", nearPlane);
    Renderer renderer;
    Framebuffer fb;
    for (Lighting lighting : {Lighting::Off, Lighting::Gouraud, Lighting::Phong}) {
        RenderSettings s;
        s.lighting = lighting;
        const Clock::time_point t0 = Clock::now();
        renderer.render(scene, s, fb);
        EXPECT_LT(msSince(t0), kCaseBudgetMs);
        for (float d : fb.depth) ASSERT_FALSE(std::isnan(d)) << toString(lighting);
    }
}

/// Renders with both paths and checks the fast-vs-reference rules (no coverage difference outside
/// the reference's ambiguity mask, colours within 1 LSB, no NaN depth); returns the fast draw's
/// stats.
RenderStats expectMatchesReference(Renderer& renderer, const Scene& scene, const RenderSettings& s,
                                   const std::string& label) {
    Framebuffer fb;
    const Clock::time_point t0 = Clock::now();
    const RenderStats stats = renderer.render(scene, s, fb);
    EXPECT_LT(msSince(t0), kCaseBudgetMs) << label;
    std::size_t nan = 0;
    for (float d : fb.depth) nan += std::isnan(d);
    EXPECT_EQ(nan, 0u) << label;
    const reference::Image ref = reference::render(scene, s);
    const test::Comparison c = test::compare(fb, ref, s.shader, s.background);
    EXPECT_EQ(c.coverageDiffers, 0u) << label << c.examples;
    EXPECT_LE(c.maxColorDiff, 1) << label << c.examples;
    return stats;
}

// A triangle crossing the near plane whose far vertices have |w| around 1e7 times the near
// distance. A ground triangle (±L, 0, −L), (0, 0, L) under a camera at (0.3, 1, 0) looking at
// (0, 0.7, 5), 64×48, f = 60, near 0.01. Until the clipper put the new vertex exactly on the
// plane, L = 1e5, 1e6, 1e7 drew nothing (its float w landed at or below 0) while the reference
// covers 1792 pixels.
TEST(ExtremeTriangles, HugeGroundTriangleAcrossNearPlaneMatchesReference) {
    Renderer renderer;
    for (float size : {1e3f, 8e4f, 1e5f, 1e6f, 1e7f}) {
        Mesh ground;
        ground.positions = {{-size, 0.0f, -size}, {size, 0.0f, -size}, {0.0f, 0.0f, size}};
        ground.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        ground.indices = {0, 1, 2};
        Scene scene = smallScene(ground);
        scene.camera.eye = {0.3, 1.0, 0.0};
        scene.camera.look = {0.0, 0.7, 5.0};
        for (Interp interp : {Interp::Perspective, Interp::Affine}) {
            RenderSettings s;
            s.interp = interp;
            s.nearPlane = 1e-2;
            char label[64];
            std::snprintf(label, sizeof label, "ground %g %s", static_cast<double>(size),
                          std::string(toString(interp)).c_str());
            const RenderStats stats = expectMatchesReference(renderer, scene, s, label);
            EXPECT_GT(stats.fragments, 1000u) << label;  // the reference covers 1713-1792
        }
    }
}

// The same ground up to the size the near-plane clip handles (see the disabled test above), so
// the working range stays pinned: with near 0.01, 8e4 world units (w up to 8e6 = 8e8 near).
TEST(ExtremeTriangles, LargeGroundTriangleAcrossNearPlaneMatchesReference) {
    Renderer renderer;
    for (float size : {1e2f, 1e3f, 1e4f, 8e4f}) {
        Mesh ground;
        ground.positions = {{-size, 0.0f, -size}, {size, 0.0f, -size}, {0.0f, 0.0f, size}};
        ground.colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        ground.indices = {0, 1, 2};
        Scene scene = smallScene(ground);
        scene.camera.eye = {0.3, 1.0, 0.0};
        scene.camera.look = {0.0, 0.7, 5.0};
        for (double nearPlane : {1e-2, 1.0}) {
            RenderSettings s;
            s.nearPlane = nearPlane;
            char label[64];
            std::snprintf(label, sizeof label, "ground %g near %g", static_cast<double>(size),
                          nearPlane);
            const RenderStats stats = expectMatchesReference(renderer, scene, s, label);
            EXPECT_GT(stats.fragments, 1000u) << label;
            EXPECT_EQ(stats.trianglesClipped, 1u) << label;
        }
    }
}

// A sphere scaled from 1e-4 to 1e5 world units with the camera and light scaled alike: float
// positions and the float transform at every magnitude give the reference's image.
TEST(ExtremeTriangles, ScaledSpheresMatchReferenceThroughRender) {
    Renderer renderer;
    for (double scale : {1e-4, 1e-2, 1.0, 1e2, 1e5}) {
        Mesh sphere = makeUvSphere(10, 16);
        for (auto& p : sphere.positions) p *= static_cast<float>(scale);
        Scene sc = smallScene(sphere);
        sc.camera.eye = glm::dvec3(0.2, -0.3, -4.0) * scale;
        sc.light.position = glm::dvec4(glm::dvec3(2.0, -3.0, -4.0) * scale, 1.0);
        for (Lighting lighting : {Lighting::Gouraud, Lighting::Phong}) {
            RenderSettings s;
            s.lighting = lighting;
            char label[64];
            std::snprintf(label, sizeof label, "sphere x%g %s", scale,
                          std::string(toString(lighting)).c_str());
            const RenderStats stats = expectMatchesReference(renderer, sc, s, label);
            EXPECT_GT(stats.fragments, 500u) << label;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// 2. Camera paths

/// A shared scene at a small size with vertices coloured by position (so interpolation errors
/// show as colour differences); false when the shared data is missing.
bool loadShared(const char* relative, Scene& scene, int w, int h) {
    Result<Scene> loaded = loadScene(std::string(FACET_SHARED_DIR) + "/data/" + relative);
    if (!loaded) return false;
    scene = std::move(loaded).value();
    const Bounds b = computeBounds(scene.mesh);
    scene.mesh.colors.clear();
    for (const auto& p : scene.mesh.positions)
        scene.mesh.colors.push_back((p - b.min) / (b.max - b.min));
    scene.camera.focal *= static_cast<double>(w) / scene.camera.width;
    scene.camera.width = w;
    scene.camera.height = h;
    return true;
}

// A camera flying through Spot and the bunny on a path that is not the near-plane test's, Phong
// lit so normals and world positions are interpolated across clipped triangles too.
TEST(CameraPaths, FlyThroughSpotAndBunnyMatchesReference) {
    for (const char* path : {"scenes/spot_1280x720.scene", "scenes/bunny_1280x720.scene"}) {
        Scene scene;
        if (!loadShared(path, scene, 96, 54)) GTEST_SKIP() << "shared data not available";
        const Bounds b = computeBounds(scene.mesh);
        const glm::dvec3 centre = 0.5 * glm::dvec3(b.min + b.max);
        const glm::dvec3 dir = glm::normalize(glm::dvec3(-0.7, 0.15, 0.6));
        const double extent = b.diagonal();
        Renderer renderer;
        int clippedFrames = 0;
        for (int frame = 0; frame < 24; ++frame) {
            const double t = -0.7 + 1.4 * frame / 23.0;
            scene.camera.eye = centre + t * extent * dir + glm::dvec3(0.0, 0.02 * extent, 0.0);
            scene.camera.look = scene.camera.eye + dir;
            RenderSettings s;
            s.interp = frame % 2 ? Interp::Affine : Interp::Perspective;
            s.lighting = frame % 3 == 0 ? Lighting::Phong : Lighting::Gouraud;
            const RenderStats stats = expectMatchesReference(
                renderer, scene, s, std::string(path) + " frame " + std::to_string(frame));
            clippedFrames += stats.trianglesClipped > 0;
        }
        std::printf("[stability] fly-through %s: %d of 24 frames clip at the near plane\n", path,
                    clippedFrames);
        EXPECT_GE(clippedFrames, 6) << path << ": the path must cross the mesh";
    }
}

// The near plane grazing the surface: the eye a few near distances (and a fraction of one) off
// a bunny vertex, looking straight at it and looking along the surface.
TEST(CameraPaths, GrazingTheNearPlaneMatchesReference) {
    Scene scene;
    if (!loadShared("scenes/bunny_1280x720.scene", scene, 80, 45))
        GTEST_SKIP() << "shared data not available";
    const Bounds b = computeBounds(scene.mesh);
    const glm::dvec3 centre = 0.5 * glm::dvec3(b.min + b.max);
    const double nearPlane = resolveNearPlane(RenderSettings{}, scene.mesh);
    Renderer renderer;
    // A vertex on the silhouette seen from +z: the one with the largest z.
    glm::dvec3 surface = scene.mesh.positions[0];
    for (const auto& p : scene.mesh.positions)
        if (p.z > surface.z) surface = p;
    // Roughly the surface normal there (the vertex is the mesh's extreme in +z).
    const glm::dvec3 outward = glm::normalize(surface - centre);
    std::size_t clipped = 0;
    for (double k : {0.5, 0.99, 1.0, 1.01, 2.0, 10.0}) {
        scene.camera.eye = surface + k * nearPlane * outward;
        for (int look = 0; look < 2; ++look) {
            // Straight at the surface, then across the normal (the near plane cuts the
            // triangles around the vertex nearly edge-on).
            const glm::dvec3 dir =
                look == 0 ? -outward : glm::normalize(glm::cross(outward, glm::dvec3(0, 1, 0)));
            scene.camera.look = scene.camera.eye + dir;
            RenderSettings s;
            s.interp = Interp::Perspective;
            char label[64];
            std::snprintf(label, sizeof label, "eye %.2f near off the surface, look %d", k, look);
            clipped += expectMatchesReference(renderer, scene, s, label).trianglesClipped;
        }
    }
    std::printf("[stability] grazing: %zu triangles clipped over 12 views\n", clipped);
    EXPECT_GT(clipped, 0u) << "the near plane must cut the surface in some views";
}

// Looking straight along the y hint: conventions §1 forbid it and checkCamera() says so; the
// look-at frame is then undefined (the cross product is zero, normalize gives NaN). A program
// that renders anyway must get no crash and no NaN depth.
TEST(CameraPaths, DegenerateLookAtIsRejectedAndRendersNoNaN) {
    Scene scene = smallScene(makeUvSphere(8, 12));
    scene.camera.eye = {0.0, 4.0, 0.0};
    scene.camera.look = {0.0, 0.0, 0.0};
    for (const glm::dvec3 up : {glm::dvec3(0, -1, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 0),
                                glm::dvec3(0, 1e-300, 0)}) {
        scene.camera.up = up;
        EXPECT_FALSE(checkCamera(scene.camera).empty()) << up.y;
        Renderer renderer;
        Framebuffer fb;
        for (Lighting lighting : {Lighting::Off, Lighting::Phong}) {
            RenderSettings s;
            s.lighting = lighting;
            const Clock::time_point t0 = Clock::now();
            const RenderStats stats = renderer.render(scene, s, fb);
            EXPECT_LT(msSince(t0), kCaseBudgetMs);
            for (float d : fb.depth) ASSERT_FALSE(std::isnan(d));
            // Every clip coordinate is NaN, so nothing can be drawn.
            EXPECT_EQ(stats.fragments, 0u);
        }
    }
    // A hint a hair off the axis is legal (checkCamera accepts it) and draws the sphere.
    scene.camera.up = {1e-6, 1.0, 0.0};
    EXPECT_TRUE(checkCamera(scene.camera).empty());
    Renderer renderer;
    expectMatchesReference(renderer, scene, RenderSettings{}, "hint 1e-6 off the axis");
}

// Far away: the bunny and Spot shrink to a few pixels, then to less than one; thousands of
// sub-pixel triangles must cover exactly the reference's pixels.
TEST(CameraPaths, FarAwaySubPixelMeshesMatchReference) {
    for (const char* path : {"scenes/spot_1280x720.scene", "scenes/bunny_1280x720.scene"}) {
        Scene scene;
        if (!loadShared(path, scene, 64, 36)) GTEST_SKIP() << "shared data not available";
        const glm::dvec3 look = scene.camera.look;
        const glm::dvec3 away = scene.camera.eye - look;
        Renderer renderer;
        std::size_t fragments = 0;
        for (double factor : {2.0, 5.0, 10.0, 30.0, 1e3, 1e5}) {
            scene.camera.eye = look + factor * away;
            RenderSettings s;
            s.nearPlane = 1e-3;
            Framebuffer fb;
            const RenderStats stats = renderer.render(scene, s, fb);
            std::printf("[stability] far %-28s x%-6g fragments=%zu\n", path, factor,
                        stats.fragments);
            fragments += factor >= 5.0 ? stats.fragments : 0;
            expectMatchesReference(renderer, scene, s,
                                   std::string(path) + " x" + std::to_string(factor));
        }
        // The far views really drew sub-pixel triangles (thousands per covered pixel).
        EXPECT_GT(fragments, 20u) << path;
    }
}

// ---------------------------------------------------------------------------------------------
// 3. Depth precision

/// Draws two parallel planes tilted 60° off the view axis through the point at distance d on the
/// axis, δ apart along their normal: the far one first (green), then the near one (red). With
/// LESS every pixel must end red; a pixel left green is z-fighting. Returns the share of the
/// far plane's pixels that show through.
double zFighting(double d, double delta) {
    const int w = 64, h = 64;
    Camera cam;
    cam.eye = {0, 0, 0};
    cam.look = {0, 0, 1};
    cam.up = {0, -1, 0};
    cam.width = w;
    cam.height = h;
    cam.focal = 64.0;
    const double tilt = 60.0 * std::numbers::pi / 180.0;
    const glm::dvec3 normal(0.0, std::sin(tilt), -std::cos(tilt));  // towards the camera
    const glm::dvec3 along(0.0, std::cos(tilt), std::sin(tilt));
    const glm::dvec3 side(1.0, 0.0, 0.0);
    std::vector<glm::vec4> clip;
    std::vector<glm::vec3> colors;
    // A quad 0.6·d on a side covers the 64×64 view at this focal length, with room to spare.
    for (int plane = 0; plane < 2; ++plane) {
        const glm::dvec3 c = glm::dvec3(0, 0, d) + (plane == 0 ? -0.5 : 0.5) * delta * normal;
        for (const glm::dvec2 q :
             {glm::dvec2(-1, -1), glm::dvec2(1, -1), glm::dvec2(1, 1), glm::dvec2(-1, 1)}) {
            const glm::dvec3 p = c + 0.6 * d * (q.x * side + q.y * along);
            clip.push_back(glm::vec4(reference::projectPoint(cam, p)));
            colors.emplace_back(plane == 0 ? 0.0f : 1.0f, plane == 0 ? 1.0f : 0.0f, 0.0f);
        }
    }
    const std::vector<std::uint32_t> idx = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    Renderer renderer;
    RenderSettings s;
    s.threads = 1;
    Framebuffer fb;
    fb.resize(w, h);
    fb.clear(rgbaFromHex(s.background));
    renderer.draw({.clip = clip, .colors = colors, .indices = idx, .nearPlane = 1e-3f}, s, fb);
    const std::uint32_t green = packRgba(0, 255, 0), red = packRgba(255, 0, 0);
    std::size_t covered = 0, fighting = 0;
    for (std::uint32_t c : fb.color) {
        covered += c == green || c == red;
        fighting += c == green;
    }
    return covered ? static_cast<double>(fighting) / static_cast<double>(covered) : 1.0;
}

// Depth is float camera-space Z, 1/(interpolated 1/w): its relative precision is about the same
// at every distance (a float's 2^-24, times the interpolation's rounding), so the smallest
// resolved gap grows linearly with d and δ/d is roughly constant from d = 1 to 1e4. Along the
// view rays of the 60° planes the gap is about 2δ, so δ/d ≈ 6e-8 is one float step of depth:
// the interpolation loses (next to) nothing beyond the storage format.
TEST(DepthPrecision, SmallestResolvedGapIsAConstantFractionOfDistance) {
    std::vector<double> resolved;
    for (double d : {1.0, 10.0, 100.0, 1e3, 1e4}) {
        // Smallest δ/d on a quarter-octave ladder such that it and every larger step resolve.
        double smallest = 0.0;
        for (double rel = 1e-3; rel > 1e-9; rel /= std::pow(2.0, 0.25)) {
            if (zFighting(d, rel * d) > 0.0) break;
            smallest = rel;
        }
        std::printf("[stability] depth d=%-6g smallest resolved delta/d=%.3g\n", d, smallest);
        resolved.push_back(smallest);
    }
    for (double rel : resolved) {
        EXPECT_GT(rel, 0.0) << "even a 1e-3 gap fights";
        // Measured smallest resolved δ/d at d = 1, 10, 100, 1e3, 1e4: 8.6e-8, 7.3e-8, 5.1e-8,
        // 8.6e-8, 5.1e-8 — about one float ulp (2^-24 = 6e-8) at every distance.
        EXPECT_LE(rel, 2e-7);
    }
    // Constant relative precision: measured spread max/min = 8.6e-8 / 5.1e-8 = 1.7.
    const auto [lo, hi] = std::minmax_element(resolved.begin(), resolved.end());
    EXPECT_LE(*hi / *lo, 4.0);
    // Below float precision nothing can resolve: this is what the search must find.
    for (double d : {1.0, 1e4}) EXPECT_GT(zFighting(d, 1e-8 * d), 0.0) << d;
}

// ---------------------------------------------------------------------------------------------
// 4. View angle

/// RMS channel error of `fast` against the reference's 8-bit image over its covered,
/// unambiguous pixels; max error in `maxOut`.
double rmse(const Framebuffer& fast, const reference::Image& ref, int& maxOut,
            std::size_t& coveredOut) {
    const std::vector<std::uint32_t> truth = ref.toRgba();
    double sum2 = 0.0;
    std::size_t covered = 0;
    maxOut = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (!std::isfinite(ref.depth[i]) || ref.ambiguous[i]) continue;
        ++covered;
        for (int shift = 0; shift < 24; shift += 8) {
            const int e = std::abs(static_cast<int>((fast.color[i] >> shift) & 0xFF) -
                                   static_cast<int>((truth[i] >> shift) & 0xFF));
            sum2 += static_cast<double>(e) * e;
            maxOut = std::max(maxOut, e);
        }
    }
    coveredOut = covered;
    return covered ? std::sqrt(sum2 / (3.0 * static_cast<double>(covered))) : 0.0;
}

// The course's brick wall turned from face-on (0°) to almost edge-on (89°) about an axis in its
// plane, the camera's y hint along that axis so depth changes along rows (the case subdivision
// is for). Perspective stays exact; affine's error grows with the angle.
TEST(ViewAngle, AffineDegradesWithAnglePerspectiveStaysExact) {
    const std::string data = std::string(FACET_SHARED_DIR) + "/data/course/";
    if (!std::filesystem::exists(data + "brick.jpg")) GTEST_SKIP() << "shared data not found";
    Result<Scene> loaded = loadScene(data + "example_textured.scene");
    ASSERT_TRUE(loaded.ok()) << loaded.error().what();
    Scene scene = std::move(loaded).value();
    ASSERT_FALSE(loadSceneTexture(scene, data + "brick.jpg").has_value());
    // The facet is the unit square in z = 0, normal +z.
    scene.camera.width = scene.camera.height = 160;
    scene.camera.focal = 110.0;
    scene.camera.look = {0.5, 0.5, 0.0};
    scene.camera.up = {1.0, 0.0, 0.0};
    RenderSettings s;
    s.shader = ShaderKind::Texture;
    // Trilinear: the wall is minified several texels per pixel, and bilinear's aliasing would
    // turn any sub-texel shift into full-contrast noise; the mip chain keeps the error a
    // measure of where the bricks land.
    s.filter = TextureFilter::Trilinear;
    Renderer renderer;
    Framebuffer fb;
    // The first angle of the sweep where each approximation's RMSE exceeds 8 LSB.
    double affineCross = -1.0, subCross = -1.0;
    for (double deg : {0.0,  0.5,  1.0,  2.0,  3.0,  4.0,  5.0,  7.5,  10.0, 15.0,
                       20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0, 85.0, 89.0}) {
        const double a = deg * std::numbers::pi / 180.0;
        scene.camera.eye = scene.camera.look + 1.0 * glm::dvec3(0.0, std::sin(a), std::cos(a));
        s.interp = Interp::Perspective;
        const reference::Image ref = reference::render(scene, s);
        double err[3];
        int maxErr[3];
        std::size_t covered = 0;
        const Interp modes[3] = {Interp::Perspective, Interp::Subdivided, Interp::Affine};
        for (int m = 0; m < 3; ++m) {
            s.interp = modes[m];
            s.subdivision = 16;
            renderer.render(scene, s, fb);
            for (float d : fb.depth) ASSERT_FALSE(std::isnan(d));
            err[m] = rmse(fb, ref, maxErr[m], covered);
        }
        std::printf(
            "[stability] angle %5.2f deg covered=%5zu rmse perspective=%.3f (max %d) "
            "subdivided:16=%.3f affine=%.3f (max %d)\n",
            deg, covered, err[0], maxErr[0], err[1], err[2], maxErr[2]);
        EXPECT_LE(maxErr[0], 1) << deg << " deg";
        // Subdivision helps up to 80° (80°: 15.2 against 17.3); nearer edge-on it can lose to
        // affine (85°: 15.9 against 11.7), both far from the truth, so no order is pinned there.
        if (deg <= 80.0) {
            EXPECT_LE(err[1], err[2]) << deg << " deg";
        }
        if (affineCross < 0.0 && err[2] > 8.0) affineCross = deg;
        if (subCross < 0.0 && err[1] > 8.0) subCross = deg;
        // Measured RMSE (LSB), affine: 0° 0, 0.5° 5.9, 1° 11.2, 2° 19.6, 5° 30.0, 10°-60° 30-36,
        // 70° 24.9, 80° 17.3, 85° 11.7, 89° 3.2 (the wall mips to its mean colour edge-on).
        if (deg >= 1.0 && deg <= 85.0) {
            EXPECT_GT(err[2], 8.0) << deg << " deg";
        }
        // subdivided:16: 0.5° 0.28, 5° 1.4, 10° 2.8, 20° 5.3, 30° 7.2, 40° 10.1, 60° 11.7,
        // 70° 15.8, 85° 15.9, 89° 3.3.
        if (deg <= 30.0) {
            EXPECT_LE(err[1], 8.0) << deg << " deg";
        }
        if (deg >= 40.0 && deg <= 85.0) {
            EXPECT_GT(err[1], 8.0) << deg << " deg";
        }
        if (deg == 0.0) {
            EXPECT_LE(maxErr[2], 1) << "face-on, affine is exact";
        }
    }
    std::printf("[stability] RMSE first exceeds 8 LSB at: affine %g deg, subdivided:16 %g deg\n",
                affineCross, subCross);
    EXPECT_EQ(affineCross, 1.0);  // measured: 5.9 LSB at 0.5°, 11.2 at 1°
    EXPECT_EQ(subCross, 40.0);    // measured: 7.2 LSB at 30°, 10.1 at 40°
}

// ---------------------------------------------------------------------------------------------
// 5. Tessellation and highlights

/// Peak red channel (0..255) of a white UV sphere lit by specular only, Gouraud and Phong.
struct Peaks {
    int gouraud = 0, phong = 0;
};

Peaks highlightPeaks(int rings, double shininess) {
    Mesh mesh = makeUvSphere(rings, 2 * rings);
    mesh.colors.assign(mesh.positions.size(), glm::vec3(1.0f));
    Scene scene;
    scene.mesh = std::move(mesh);
    // Eye and light together on a generic direction, so the highlight centre (the point facing
    // them) falls inside a face rather than on a vertex.
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.31, -0.23, -1.0));
    scene.camera.eye = 4.0 * dir;
    scene.camera.look = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, -1.0, 0.0};
    scene.camera.width = scene.camera.height = 96;
    scene.camera.focal = 150.0;
    scene.ambient = 0.0;
    scene.light.position = glm::dvec4(4.0 * dir, 1.0);
    scene.light.intensity = 1.0;
    scene.material = {.ka = 0.0, .kd = 0.0, .ks = 1.0, .s = shininess};
    Renderer renderer;
    Framebuffer fb;
    Peaks p;
    for (Lighting lighting : {Lighting::Gouraud, Lighting::Phong}) {
        RenderSettings s;
        s.lighting = lighting;
        s.background = 0x000000;
        renderer.render(scene, s, fb);
        int peak = 0;
        for (std::uint32_t c : fb.color) peak = std::max(peak, static_cast<int>(c & 0xFF));
        (lighting == Lighting::Gouraud ? p.gouraud : p.phong) = peak;
    }
    return p;
}

// Gouraud samples the highlight only at vertices: once the highlight is narrower than a face
// it falls between them and Gouraud's peak collapses, while Phong keeps it. Measured ratio
// Gouraud peak / Phong peak (96×96, sphere 2·rings sectors):
//   rings 8:  s=1 0.96, 4 0.87, 16 0.57, 64 0.11, 256 0.00, 1024 0.00
//   rings 16: s=1 0.99, 4 0.96, 16 0.87, 64 0.58, 256 0.13, 1024 0.00
//   rings 32: s=1 1.00, 4 1.00, 16 0.98, 64 0.94, 256 0.87, 1024 0.72
// Phong's own peak (252-255 up to s = 64) drops to 244-246 at s = 256 and 213-244 at s = 1024: the
// highlight is then narrower than a pixel, and pixel centres miss its maximum.
TEST(Highlights, GouraudLosesTheHighlightAsShininessGrows) {
    const std::vector<double> shininess = {1.0, 4.0, 16.0, 64.0, 256.0, 1024.0};
    for (int rings : {8, 16, 32}) {
        std::printf("[stability] highlight rings=%-3d gouraud/phong peak:", rings);
        double loses = 0.0;  // smallest s with Gouraud's peak below half of Phong's
        double previous = 2.0;
        for (double s : shininess) {
            const Peaks p = highlightPeaks(rings, s);
            ASSERT_GT(p.phong, 0);
            const double ratio = static_cast<double>(p.gouraud) / p.phong;
            std::printf(" s=%g:%.2f", s, ratio);
            EXPECT_GE(p.phong, s <= 64.0 ? 250 : 200) << "rings " << rings << " s " << s;
            // A sharper highlight is never better sampled by the same vertices.
            EXPECT_LE(ratio, previous + 0.01) << "rings " << rings << " s " << s;
            previous = ratio;
            if (loses == 0.0 && ratio < 0.5) loses = s;
        }
        std::printf(" -> below half from s=%g\n", loses);
        // Where the highlight is lost: each doubling of the tessellation buys about a factor of
        // four in s (the highlight's width goes as 1/sqrt(s)).
        if (rings == 8) {
            EXPECT_EQ(loses, 64.0);  // 0.57 at s=16, 0.11 at s=64
        }
        if (rings == 16) {
            EXPECT_EQ(loses, 256.0);  // 0.58 at s=64, 0.13 at s=256
        }
        if (rings == 32) {
            EXPECT_EQ(loses, 0.0);  // still 0.72 at s=1024
        }
    }
}

}  // namespace
}  // namespace facet
