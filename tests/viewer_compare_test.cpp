// The Compare view and the engine's image difference behind it (error per pixel, the numbers,
// the heat map, the split composition, two renders of one view with their own interpolations),
// and the render worker that runs the engine on its own thread.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "compare.hpp"
#include "facet/colormap.hpp"
#include "facet/image_diff.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "render_worker.hpp"
#include "viewer_model.hpp"

namespace {

using namespace facet;
using namespace facet::view;

Framebuffer filled(int w, int h, std::uint32_t rgba) {
    Framebuffer f;
    f.resize(w, h);
    f.clear(rgba);
    return f;
}

TEST(ImageDiff, PixelErrorIsTheLargestChannelDifference) {
    EXPECT_EQ(pixelError(packRgba(10, 20, 30), packRgba(10, 20, 30)), 0);
    EXPECT_EQ(pixelError(packRgba(10, 20, 30), packRgba(13, 10, 31)), 10);
    EXPECT_EQ(pixelError(packRgba(0, 0, 0, 0), packRgba(0, 0, 0, 255)), 0);  // alpha ignored
    EXPECT_EQ(pixelError(packRgba(255, 0, 0), packRgba(0, 0, 0)), 255);
}

TEST(ImageDiff, CountsMeanMaxAndTheHeatMap) {
    Framebuffer a = filled(4, 2, packRgba(100, 100, 100));
    Framebuffer b = a;
    Framebuffer heat;
    ImageDiff d = diffImages(a, b, &heat);
    EXPECT_TRUE(d.sameSize);
    EXPECT_EQ(d.pixels, 8u);
    EXPECT_EQ(d.pixelsDiffering, 0u);
    EXPECT_EQ(d.maxError, 0);
    EXPECT_EQ(d.meanError, 0.0);
    for (std::uint32_t p : heat.color) EXPECT_EQ(p, packRgba(0, 0, 0));  // equal: black

    b.color[3] = packRgba(100, 140, 100);  // error 40
    b.color[5] = packRgba(90, 100, 100);   // error 10
    d = diffImages(a, b, &heat);
    EXPECT_EQ(d.pixelsDiffering, 2u);
    EXPECT_EQ(d.maxError, 40);
    EXPECT_DOUBLE_EQ(d.meanError, 50.0 / 8.0);
    ASSERT_EQ(heat.width, 4);
    ASSERT_EQ(heat.height, 2);
    const glm::dvec3 top = viridis(1.0);
    EXPECT_EQ(heat.color[3], packRgba(static_cast<std::uint32_t>(std::lround(top.r * 255)),
                                      static_cast<std::uint32_t>(std::lround(top.g * 255)),
                                      static_cast<std::uint32_t>(std::lround(top.b * 255))));
    EXPECT_NE(heat.color[5], packRgba(0, 0, 0));
    EXPECT_NE(heat.color[5], heat.color[3]);
    EXPECT_EQ(heat.color[0], packRgba(0, 0, 0));
    // A fixed scale: error 40 of 80 is mid-scale, no longer the brightest colour.
    diffImages(a, b, &heat, 80);
    EXPECT_NE(heat.color[3], packRgba(253, 231, 37));

    const Framebuffer c = filled(3, 2, 0);
    d = diffImages(a, c, &heat);
    EXPECT_FALSE(d.sameSize);
    EXPECT_EQ(d.pixels, 0u);
}

TEST(CompareView, SplitTakesEachSideFromItsFrameWithAWhiteDivider) {
    const Framebuffer a = filled(10, 3, packRgba(255, 0, 0));
    const Framebuffer b = filled(10, 3, packRgba(0, 0, 255));
    Framebuffer out;
    composeSplit(a, b, 4, out);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 10; ++x) {
            const std::uint32_t p = out.color[out.index(x, y)];
            if (x < 4)
                EXPECT_EQ(p, a.color[0]) << x;
            else if (x == 4)
                EXPECT_EQ(p, packRgba(255, 255, 255));
            else
                EXPECT_EQ(p, b.color[0]) << x;
        }
    composeSplit(a, b, 10, out);  // all left, no line
    EXPECT_EQ(out.color[9], a.color[0]);
    composeSplit(a, b, 0, out);  // line at column 0, the rest right
    EXPECT_EQ(out.color[1], b.color[0]);
    EXPECT_EQ(dividerColumn(0.5, 1280), 640);
    EXPECT_EQ(dividerColumn(-3.0, 1280), 0);
    EXPECT_EQ(dividerColumn(7.0, 1280), 1280);
    EXPECT_EQ(dividerColumn(NAN, 1280), 640);
}

TEST(CompareView, RendersTheSameViewWithTwoInterpolations) {
    ViewerModel m;
    ASSERT_FALSE(m.load(std::string(FACET_ASSETS_DIR) + "/default.scene"));
    m.prepareFrame(640, 360);
    CompareView c;
    c.enabled = true;
    const Framebuffer& shown = c.render(m.scene, m.settings);

    // Each side is exactly what the engine draws with that interpolation alone.
    RenderSettings s = m.settings;
    Renderer r;
    Framebuffer affine, perspective;
    s.interp = Interp::Affine;
    r.render(m.scene, s, affine);
    s.interp = Interp::Perspective;
    r.render(m.scene, s, perspective);
    EXPECT_TRUE(c.leftFrame.color == affine.color);
    EXPECT_TRUE(c.rightFrame.color == perspective.color);
    const ImageDiff d = diffImages(affine, perspective);
    EXPECT_EQ(c.diff.pixelsDiffering, d.pixelsDiffering);
    EXPECT_EQ(c.diff.maxError, d.maxError);
    EXPECT_EQ(c.leftStats.trianglesIn, m.scene.mesh.triangleCount());

    ASSERT_EQ(shown.width, 640);
    for (int y = 0; y < shown.height; y += 7) {
        EXPECT_EQ(shown.color[shown.index(100, y)], affine.color[affine.index(100, y)]);
        EXPECT_EQ(shown.color[shown.index(500, y)], perspective.color[perspective.index(500, y)]);
        EXPECT_EQ(shown.color[shown.index(320, y)], packRgba(255, 255, 255));
    }

    c.display = CompareDisplay::Difference;
    const Framebuffer& heat = c.compose();
    ASSERT_EQ(heat.width, 640);
    for (std::size_t i = 0; i < heat.color.size(); i += 97)
        EXPECT_EQ(heat.color[i] == packRgba(0, 0, 0), affine.color[i] == perspective.color[i]);

    c.left = {Interp::Subdivided, 4};
    c.right = {Interp::Subdivided, 4};
    c.render(m.scene, m.settings);
    EXPECT_EQ(c.diff.pixelsDiffering, 0u);
}

}  // namespace

namespace {

using namespace facet;
using namespace facet::view;

// The engine's thread: what it hands back is exactly what the engine draws for the state
// submitted, edits reach the next job, and a new scene's mesh replaces the old one.
TEST(RenderWorker, HandsBackTheEngineFrameOfTheSubmittedState) {
    ViewerModel m;
    ASSERT_FALSE(m.load(std::string(FACET_ASSETS_DIR) + "/default.scene"));
    m.settings.lighting = Lighting::Gouraud;
    m.prepareFrame(640, 360);
    m.render();
    RenderWorker worker;
    CompareView compare;
    Framebuffer shown;
    EXPECT_EQ(worker.wait(shown).renderMs, 0.0);  // no job yet: nothing handed out
    EXPECT_EQ(shown.width, 0);

    worker.submit(m.scene, m.sceneVersion, m.settings, compare);
    const RenderResult& r = worker.wait(shown);
    EXPECT_TRUE(shown.color == m.frame.color);
    EXPECT_EQ(r.stats.trianglesIn, m.scene.mesh.triangleCount());
    EXPECT_FALSE(r.compared);

    // Edits after a submit do not disturb the job; the next job sees them.
    m.scene.material.ks = 0.0;
    worker.submit(m.scene, m.sceneVersion, m.settings, compare);
    m.scene.material.ks = 2.0;
    worker.wait(shown);
    m.scene.material.ks = 0.0;
    m.render();
    EXPECT_TRUE(shown.color == m.frame.color);
    worker.wait(shown);  // again, no new job: the picture stays
    EXPECT_TRUE(shown.color == m.frame.color);

    compare.enabled = true;
    worker.submit(m.scene, m.sceneVersion, m.settings, compare);
    const RenderResult& c = worker.wait(shown);
    EXPECT_TRUE(c.compared);
    CompareView direct;
    direct.enabled = true;
    const Framebuffer& expected = direct.render(m.scene, m.settings);
    EXPECT_TRUE(shown.color == expected.color);
    EXPECT_EQ(c.diff.pixelsDiffering, direct.diff.pixelsDiffering);

    ASSERT_FALSE(m.load(std::string(FACET_TEST_DATA) + "/scene_valid.scene"));
    m.prepareFrame(320, 240);
    m.render();
    compare.enabled = false;
    worker.submit(m.scene, m.sceneVersion, m.settings, compare);
    worker.wait(shown);
    EXPECT_EQ(shown.width, 320);
    EXPECT_TRUE(shown.color == m.frame.color);
}

}  // namespace
