// Shading through the fast path's whole pipeline, checked against facts that need no reference
// renderer: mip level from the distance of a plane, Phong's highlight inside a face where
// Gouraud has none, the subdivided mode exact at span ends, the normals display and its depth
// test, and the texture shader's combine.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <utility>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/scene.hpp"
#include "facet/texture.hpp"

namespace {

using facet::Framebuffer;
using facet::Interp;
using facet::Lighting;
using facet::LightingParams;
using facet::RenderSettings;
using facet::Scene;
using facet::ShaderKind;
using facet::TextureFilter;

int channel(std::uint32_t rgba, int c) {
    return static_cast<int>((rgba >> (8 * c)) & 0xFFu);
}

/// A square [-1, 1]² in the plane z = zPlane, uv (0,0)..(1,1), two triangles facing −z.
facet::Mesh square(float zPlane = 0.0f, float half = 1.0f) {
    facet::Mesh m;
    m.positions = {
        {-half, -half, zPlane}, {half, -half, zPlane}, {half, half, zPlane}, {-half, half, zPlane}};
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 2, 1, 0, 3, 2};
    return m;
}

/// Camera on the −z axis looking at the origin, world +Y up on screen.
Scene sceneFacing(facet::Mesh mesh, double distance, double focal, int size) {
    Scene s;
    s.mesh = std::make_shared<const facet::Mesh>(std::move(mesh));
    s.camera.eye = {0.0, 0.0, -distance};
    s.camera.look = {0.0, 0.0, 0.0};
    s.camera.up = {0.0, -1.0, 0.0};
    s.camera.focal = focal;
    s.camera.width = size;
    s.camera.height = size;
    return s;
}

/// A T×T checker of single black and white texels.
std::shared_ptr<const facet::Texture> checker(int t) {
    std::vector<std::uint32_t> px(static_cast<std::size_t>(t) * t);
    for (int y = 0; y < t; ++y)
        for (int x = 0; x < t; ++x)
            px[static_cast<std::size_t>(y) * t + x] =
                ((x + y) % 2) ? facet::packRgba(255, 255, 255) : facet::packRgba(0, 0, 0);
    auto r = facet::Texture::fromRgba(t, t, std::move(px), "checker");
    return std::make_shared<const facet::Texture>(std::move(r.value()));
}

// The quad is 2 world units wide at distance 4: 2·f/4 pixels for 64 texels. With f = 128 one
// texel per pixel (level 0, the checker itself); with f = 64 two texels per pixel (level 1, grey).
TEST(Shading, TrilinearPicksTheLevelFromTheDistance) {
    for (const double focal : {128.0, 64.0, 32.0}) {
        Scene s = sceneFacing(square(), 4.0, focal, 256);
        s.texture = checker(64);
        RenderSettings set;
        set.shader = ShaderKind::Texture;
        set.filter = TextureFilter::Trilinear;
        facet::Renderer r;
        Framebuffer f;
        r.render(s, set, f);
        const int half = static_cast<int>(focal / 4.0);  // quad half-width in pixels
        int minV = 255, maxV = 0;
        for (int y = 128 - half + 1; y < 128 + half - 1; ++y)
            for (int x = 128 - half + 1; x < 128 + half - 1; ++x) {
                const int v = channel(f.color[f.index(x, y)], 0);
                minV = std::min(minV, v);
                maxV = std::max(maxV, v);
            }
        if (focal == 128.0) {
            EXPECT_EQ(minV, 0) << "level 0 shows the black texels";
            EXPECT_EQ(maxV, 255) << "level 0 shows the white texels";
        } else {
            EXPECT_GE(minV, 126) << "focal " << focal << ": a coarser level is uniform grey";
            EXPECT_LE(maxV, 129) << "focal " << focal;
        }
    }
}

// A light just in front of the middle of a big square: every vertex sees it at a grazing angle,
// the centre head-on. Gouraud interpolates the dim corners; Phong finds the bright centre.
TEST(Shading, PhongFindsTheHighlightInsideAFace) {
    Scene s = sceneFacing(square(0.0f, 2.0f), 6.0, 100.0, 128);
    s.lighting.ambient = 0.0;
    s.lighting.light.position = {0.0, 0.0, -0.3, 1.0};
    s.lighting.light.intensity = 1.0;
    s.lighting.material = {0.0, 0.8, 0.0, 1.0};
    RenderSettings set;
    facet::Renderer r;
    Framebuffer gouraud, phong;
    set.lighting = Lighting::Gouraud;
    r.render(s, set, gouraud);
    set.lighting = Lighting::Phong;
    r.render(s, set, phong);
    const std::size_t centre = phong.index(64, 64);
    // n·l at a corner: 0.3 / sqrt(0.09 + 8) ≈ 0.105, so about 0.084 · 255 ≈ 22 everywhere.
    EXPECT_LE(channel(gouraud.color[centre], 0), 30);
    // At the centre n·l ≈ 1: 0.8 · 255 = 204.
    EXPECT_NEAR(channel(phong.color[centre], 0), 204, 2);
    // Phong is symmetric about the centre; no NaN pixels anywhere (they would round to 0).
    EXPECT_EQ(phong.color[phong.index(54, 64)], phong.color[phong.index(73, 64)]);
}

// A long wall seen at a grazing angle, so depth changes along each row: the subdivided mode is
// exact where x is a multiple of N, and its error elsewhere shrinks with N.
TEST(Shading, SubdividedIsExactAtSpanEndsAndBetweenAffineAndPerspective) {
    facet::Mesh wall;
    wall.positions = {{-1, -1, 0}, {-1, 1, 0}, {-1, 1, 30}, {-1, -1, 30}};
    wall.uvs = {{0, 0}, {0, 2}, {15, 2}, {15, 0}};
    wall.indices = {0, 2, 1, 0, 3, 2};
    Scene s = sceneFacing(std::move(wall), 2.0, 200.0, 256);
    s.texture = checker(8);
    s.camera.eye = {0.0, 0.0, -1.0};
    s.camera.look = {-0.3, 0.0, 4.0};
    facet::Renderer r;
    RenderSettings set;
    set.shader = ShaderKind::Texture;
    set.filter = TextureFilter::Bilinear;
    auto renderWith = [&](Interp interp, int n) {
        set.interp = interp;
        set.subdivision = n;
        Framebuffer f;
        r.render(s, set, f);
        return f;
    };
    const Framebuffer exact = renderWith(Interp::Perspective, 16);
    const Framebuffer affine = renderWith(Interp::Affine, 16);
    auto error = [&](const Framebuffer& f, bool spanEndsOnly, int n) {
        long long sum = 0;
        int maxDiff = 0;
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x) {
                if (spanEndsOnly && x % n != 0) continue;
                const std::size_t i = f.index(x, y);
                for (int c = 0; c < 3; ++c) {
                    const int d = std::abs(channel(f.color[i], c) - channel(exact.color[i], c));
                    sum += d;
                    maxDiff = std::max(maxDiff, d);
                }
            }
        return std::make_pair(sum, maxDiff);
    };
    long long previous = error(affine, false, 1).first;
    ASSERT_GT(previous, 10000) << "the scene must show affine's error";
    for (const int n : {32, 8, 2}) {
        const Framebuffer sub = renderWith(Interp::Subdivided, n);
        EXPECT_LE(error(sub, true, n).second, 1) << "N = " << n << ": exact at span ends";
        const long long e = error(sub, false, n).first;
        EXPECT_LT(e, previous) << "N = " << n << ": finer spans, smaller error";
        previous = e;
    }
}

// Normals: one segment per vertex with a face; hidden behind a nearer surface under the depth
// test, drawn over it by the Simple shader.
TEST(Shading, NormalsDisplayDrawsRedSegmentsWithTheDepthTest) {
    facet::Mesh m = square(0.0f, 1.0f);
    // The square faces −z (towards the camera), so its normals point at the camera: give them
    // length 0 in view by looking from the side instead.
    Scene s = sceneFacing(std::move(m), 4.0, 100.0, 128);
    s.camera.eye = {4.0, 0.0, -0.5};
    s.camera.look = {0.0, 0.0, -0.5};
    RenderSettings set;
    set.showNormals = true;
    set.normalLength = 1.0;
    facet::Renderer r;
    Framebuffer f;
    const facet::RenderStats st = r.render(s, set, f).value();
    EXPECT_EQ(st.normalsDrawn, 4u);
    int red = 0;
    for (const std::uint32_t p : f.color) red += p == facet::packRgba(255, 0, 0);
    EXPECT_GT(red, 40) << "four segments of 25 px seen from the side";

    // A wall between the camera and the segments hides them from Painter, not from Simple.
    facet::Mesh both = *s.mesh;
    const std::uint32_t base = static_cast<std::uint32_t>(both.positions.size());
    for (const glm::vec3 p :
         {glm::vec3(2, -2, -3), glm::vec3(2, 2, -3), glm::vec3(2, 2, 3), glm::vec3(2, -2, 3)})
        both.positions.push_back(p);
    for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) both.indices.push_back(base + i);
    s.mesh = std::make_shared<const facet::Mesh>(std::move(both));
    set.normalLength = 1.0;
    r.render(s, set, f);
    int hidden = 0;
    for (const std::uint32_t p : f.color) hidden += p == facet::packRgba(255, 0, 0);
    EXPECT_EQ(hidden, 0);
    set.shader = ShaderKind::Simple;
    r.render(s, set, f);
    int shown = 0;
    for (const std::uint32_t p : f.color) shown += p == facet::packRgba(255, 0, 0);
    EXPECT_GT(shown, 40);
}

// Combine multiplies the texel by the vertex colour; without it the colour is ignored.
TEST(Shading, CombineMultipliesTheTexelByTheColour) {
    Scene s = sceneFacing(square(), 4.0, 128.0, 64);
    std::vector<std::uint32_t> px(4, facet::packRgba(200, 100, 50));
    s.texture = std::make_shared<const facet::Texture>(
        std::move(facet::Texture::fromRgba(2, 2, std::move(px), "flat").value()));
    facet::Mesh coloured = *s.mesh;
    coloured.colors.assign(4, glm::vec3(0.5f, 1.0f, 0.0f));
    s.mesh = std::make_shared<const facet::Mesh>(std::move(coloured));
    RenderSettings set;
    set.shader = ShaderKind::Texture;
    facet::Renderer r;
    Framebuffer f;
    r.render(s, set, f);
    EXPECT_EQ(f.color[f.index(32, 32)], facet::packRgba(200, 100, 50));
    set.combine = true;
    r.render(s, set, f);
    EXPECT_EQ(f.color[f.index(32, 32)], facet::packRgba(100, 100, 0));
    // No texture at all samples white: the combined colour is the vertex colour.
    s.texture.reset();
    r.render(s, set, f);
    EXPECT_EQ(f.color[f.index(32, 32)], facet::packRgba(128, 255, 0));
}

}  // namespace

namespace {

// Lighting parameters are plain scene fields: an edit shows in the next frame of the same
// renderer, with nothing reloaded or rebuilt.
TEST(Shading, LightingEditsShowInTheNextFrame) {
    auto start = [] {
        Scene x = sceneFacing(square(0.0f, 2.0f), 6.0, 100.0, 64);
        x.lighting.light.position = {0.5, 0.5, -2.0, 1.0};
        x.lighting.ambient = 0.2;
        x.lighting.material = {0.2, 0.4, 0.2, 8.0};
        return x;
    };
    Scene s = start();
    facet::Renderer r;
    Framebuffer f;
    for (const Lighting lighting : {Lighting::Gouraud, Lighting::Phong}) {
        RenderSettings set;
        set.lighting = lighting;
        r.render(s, set, f);
        std::vector<std::uint32_t> previous = f.color;
        const auto edits = {+[](LightingParams& x) { x.material.kd *= 0.5; },
                            +[](LightingParams& x) { x.material.ks = 0.9; },
                            +[](LightingParams& x) { x.material.s = 40.0; },
                            +[](LightingParams& x) { x.ambient = 0.6; },
                            +[](LightingParams& x) { x.material.ka = 0.9; },
                            +[](LightingParams& x) { x.light.intensity = 2.0; },
                            +[](LightingParams& x) {
                                x.light.position = {0.0, 0.0, -1.0, 0.0};
                            }};
        int k = 0;
        for (auto edit : edits) {
            edit(s.lighting);
            r.render(s, set, f);
            EXPECT_NE(f.color, previous) << facet::toString(lighting) << ", edit " << k;
            previous = f.color;
            ++k;
        }
        s = start();
    }
}

}  // namespace

namespace {

// The depth legend: a black box in the bottom-left corner holding the viridis bar (dark on the
// left, bright on the right) and the two depths as white digits.
TEST(Shading, DepthLegendShowsTheBarAndTheRange) {
    Scene s = sceneFacing(square(), 4.0, 128.0, 400);
    RenderSettings set;
    set.shader = ShaderKind::Depth;
    set.depthLegend = true;
    facet::Renderer r;
    Framebuffer f;
    const facet::RenderStats st = r.render(s, set, f).value();
    EXPECT_FLOAT_EQ(st.depthNear, st.depthFar);  // a square facing the camera: one depth
    // Scale 2 at this height: margin 8, bar 12 px high starting 8 px inside the box.
    const int barTop = f.height - 8 - (12 + 10 + 24) + 8;
    const std::uint32_t left = f.color[f.index(16, barTop + 2)];
    const std::uint32_t right = f.color[f.index(16 + 255, barTop + 2)];
    EXPECT_LT(channel(left, 1), 20) << "viridis starts dark purple";
    EXPECT_GT(channel(right, 0), 200) << "and ends bright yellow";
    int white = 0;
    for (int y = barTop + 12; y < f.height; ++y)
        for (int x = 0; x < 300; ++x)
            white += f.color[f.index(x, y)] == facet::packRgba(255, 255, 255);
    EXPECT_GT(white, 50) << "the labels are drawn";
    // Without the flag, no legend.
    set.depthLegend = false;
    r.render(s, set, f);
    EXPECT_EQ(f.color[f.index(16, barTop + 2)], facet::rgbaFromHex(set.background));
}

}  // namespace
