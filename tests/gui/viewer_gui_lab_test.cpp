// Your pipeline (the lab kit, built with the solution) inside the real viewer under Xvfb: alone
// it draws what the engine draws within 1 step; "Compare your pipeline | facet" puts it left of
// the divider and the engine's picture, bit for bit, right of it; the difference is black
// nearly everywhere.

#include <cstddef>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "facet/evaluation/image_diff.hpp"
#include "facet/framebuffer.hpp"
#include "viewer_gui_support.hpp"

namespace {

using namespace facet;
using namespace viewer_gui;

/// Columns [x0, x1): the lab's picture against the engine's. Coverage may differ only on
/// edges (the course's inside test has no fill rule, docs/lab.md), colours by 1 step.
void expectLabAgrees(const Framebuffer& engine, const Framebuffer& lab, int x0, int x1) {
    ASSERT_EQ(engine.width, lab.width);
    ASSERT_EQ(engine.height, lab.height);
    const std::uint32_t background = rgbaFromHex(RenderSettings{}.background) & 0xFFFFFFu;
    std::size_t covered = 0, coverageDiffers = 0;
    DiffHistogram both;
    for (int y = 0; y < engine.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::uint32_t pa = engine.color[engine.index(x, y)];
            const std::uint32_t pb = lab.color[lab.index(x, y)];
            const bool ca = (pa & 0xFFFFFFu) != background, cb = (pb & 0xFFFFFFu) != background;
            covered += ca;
            if (ca != cb)
                ++coverageDiffers;
            else if (ca)
                both.add(pixelError(pa, pb));
        }
    EXPECT_GT(covered, static_cast<std::size_t>(0.1 * (x1 - x0) * engine.height));
    EXPECT_LE(static_cast<double>(coverageDiffers), 1e-3 * static_cast<double>(covered));
    EXPECT_LE(both.shareAbove(1), 1e-3);
}

TEST_F(ViewerGui, YourPipelineAloneDrawsWhatTheEngineDraws) {
    REQUIRE_XVFB();
    const Outcome r = viewer(
        "--renderer lab --frames 3 --size 1660x720 --no-vsync --screenshot lab.png "
        "--state state.txt");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("renderer"), "lab");
    EXPECT_EQ(state.at("engine_frames"), "0");  // your pipeline alone: the engine sat out
    EXPECT_EQ(state.at("twin_frames"), "3");
    const Framebuffer lab = readPng(path("lab.png"));
    expectLabAgrees(cliRender("cpu.png"), lab, 0, 1280);
}

TEST_F(ViewerGui, CompareYourPipelineWithFacetSideBySideAndAsADifference) {
    REQUIRE_XVFB();
    const Outcome r = viewer(
        "--renderer lab-split --frames 3 --size 1660x720 --no-vsync --screenshot split.png "
        "--state state.txt");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("renderer"), "lab-split");
    EXPECT_EQ(state.at("engine_frames"), "3");
    EXPECT_EQ(state.at("twin_frames"), "3");
    const Framebuffer shown = readPng(path("split.png"));
    const Framebuffer cpu = cliRender("cpu.png");
    ASSERT_EQ(shown.width, 1280);
    expectLabAgrees(cpu, shown, 0, 640);                            // yours, left
    EXPECT_EQ(differingShare(shown, cpu, 641, 0, 1280, 720), 0.0);  // facet's, right
    for (int y = 0; y < 720; y += 10) EXPECT_EQ(shown.color[shown.index(640, y)], 0xFFFFFFFFu);

    const Outcome d = viewer(
        "--renderer lab-split --difference --frames 3 --size 1660x720 --no-vsync "
        "--screenshot diff.png");
    ASSERT_EQ(d.exitCode, 0) << d.out;
    const Framebuffer diff = readPng(path("diff.png"));
    std::size_t black = 0;
    for (const std::uint32_t p : diff.color) black += (p & 0xFFFFFFu) == 0;
    EXPECT_GT(static_cast<double>(black), 0.99 * static_cast<double>(diff.color.size()));
}

}  // namespace
