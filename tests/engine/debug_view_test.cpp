// Debug views (RenderSettings::view): each view's numbers on a scene whose answer is known, and
// the heat map and legend render() paints from them.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "facet/advanced/draw.hpp"
#include "facet/camera.hpp"
#include "facet/colormap.hpp"
#include "facet/debug_view.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/scene.hpp"
#include "facet/scene_io.hpp"
#include "facet/settings.hpp"
#include "facet/texture.hpp"
#include "pipeline/vertex_stage.hpp"
#include "world_at.hpp"

namespace {

using facet::DebugMap;
using facet::DebugView;
using facet::Framebuffer;
using facet::RenderSettings;
using facet::Scene;
using facet::test::worldAt;

/// A pixel-space corner of a test quad or triangle: position, camera depth, uv and colour.
struct Corner {
    double x, y, z;
    glm::vec2 uv{0.0f};
    glm::vec3 rgb{1.0f};
};

/// Builds meshes in pixels on a `w`×`h` camera.
struct SceneBuilder {
    Scene scene;
    facet::Mesh mesh;

    SceneBuilder(int w, int h) {
        scene.camera.width = w;
        scene.camera.height = h;
        scene.camera.focal = 100.0;
    }
    void triangle(const Corner& a, const Corner& b, const Corner& c) {
        for (const Corner& k : {a, b, c}) {
            mesh.indices.push_back(static_cast<std::uint32_t>(mesh.positions.size()));
            mesh.positions.push_back(worldAt(scene.camera, k.x, k.y, k.z));
            mesh.uvs.push_back(k.uv);
            mesh.colors.push_back(k.rgb);
        }
    }
    /// An axis-aligned rectangle [x0, x1] × [y0, y1] as two triangles, depth z0 at x0 and z1 at
    /// x1, uv (0,0) at the top-left and (1,1) at the bottom-right, red growing left to right.
    void quad(double x0, double y0, double x1, double y1, double z0, double z1 = -1.0) {
        if (z1 < 0.0) z1 = z0;
        const Corner tl{x0, y0, z0, {0, 0}, {0, 0, 1}}, tr{x1, y0, z1, {1, 0}, {1, 0, 1}};
        const Corner br{x1, y1, z1, {1, 1}, {1, 1, 1}}, bl{x0, y1, z0, {0, 1}, {0, 1, 1}};
        triangle(tl, tr, br);
        triangle(tl, br, bl);
    }
    Scene done() {
        scene.mesh = std::make_shared<const facet::Mesh>(std::move(mesh));
        return scene;
    }
};

DebugMap measure(const Scene& scene, DebugView view, RenderSettings s = {}) {
    s.view = view;
    facet::Renderer renderer;
    Framebuffer frame;
    DebugMap map;
    renderer.renderDebugView(scene, s, frame, map);
    EXPECT_EQ(map.view, view);
    EXPECT_EQ(map.width, scene.camera.width);
    EXPECT_EQ(map.height, scene.camera.height);
    return map;
}

/// How many pixels of `map` hold exactly `value`.
int countEqual(const DebugMap& map, float value) {
    int n = 0;
    for (const float v : map.values) n += v == value;
    return n;
}

std::uint32_t viridisRgba(double t) {
    const glm::dvec3 c = facet::viridis(t);
    auto byte = [](double v) { return static_cast<std::uint32_t>(v * 255.0f + 0.5f); };
    return facet::packRgba(byte(static_cast<float>(c.r)), byte(static_cast<float>(c.g)),
                           byte(static_cast<float>(c.b)));
}

TEST(DebugView, NamesRoundTrip) {
    const auto names = facet::debugViewNames();
    ASSERT_EQ(names.size(), 7u);
    for (const std::string_view name : names) {
        const auto view = facet::parseDebugView(name);
        ASSERT_TRUE(view.has_value()) << name;
        EXPECT_EQ(facet::toString(*view), name);
    }
    EXPECT_EQ(facet::parseDebugView("overdraw"), DebugView::Overdraw);
    EXPECT_FALSE(facet::parseDebugView("Overdraw").has_value());
    EXPECT_EQ(RenderSettings{}.view, DebugView::None);
}

// Overlapping 40×30 and 40×40 quads: overdraw is exactly 1 where one covers the pixel (their shared
// diagonals included: the top-left rule gives each centre to one triangle), 2 in the 20×20
// overlap, nothing elsewhere.
TEST(DebugView, OverdrawCountsFragmentsPerPixel) {
    SceneBuilder b(128, 96);
    b.quad(10, 10, 50, 40, 2.0);
    b.quad(30, 20, 70, 60, 3.0);
    const DebugMap map = measure(b.done(), DebugView::Overdraw);
    EXPECT_EQ(map.at(15, 15), 1.0f);
    EXPECT_EQ(map.at(40, 30), 2.0f);
    EXPECT_EQ(map.at(65, 55), 1.0f);
    EXPECT_TRUE(std::isnan(map.at(100, 80)));
    EXPECT_EQ(countEqual(map, 2.0f), 20 * 20);
    EXPECT_EQ(countEqual(map, 1.0f), (40 * 30 - 20 * 20) + (40 * 40 - 20 * 20));
    EXPECT_EQ(map.maxValue, 2.0f);
}

// Overdraw is the coverage count of the real draw (countCoverage, facet/advanced/draw.hpp) on a
// real mesh.
TEST(DebugView, OverdrawIsTheDrawsCoverageOnAMesh) {
    facet::Result<Scene> loaded =
        facet::loadScene(std::string(FACET_ASSETS_DIR) + "/default.scene");
    ASSERT_TRUE(loaded.ok()) << loaded.error().what();
    Scene scene = std::move(loaded).value();
    scene.camera = facet::resizedCamera(scene.camera, 200, 150);
    for (const bool cull : {false, true}) {
        RenderSettings s;
        s.cullBackFaces = cull;
        const DebugMap map = measure(scene, DebugView::Overdraw, s);
        // The same clip-space input the renderer draws.
        facet::Renderer renderer;
        const facet::Mesh& mesh = *scene.mesh;
        std::vector<glm::vec4> clip;
        const glm::dmat4 m = facet::clipFromWorld(scene.camera);
        for (const glm::vec3& p : mesh.positions) clip.push_back(facet::detail::clipPoint(m, p));
        facet::DrawInput in{.clip = clip,
                            .indices = mesh.indices,
                            .nearPlane = static_cast<float>(facet::resolveNearPlane(s, mesh))};
        std::vector<std::uint16_t> counts;
        facet::countCoverage(renderer, in, s, scene.camera.width, scene.camera.height, counts);
        int drawn = 0;
        for (std::size_t i = 0; i < counts.size(); ++i) {
            if (counts[i] == 0) {
                EXPECT_TRUE(std::isnan(map.values[i])) << i;
            } else {
                EXPECT_EQ(map.values[i], counts[i]) << i;
                ++drawn;
            }
        }
        EXPECT_GT(drawn, 1000);
        EXPECT_GT(map.maxValue, 1.0f);  // the knot overlaps itself
    }
}

// The quad drawn second is behind the first: where they overlap its fragments fail (1
// failure), elsewhere every fragment passed (0); drawn the other way round, nothing fails.
// The simple shader has no depth test: nothing ever fails.
TEST(DebugView, DepthTestPassedFailedAndNeverDrawn) {
    SceneBuilder nearFirst(128, 96);
    nearFirst.quad(10, 10, 50, 40, 2.0);
    nearFirst.quad(30, 20, 70, 60, 3.0);
    const DebugMap a = measure(nearFirst.done(), DebugView::DepthTest);
    EXPECT_EQ(a.at(40, 30), 1.0f);
    EXPECT_EQ(countEqual(a, 1.0f), 20 * 20);
    EXPECT_EQ(a.at(15, 15), 0.0f);
    EXPECT_EQ(a.at(65, 55), 0.0f);
    EXPECT_TRUE(std::isnan(a.at(100, 80)));

    SceneBuilder farFirst(128, 96);
    farFirst.quad(30, 20, 70, 60, 3.0);
    farFirst.quad(10, 10, 50, 40, 2.0);
    const Scene scene = farFirst.done();
    const DebugMap b = measure(scene, DebugView::DepthTest);
    EXPECT_EQ(b.at(40, 30), 0.0f);
    EXPECT_EQ(countEqual(b, 1.0f), 0);
    EXPECT_EQ(countEqual(b, 0.0f), 40 * 30 + 40 * 40 - 20 * 20);  // the union

    RenderSettings simple;
    simple.shader = facet::ShaderKind::Simple;
    const DebugMap c = measure(nearFirst.scene, DebugView::DepthTest, simple);
    EXPECT_EQ(c.maxValue, 0.0f);
}

// Pixel centres strictly inside a triangle (none lies on an edge of this one), with its
// vertices snapped to the 1/256 px grid as the rasterizer snaps them.
int centresInside(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, int w, int h) {
    auto snap = [](glm::dvec2 p) { return glm::round(p * 256.0) / 256.0; };
    a = snap(a);
    b = snap(b);
    c = snap(c);
    auto edge = [](glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {
        return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    };
    const double sign = edge(a, b, c) > 0 ? 1.0 : -1.0;
    int n = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::dvec2 p(x + 0.5, y + 0.5);
            const double e0 = sign * edge(a, b, p), e1 = sign * edge(b, c, p),
                         e2 = sign * edge(c, a, p);
            EXPECT_TRUE(std::abs(e0) > 1e-6 && std::abs(e1) > 1e-6 && std::abs(e2) > 1e-6);
            n += e0 > 0 && e1 > 0 && e2 > 0;
        }
    return n;
}

// Each pixel shows the fragment count of the triangle that wrote it: a big triangle, and a
// small one in front of it that hides part of it.
TEST(DebugView, TriangleSizeIsThePixelsOfTheTriangleThatWroteThePixel) {
    SceneBuilder b(128, 96);
    const glm::dvec2 big[3] = {{8.0, 8.0}, {100.3, 8.0}, {8.0, 80.1}};
    const glm::dvec2 small[3] = {{20.0, 20.0}, {30.7, 20.0}, {20.0, 29.4}};
    b.triangle({big[0].x, big[0].y, 3.0}, {big[1].x, big[1].y, 3.0}, {big[2].x, big[2].y, 3.0});
    b.triangle({small[0].x, small[0].y, 2.0}, {small[1].x, small[1].y, 2.0},
               {small[2].x, small[2].y, 2.0});
    const int bigPixels = centresInside(big[0], big[1], big[2], 128, 96);
    const int smallPixels = centresInside(small[0], small[1], small[2], 128, 96);
    ASSERT_GT(bigPixels, 3000);
    ASSERT_GT(smallPixels, 40);
    const DebugMap map = measure(b.done(), DebugView::TriangleSize);
    EXPECT_EQ(map.at(10, 10), static_cast<float>(bigPixels));
    EXPECT_EQ(map.at(60, 12), static_cast<float>(bigPixels));
    EXPECT_EQ(map.at(22, 22), static_cast<float>(smallPixels));
    EXPECT_EQ(countEqual(map, static_cast<float>(smallPixels)), smallPixels);
    EXPECT_EQ(countEqual(map, static_cast<float>(bigPixels)), bigPixels - smallPixels);
    EXPECT_TRUE(std::isnan(map.at(120, 90)));
    EXPECT_EQ(map.maxValue, static_cast<float>(bigPixels));
}

// Triangles per 64×64 tile of a 128×128 frame: one in the top-left tile only, one across the
// two top tiles, one across all four; the count is the tile's, on every pixel of it, and does
// not depend on the thread count.
TEST(DebugView, BinLoadCountsTrianglesPerTile) {
    SceneBuilder b(128, 128);
    b.triangle({5, 5, 2}, {30, 5, 2}, {5, 30, 2});
    b.triangle({40, 10, 2}, {100, 10, 2}, {40, 30, 2});
    b.triangle({50, 50, 2}, {80, 50, 2}, {50, 80, 2});
    const Scene scene = b.done();
    for (const int threads : {1, 2, 3}) {
        RenderSettings s;
        s.threads = threads;
        const DebugMap map = measure(scene, DebugView::BinLoad, s);
        EXPECT_EQ(map.tileSize, 64);
        EXPECT_EQ(map.at(0, 0), 3.0f);
        EXPECT_EQ(map.at(63, 63), 3.0f);
        EXPECT_EQ(map.at(64, 0), 2.0f);
        EXPECT_EQ(map.at(127, 63), 2.0f);
        EXPECT_EQ(map.at(0, 64), 1.0f);
        EXPECT_EQ(map.at(127, 127), 1.0f);
        EXPECT_EQ(countEqual(map, 3.0f), 64 * 64);
        EXPECT_EQ(map.maxValue, 3.0f);
    }
    // No triangle in a tile: no value there.
    SceneBuilder one(128, 128);
    one.triangle({5, 5, 2}, {30, 5, 2}, {5, 30, 2});
    const DebugMap map = measure(one.done(), DebugView::BinLoad);
    EXPECT_EQ(map.at(10, 10), 1.0f);
    EXPECT_TRUE(std::isnan(map.at(100, 100)));
}

Scene texturedQuad(double side, int texels) {
    SceneBuilder b(160, 128);
    b.quad(16, 16, 16 + side, 16 + side, 2.0);
    Scene scene = b.done();
    std::vector<std::uint32_t> pixels(static_cast<std::size_t>(texels * texels),
                                      facet::packRgba(200, 100, 50));
    facet::Result<facet::Texture> t = facet::Texture::fromRgba(texels, texels, pixels, "test");
    EXPECT_TRUE(t.ok());
    scene.texture = std::make_shared<const facet::Texture>(std::move(t).value());
    return scene;
}

// A screen-parallel quad 32 px wide showing a 256-texel texture: 8 texels per pixel, level 3;
// at 64 px, level 2; at 256 px, level 0 (no minification). Whatever shader the settings name,
// the view measures the texture shader with trilinear filtering.
TEST(DebugView, TextureLodOfAQuadAtKnownMinification) {
    for (const auto& [side, level] : {std::pair{32.0, 3.0f}, {64.0, 2.0f}, {96.0, 256.0f}}) {
        const Scene scene = texturedQuad(side, 256);
        const DebugMap map = measure(scene, DebugView::TextureLod);
        EXPECT_EQ(map.mipLevels, 9);
        const float expected = side == 96.0 ? std::log2(256.0f / 96.0f) : level;
        EXPECT_NEAR(map.at(20, 20), expected, 1e-3) << side;
        EXPECT_NEAR(map.at(16 + static_cast<int>(side) - 2, 16 + static_cast<int>(side) - 2),
                    expected, 1e-3)
            << side;
        EXPECT_TRUE(std::isnan(map.at(5, 5)));
    }
    const DebugMap magnified = measure(texturedQuad(64.0, 16), DebugView::TextureLod);
    EXPECT_EQ(magnified.at(40, 40), 0.0f);  // magnified: level 0
    EXPECT_EQ(magnified.mipLevels, 5);
}

// Affine and perspective interpolation agree on a quad parallel to the screen (error 0 on every
// pixel drawn) and differ on one slanted in depth; nothing drawn, no value.
TEST(DebugView, InterpolationErrorZeroWhenParallelNonZeroWhenSlanted) {
    SceneBuilder flat(128, 96);
    flat.quad(10, 10, 110, 80, 2.0);
    const DebugMap a = measure(flat.done(), DebugView::InterpError);
    EXPECT_EQ(a.maxValue, 0.0f);
    EXPECT_EQ(countEqual(a, 0.0f), 100 * 70);
    EXPECT_TRUE(std::isnan(a.at(5, 5)));

    SceneBuilder slanted(128, 96);
    slanted.quad(10, 10, 110, 80, 1.0, 6.0);
    const DebugMap b = measure(slanted.done(), DebugView::InterpError);
    EXPECT_GT(b.maxValue, 20.0f);
    EXPECT_TRUE(std::isnan(b.at(5, 5)));
    // The interpolations agree at the quad's vertices and part most inside it.
    EXPECT_LT(b.at(10, 40) * 4.0f, b.at(60, 40));
    EXPECT_GT(b.at(60, 40), 10.0f);
}

// render() paints the map: overdraw 1 and 2 as the two ends of viridis, no fragment black, the
// legend in a black box at the bottom left; the depth test in its three colours.
TEST(DebugView, RenderPaintsTheHeatMapAndLegend) {
    SceneBuilder b(256, 200);
    b.quad(10, 10, 50, 40, 2.0);
    b.quad(30, 20, 70, 60, 3.0);
    const Scene scene = b.done();
    facet::Renderer renderer;
    Framebuffer frame;
    RenderSettings s;
    s.view = DebugView::Overdraw;
    renderer.render(scene, s, frame);
    ASSERT_EQ(frame.width, 256);
    EXPECT_EQ(frame.color[frame.index(15, 15)], viridisRgba(0.0));
    EXPECT_EQ(frame.color[frame.index(40, 30)], viridisRgba(1.0));
    EXPECT_EQ(frame.color[frame.index(200, 20)], facet::kDebugEmpty);
    // The legend: a black box whose bar holds both colours.
    int low = 0, high = 0;
    for (int y = 150; y < 200; ++y)
        for (int x = 0; x < 150; ++x) {
            low += frame.color[frame.index(x, y)] == viridisRgba(0.0);
            high += frame.color[frame.index(x, y)] == viridisRgba(1.0);
        }
    EXPECT_GT(low, 50);
    EXPECT_GT(high, 50);

    s.view = DebugView::DepthTest;
    renderer.render(scene, s, frame);
    EXPECT_EQ(frame.color[frame.index(40, 30)], facet::kDepthTestFailed);
    EXPECT_EQ(frame.color[frame.index(15, 15)], facet::kDepthTestPassed);
    EXPECT_EQ(frame.color[frame.index(200, 20)], facet::kDepthTestNever);

    // Back to the normal image: the same as a fresh renderer's.
    s.view = DebugView::None;
    renderer.render(scene, s, frame);
    Framebuffer fresh;
    facet::Renderer().render(scene, s, fresh);
    EXPECT_EQ(frame.color, fresh.color);
}

// The frame a view is drawn over is the normal image of its base settings: the instrumented
// draw leaves the real one alone.
TEST(DebugView, TheFrameUnderAViewIsTheNormalImage) {
    SceneBuilder b(128, 96);
    b.quad(10, 10, 50, 40, 2.0);
    b.quad(30, 20, 70, 60, 3.0, 1.5);
    const Scene scene = b.done();
    facet::Renderer renderer;
    Framebuffer normal, under;
    RenderSettings s;
    renderer.render(scene, s, normal);
    for (const DebugView v :
         {DebugView::Overdraw, DebugView::TriangleSize, DebugView::BinLoad, DebugView::DepthTest}) {
        s.view = v;
        DebugMap map;
        renderer.renderDebugView(scene, s, under, map);
        EXPECT_EQ(under.color, normal.color) << facet::toString(v);
        EXPECT_EQ(under.depth, normal.depth) << facet::toString(v);
    }
}

}  // namespace
