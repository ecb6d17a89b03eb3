// The Compare view and the engine's image difference behind it (error per pixel, the numbers,
// the heat map, the split composition, two renders of one view with their own interpolations),
// the renderer choice that puts the OpenGL twin beside the engine across the same divider, and
// the render worker that runs the engine on its own thread.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "compare.hpp"
#include "facet/colormap.hpp"
#include "facet/evaluation/image_diff.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "render_worker.hpp"
#include "renderer_choice.hpp"
#include "test_scenes.hpp"
#include "viewer_model.hpp"

namespace {

using namespace facet;
using namespace facet::view;

using facet::test::filledFrame;

TEST(ImageDiff, PixelErrorIsTheLargestChannelDifference) {
    EXPECT_EQ(pixelError(packRgba(10, 20, 30), packRgba(10, 20, 30)), 0);
    EXPECT_EQ(pixelError(packRgba(10, 20, 30), packRgba(13, 10, 31)), 10);
    EXPECT_EQ(pixelError(packRgba(0, 0, 0, 0), packRgba(0, 0, 0, 255)), 0);  // alpha ignored
    EXPECT_EQ(pixelError(packRgba(255, 0, 0), packRgba(0, 0, 0)), 255);
}

TEST(ImageDiff, CountsMeanMaxAndTheHeatMap) {
    Framebuffer a = filledFrame(4, 2, packRgba(100, 100, 100));
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

    const Framebuffer c = filledFrame(3, 2, 0);
    d = diffImages(a, c, &heat);
    EXPECT_FALSE(d.sameSize);
    EXPECT_EQ(d.pixels, 0u);
}

TEST(CompareView, SplitTakesEachSideFromItsFrameWithAWhiteDivider) {
    const Framebuffer a = filledFrame(10, 3, packRgba(255, 0, 0));
    const Framebuffer b = filledFrame(10, 3, packRgba(0, 0, 255));
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

TEST(CompareView, ComposingTwoRenderersIsComposingTwoInterpolations) {
    // Side by side, the engine's frame and the twin's go through the very code the Compare
    // view uses: the split keeps each side's pixels, the heat map marks where they differ.
    const Framebuffer cpu = filledFrame(8, 2, packRgba(10, 20, 30));
    Framebuffer gl = cpu;
    gl.color[gl.index(6, 1)] = packRgba(10, 21, 30);  // one step apart, on the right side
    Framebuffer shown;
    ImageDiff d = composeSides(cpu, gl, CompareDisplay::Split, 0.25, 0, shown);
    EXPECT_EQ(d.pixelsDiffering, 1u);
    EXPECT_EQ(d.maxError, 1);
    EXPECT_EQ(shown.color[shown.index(1, 0)], cpu.color[0]);
    EXPECT_EQ(shown.color[shown.index(2, 0)], packRgba(255, 255, 255));
    EXPECT_EQ(shown.color[shown.index(6, 1)], gl.color[gl.index(6, 1)]);
    d = composeSides(cpu, gl, CompareDisplay::Difference, 0.25, 0, shown);
    EXPECT_EQ(d.pixelsDiffering, 1u);
    for (std::size_t i = 0; i < shown.color.size(); ++i)
        EXPECT_EQ(shown.color[i] == packRgba(0, 0, 0), i != gl.index(6, 1)) << i;

    CompareView c;
    c.leftFrame = cpu;
    c.rightFrame = gl;
    CompareSettings quarter;
    quarter.divider = 0.25;
    const Framebuffer& composed = c.compose(quarter);
    composeSides(cpu, gl, CompareDisplay::Split, 0.25, 0, shown);
    EXPECT_TRUE(composed.color == shown.color);
    EXPECT_EQ(c.diff.pixelsDiffering, 1u);
}

TEST(RendererChoice, NamesLabelsAndTheGKeyCycle) {
    EXPECT_EQ(rendererNames(),
              (std::vector<std::string_view>{"cpu", "gl", "split", "lab", "lab-split"}));
    for (const std::string_view name : rendererNames())
        EXPECT_EQ(toString(parseRenderer(name).value()), name);
    EXPECT_FALSE(parseRenderer("GL").has_value());
    EXPECT_FALSE(parseRenderer("").has_value());
    EXPECT_EQ(rendererLabel(RendererChoice::Cpu), "CPU engine");
    EXPECT_EQ(rendererLabel(RendererChoice::OpenGl), "OpenGL twin");
    EXPECT_EQ(rendererLabel(RendererChoice::Split), "CPU | OpenGL side by side");
    EXPECT_EQ(rendererLabel(RendererChoice::Lab), "Your pipeline");
    EXPECT_EQ(rendererLabel(RendererChoice::LabSplit), "Compare your pipeline | facet");
    // G cycles the engine and the OpenGL twin; from the lab's choices it goes back to the engine.
    EXPECT_EQ(nextRenderer(RendererChoice::Lab), RendererChoice::Cpu);
    EXPECT_EQ(nextRenderer(RendererChoice::LabSplit), RendererChoice::Cpu);
    RendererChoice c = RendererChoice::Cpu;
    for (const RendererChoice expected :
         {RendererChoice::OpenGl, RendererChoice::Split, RendererChoice::Cpu}) {
        c = nextRenderer(c);
        EXPECT_EQ(c, expected);
    }
}

TEST(RendererChoice, WhatAFrameRunsForEachChoice) {
    const FramePlan cpu = planFrame(RendererChoice::Cpu, false);
    EXPECT_TRUE(cpu.engine && !cpu.engineCompare && !cpu.twin && !cpu.sideBySide);
    EXPECT_FALSE(cpu.twoSides());
    const FramePlan compare = planFrame(RendererChoice::Cpu, true);
    EXPECT_TRUE(compare.engine && compare.engineCompare && !compare.twin && compare.twoSides());
    for (const bool compareOn : {false, true}) {
        // The Compare checkbox only counts with the CPU engine.
        const FramePlan gl = planFrame(RendererChoice::OpenGl, compareOn);
        EXPECT_TRUE(!gl.engine && !gl.engineCompare && gl.twin && !gl.sideBySide);
        EXPECT_FALSE(gl.twoSides());
        const FramePlan split = planFrame(RendererChoice::Split, compareOn);
        EXPECT_TRUE(split.engine && !split.engineCompare && split.twin && split.sideBySide);
        EXPECT_TRUE(split.twoSides());
        // Your pipeline is drawn in the twin's place: alone, or beside the engine.
        const FramePlan lab = planFrame(RendererChoice::Lab, compareOn);
        EXPECT_TRUE(!lab.engine && !lab.engineCompare && lab.twin && !lab.sideBySide);
        const FramePlan labSplit = planFrame(RendererChoice::LabSplit, compareOn);
        EXPECT_TRUE(labSplit.engine && !labSplit.engineCompare && labSplit.twin &&
                    labSplit.sideBySide);
        EXPECT_TRUE(isLab(RendererChoice::Lab) && isLab(RendererChoice::LabSplit));
        EXPECT_FALSE(isLab(RendererChoice::Split) || isLab(RendererChoice::Cpu));
    }
}

TEST(RendererChoice, TheTwinAndTheInterpolationCompareExcludeEachOther) {
    ViewerModel m;
    CompareSettings c;
    EXPECT_EQ(m.rendererChoice, RendererChoice::Cpu);
    setCompare(true, m.rendererChoice, c);
    EXPECT_TRUE(c.enabled);
    selectRenderer(m.rendererChoice, RendererChoice::Split, c);  // the divider is the twin's now
    EXPECT_EQ(m.rendererChoice, RendererChoice::Split);
    EXPECT_FALSE(c.enabled);
    setCompare(true, m.rendererChoice, c);  // and back: Compare takes the CPU engine
    EXPECT_EQ(m.rendererChoice, RendererChoice::Cpu);
    EXPECT_TRUE(c.enabled);
    selectRenderer(m.rendererChoice, RendererChoice::Cpu, c);  // the engine keeps Compare
    EXPECT_TRUE(c.enabled);
    selectRenderer(m.rendererChoice, RendererChoice::OpenGl, c);
    EXPECT_FALSE(c.enabled);
    setCompare(false, m.rendererChoice, c);  // off leaves the choice alone
    EXPECT_EQ(m.rendererChoice, RendererChoice::OpenGl);
}

TEST(CompareView, RendersTheSameViewWithTwoInterpolations) {
    ViewerModel m;
    ASSERT_TRUE(m.load(std::string(FACET_ASSETS_DIR) + "/default.scene"));
    m.prepareFrame(640, 360);
    CompareSettings compare;
    compare.enabled = true;
    CompareView c;
    const Framebuffer& shown = c.render(m.scene, m.settings, compare);

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
    EXPECT_EQ(c.leftStats.trianglesIn, m.scene.mesh->triangleCount());
    // The numbers the panel shows are over the pixels either side covers (a mode of
    // diffImages), counted here from the two depth planes as the panel counted them before.
    std::size_t covered = 0;
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < affine.color.size(); ++i) {
        const int e = pixelError(affine.color[i], perspective.color[i]);
        sum += static_cast<std::uint64_t>(e);
        if (e > 0 || affine.depth[i] != kEmptyDepth || perspective.depth[i] != kEmptyDepth)
            ++covered;
    }
    ASSERT_GT(covered, 0u);
    ASSERT_LT(covered, affine.color.size());  // background around the knot: the counts differ
    EXPECT_EQ(c.diff.pixels, covered);
    EXPECT_DOUBLE_EQ(c.diff.meanError, static_cast<double>(sum) / static_cast<double>(covered));
    EXPECT_GT(c.diff.meanError, d.meanError);  // d: over the whole frame

    ASSERT_EQ(shown.width, 640);
    for (int y = 0; y < shown.height; y += 7) {
        EXPECT_EQ(shown.color[shown.index(100, y)], affine.color[affine.index(100, y)]);
        EXPECT_EQ(shown.color[shown.index(500, y)], perspective.color[perspective.index(500, y)]);
        EXPECT_EQ(shown.color[shown.index(320, y)], packRgba(255, 255, 255));
    }

    compare.display = CompareDisplay::Difference;
    const Framebuffer& heat = c.compose(compare);
    ASSERT_EQ(heat.width, 640);
    for (std::size_t i = 0; i < heat.color.size(); i += 97)
        EXPECT_EQ(heat.color[i] == packRgba(0, 0, 0), affine.color[i] == perspective.color[i]);

    compare.left = {Interp::Subdivided, 4};
    compare.right = {Interp::Subdivided, 4};
    c.render(m.scene, m.settings, compare);
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
    ASSERT_TRUE(m.load(std::string(FACET_ASSETS_DIR) + "/default.scene"));
    m.settings.lighting = Lighting::Gouraud;
    m.prepareFrame(640, 360);
    m.render();
    RenderWorker worker;
    CompareSettings compare;
    Framebuffer shown;
    EXPECT_EQ(worker.wait(shown).renderMs, 0.0);  // no job yet: nothing handed out
    EXPECT_EQ(shown.width, 0);

    worker.submit(m.scene, m.settings, compare);
    const RenderResult& r = worker.wait(shown);
    EXPECT_TRUE(shown.color == m.frame.color);
    EXPECT_EQ(r.stats.trianglesIn, m.scene.mesh->triangleCount());
    EXPECT_FALSE(r.compared);

    // Edits after a submit do not disturb the job; the next job sees them.
    m.scene.lighting.material.ks = 0.0;
    worker.submit(m.scene, m.settings, compare);
    m.scene.lighting.material.ks = 2.0;
    worker.wait(shown);
    m.scene.lighting.material.ks = 0.0;
    m.render();
    EXPECT_TRUE(shown.color == m.frame.color);
    worker.wait(shown);  // again, no new job: the picture stays
    EXPECT_TRUE(shown.color == m.frame.color);

    compare.enabled = true;
    worker.submit(m.scene, m.settings, compare);
    const RenderResult& c = worker.wait(shown);
    EXPECT_TRUE(c.compared);
    CompareView direct;
    const Framebuffer& expected = direct.render(m.scene, m.settings, compare);
    EXPECT_TRUE(shown.color == expected.color);
    EXPECT_EQ(c.diff.pixelsDiffering, direct.diff.pixelsDiffering);

    ASSERT_TRUE(m.load(std::string(FACET_TEST_DATA) + "/scene_valid.scene"));
    m.prepareFrame(320, 240);
    m.render();
    compare.enabled = false;
    worker.submit(m.scene, m.settings, compare);
    worker.wait(shown);
    EXPECT_EQ(shown.width, 320);
    EXPECT_TRUE(shown.color == m.frame.color);
}

}  // namespace
