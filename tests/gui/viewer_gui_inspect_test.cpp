// The pixel inspector in a real window under Xvfb, driven by xdotool: Shift + left click on the
// image inspects the pixel under the pointer (and does not orbit), the window opens beside it
// inside the image area, its final colour is the engine frame's pixel, and the marker is drawn
// on that pixel.

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "viewer_gui_support.hpp"

namespace {

using namespace facet;
using namespace viewer_gui;
using facet::view::Rect;

std::string hexOf(std::uint32_t p) {
    char buf[8];
    std::snprintf(buf, sizeof buf, "#%02X%02X%02X", p & 0xFFu, (p >> 8) & 0xFFu, (p >> 16) & 0xFFu);
    return buf;
}

TEST_F(ViewerGui, ShiftClickInspectsThePixelUnderThePointer) {
    REQUIRE_XDOTOOL();
    // The 1280×720 frame sits at x = kFrameX, 1:1: window point (kFrameX + 700, 330) is frame
    // pixel (700, 330), on the default scene's model.
    const int px = 700, py = 330;
    const Outcome r =
        driveSteps("shiftclick " + std::to_string(kFrameX + px) + " " + std::to_string(py),
                   "--size " + kWindow1280 + " --window-shot window.png");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    std::ifstream log(path("viewer.log"));
    std::stringstream printedStream;
    printedStream << log.rdbuf();
    const std::string printed = printedStream.str();
    EXPECT_NE(printed.find("inspected pixel 700 330"), std::string::npos) << printed;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "0") << "the click orbited the camera";
    EXPECT_EQ(state.at("inspector"), "1 1");
    EXPECT_EQ(state.at("inspector_pixel"), "700 330");
    // Some triangle drew there, so the history is not empty.
    std::istringstream entries(state.at("inspector_entries"));
    int all = 0, covered = 0, passed = 0;
    entries >> all >> covered >> passed;
    EXPECT_GE(covered, 1);
    EXPECT_GE(passed, 1);
    // Its final colour is the engine frame's pixel.
    const Framebuffer frame = readPng(path("frame.png"));
    ASSERT_EQ(frame.width, 1280);
    EXPECT_EQ(state.at("inspector_final"), hexOf(frame.color[frame.index(px, py)]));

    // The window sits inside the image area, on the half away from the pixel (left of it).
    const Rect window = rectOf(state, "window_inspector");
    const Rect image = rectOf(state, "image_area");
    EXPECT_GT(window.w, 300);
    EXPECT_GE(window.x, image.x);
    EXPECT_LE(window.x + window.w, image.x + image.w);
    EXPECT_LE(window.x + window.w, kFrameX + px);
    // The marker: yellow pixels around the inspected one in the window shot that the engine's
    // frame does not have there.
    const Framebuffer shot = readPng(path("window.png"));
    ASSERT_GT(shot.width, kFrameX + px + 20);
    auto yellowish = [](std::uint32_t c) {
        const unsigned red = c & 0xFFu, green = (c >> 8) & 0xFFu, blue = (c >> 16) & 0xFFu;
        return red > 150 && green > 130 && blue < 90;
    };
    int yellow = 0;
    for (int y = py - 20; y <= py + 20; ++y)
        for (int x = px - 20; x <= px + 20; ++x)
            yellow += yellowish(shot.color[shot.index(x + kFrameX, y)]) &&
                      !yellowish(frame.color[frame.index(x, y)]);
    EXPECT_GT(yellow, 20);
}

TEST_F(ViewerGui, APlainClickStillOrbitsAndInspectsNothing) {
    REQUIRE_XDOTOOL();
    const Outcome r = driveSteps("drag 1 1000 360 120 40 6", "--size " + kWindow1280);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "1");
    EXPECT_EQ(state.at("inspector"), "0 0");
}

}  // namespace
