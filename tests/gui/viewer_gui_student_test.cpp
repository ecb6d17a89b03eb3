// The viewer as a first-time student meets it, in real windows (xvfb-run, xdotool): Esc never
// loses the work, Ctrl+Q asks once before throwing changes away, a dragged light stays on the
// side the camera sees, a saved scene reopens as it looked, a Z-up model stands upright, and a
// small window keeps most of its area for the picture.

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "shared_data.hpp"
#include "viewer_gui_support.hpp"

namespace {

using namespace facet;
using namespace viewer_gui;
using facet::view::Rect;

// The inspector open, Esc closes it; the viewer keeps running (the key after it still acts).
TEST_F(ViewerGui, EscClosesTheInspectorAndTheViewerKeepsRunning) {
    REQUIRE_XDOTOOL();
    const Outcome r = driveSteps("shiftclick 1020 360; key Escape; pause 0.3; key 2; pause 0.3",
                                 "--size " + kWindow1280);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("inspector").substr(0, 3), "0 1");  // closed, after one inspection
    EXPECT_EQ(state.at("mode"), "wireframe");
    EXPECT_EQ(state.count("window_inspector"), 0u);
}

// A combo's drop-down open, Esc closes the drop-down only (nothing chosen, still running); Esc
// with nothing open does nothing.
TEST_F(ViewerGui, EscClosesAComboDropDownAndNeverQuits) {
    REQUIRE_XDOTOOL();
    const Outcome r = driveSteps(
        "at 110 114; click 1; pause 0.4; key Escape; key Escape; key Escape; at 1000 400; key 2",
        "--size " + kWindow1280);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("renderer"), "cpu");
    EXPECT_EQ(state.at("mode"), "wireframe");
}

// Ctrl+Q with nothing changed quits at once.
TEST_F(ViewerGui, CtrlQQuitsAtOnceWithoutChanges) {
    REQUIRE_XDOTOOL();
    const Outcome r = driveSteps("at 1000 400; key ctrl+q; pause 1", "--size " + kWindow1280,
                                 /*selfQuit=*/true);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(r.out.find("still running"), std::string::npos) << r.out;
    EXPECT_EQ(readState(path("state.txt")).at("unsaved"), "0");
}

// After an orbit, Ctrl+Q asks (the viewer still runs, the question shows); Ctrl+Q again quits.
TEST_F(ViewerGui, CtrlQAfterAnOrbitAsksOnceBeforeQuitting) {
    REQUIRE_XDOTOOL();
    {
        const Outcome r =
            driveSteps("drag 1 1000 400 120 40 5; key ctrl+q; pause 0.5", "--size " + kWindow1280);
        ASSERT_EQ(r.exitCode, 0) << r.out;
        const auto state = readState(path("state.txt"));
        EXPECT_EQ(state.at("unsaved"), "1");
        EXPECT_EQ(state.count("window_quit_question"), 1u);
    }
    {
        const Outcome r =
            driveSteps("drag 1 1000 400 120 40 5; key ctrl+q; pause 0.5; key ctrl+q; pause 1",
                       "--size " + kWindow1280, /*selfQuit=*/true);
        ASSERT_EQ(r.exitCode, 0) << r.out;
        EXPECT_EQ(r.out.find("still running"), std::string::npos) << r.out;
    }
    {  // Esc cancels the question, and the viewer keeps running.
        const Outcome r = driveSteps(
            "drag 1 1000 400 120 40 5; key ctrl+q; pause 0.5; key Escape; pause 0.3; key 2",
            "--size " + kWindow1280);
        ASSERT_EQ(r.exitCode, 0) << r.out;
        const auto state = readState(path("state.txt"));
        EXPECT_EQ(state.count("window_quit_question"), 0u);
        EXPECT_EQ(state.at("mode"), "wireframe");
    }
}

const std::string kShared = facet::test::sharedData("models/");

glm::dvec3 vec3Of(const std::map<std::string, std::string>& state, const std::string& key) {
    std::istringstream in(state.at(key));
    glm::dvec3 v(0.0);
    in >> v.x >> v.y >> v.z;
    return v;
}

// The bare cow: the light starts farther from the cow than the camera. Dragging its
// marker across the cow's centre keeps it on the camera's side (n·l > 0 at the centre, for the
// normal facing the camera); the marker starts in the frame or says it is off screen.
TEST_F(ViewerGui, ADraggedLightStaysOnTheCamerasSide) {
    REQUIRE_XDOTOOL();
    const std::string cow = kShared + "cow.obj";
    REQUIRE_SHARED_DATA(cow);
    const std::string args = "--size " + kWindow1280 + " " + cow;
    Outcome r = driveSteps("pause 0.3", args);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    auto state = readState(path("state.txt"));
    std::istringstream marker(state.at("light_marker"));
    int shown = 0, inFrame = 0;
    double mx = 0.0, my = 0.0;
    marker >> shown >> mx >> my >> inFrame;
    ASSERT_EQ(shown, 1) << state.at("light_marker");
    if (!inFrame) {
        EXPECT_NE(state.at("light_marker_note"), "");
    }
    // From the marker across the image's centre to as far on the other side.
    const Rect view = rectOf(state, "view");
    const double cx = view.x + 0.5 * view.w, cy = view.y + 0.5 * view.h;
    const int x0 = static_cast<int>(mx), y0 = static_cast<int>(my);
    const int dx = static_cast<int>(1.3 * (cx - mx)), dy = static_cast<int>(1.3 * (cy - my));
    r = driveSteps("drag 1 " + std::to_string(x0) + " " + std::to_string(y0) + " " +
                       std::to_string(dx) + " " + std::to_string(dy) + " 12",
                   args);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "0");  // the light moved, not the camera
    std::istringstream lightIn(state.at("light"));
    glm::dvec4 light(0.0);
    lightIn >> light.x >> light.y >> light.z >> light.w;
    ASSERT_NE(light.w, 0.0);
    const glm::dvec3 target = vec3Of(state, "target");
    const glm::dvec3 n = glm::normalize(vec3Of(state, "eye") - target);
    const glm::dvec3 l = glm::normalize(glm::dvec3(light) / light.w - target);
    EXPECT_GT(glm::dot(n, l), 0.0) << state.at("light");
}

// A click right after a long move (in one go, as at a few frames a second) does not turn the
// view: the pointer's travel before the press is no drag.
TEST_F(ViewerGui, APressAfterAMoveDoesNotJump) {
    REQUIRE_XDOTOOL();
    const Outcome r = driveSteps("at 500 100; pause 0.5; press 1400 650; press 520 120",
                                 "--size " + kWindow1280 + " --serial");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "0")
        << "yaw " << state.at("yaw") << " pitch " << state.at("pitch");
}

// Orbit a bare cow and Ctrl+S: the first save asks where (the cow's folder proposed), the
// notice says where it went, and the saved scene reopens with the same picture (not a white
// silhouette: both open lit, by spec §9) at the bare mesh's own size.
TEST_F(ViewerGui, ASavedBareMeshSceneReopensWithTheSamePicture) {
    REQUIRE_XDOTOOL();
    const std::string cow = kShared + "cow.obj";
    REQUIRE_SHARED_DATA(cow);
    Outcome r = drive("save", "--size " + kWindow1280 + " " + cow,
                      "FACET_DRIVE_SAVE_AS=" + path("cow.scene"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    ASSERT_TRUE(fs::exists(path("cow.scene"))) << r.out;
    auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "1");
    EXPECT_EQ(state.at("notice"), "Saved to " + path("cow.scene"));
    EXPECT_EQ(state.at("lighting"), "gouraud");
    const Framebuffer before = readPng(path("frame.png"));
    fs::rename(path("frame.png"), path("before.png"));

    r = driveSteps("pause 0.3", "--size " + kWindow1280 + " " + path("cow.scene"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    state = readState(path("state.txt"));
    EXPECT_EQ(state.at("lighting"), "gouraud");
    EXPECT_EQ(state.at("size"), "1280 720");
    const Framebuffer after = readPng(path("frame.png"));
    ASSERT_EQ(before.width, after.width);
    ASSERT_EQ(before.height, after.height);
    EXPECT_LT(differingShare(before, after, 0, 0, after.width, after.height), 0.001);
    // The picture is lit, not one flat colour: many distinct pixel values on the cow.
    std::set<std::uint32_t> colours(after.color.begin(), after.color.end());
    EXPECT_GT(colours.size(), 50u);
}

/// Width over height of the pixels that differ from the background (the model's silhouette).
double silhouetteAspect(const Framebuffer& f) {
    const std::uint32_t background = f.color[0];
    int x0 = f.width, y0 = f.height, x1 = -1, y1 = -1;
    for (int y = 0; y < f.height; ++y)
        for (int x = 0; x < f.width; ++x)
            if (f.color[f.index(x, y)] != background) {
                x0 = std::min(x0, x);
                x1 = std::max(x1, x);
                y0 = std::min(y0, y);
                y1 = std::max(y1, y);
            }
    if (x1 < x0 || y1 < y0) return NAN;
    return static_cast<double>(x1 - x0 + 1) / static_cast<double>(y1 - y0 + 1);
}

// Nefertiti is a Z-up scan: --up z shows the bust upright (taller than wide), the default Y
// shows it lying (wider than tall); the state's up vector (the camera's y hint) is −Z.
TEST_F(ViewerGui, UpZShowsNefertitiUpright) {
    REQUIRE_XVFB();
    const std::string nefertiti = kShared + "nefertiti.obj";
    REQUIRE_SHARED_DATA(nefertiti);
    for (const char* up : {"z", "y"}) {
        const Outcome r =
            viewer("--frames 3 --no-vsync --size " + kWindow1280 +
                   " --state state.txt --screenshot frame.png --up " + up + " " + nefertiti);
        ASSERT_EQ(r.exitCode, 0) << r.out;
        const double aspect = silhouetteAspect(readPng(path("frame.png")));
        const auto state = readState(path("state.txt"));
        if (std::string(up) == "z") {
            EXPECT_LT(aspect, 0.8) << "not upright";
            const glm::dvec3 hint = vec3Of(state, "up");
            EXPECT_NEAR(hint.z, -1.0, 1e-9);
        } else {
            EXPECT_GT(aspect, 1.0) << "the default Y should show it lying";
        }
    }
    const Outcome bad = viewer("--frames 1 --up w " + nefertiti);
    EXPECT_EQ(bad.exitCode, 2) << bad.out;
    EXPECT_NE(bad.out.find("--up w"), std::string::npos) << bad.out;
}

// At 800x600 the side bar narrows itself: the frame keeps at least 60 % of the window's area,
// and the F1 help fits in the window whole (no scrolling), over the frame; the stats box stays
// a small corner of the image.
TEST_F(ViewerGui, At800x600TheFrameKeepsMostOfTheWindowAndTheHelpFits) {
    REQUIRE_XDOTOOL();
    const Outcome r = driveSteps("at 600 300; key F1; pause 0.5", "--size 800x600");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    const Rect view = rectOf(state, "view");
    EXPECT_GE(static_cast<double>(view.w) * view.h, 0.6 * 800 * 600)
        << state.at("view") << ", side bar " << state.at("window_sidebar");
    EXPECT_EQ(state.at("help"), "1");
    EXPECT_EQ(state.at("help_scrolls"), "0");
    const Rect help = rectOf(state, "window_help");
    EXPECT_GE(help.x, 0);
    EXPECT_GE(help.y, 0);
    EXPECT_LE(help.x + help.w, 800);
    EXPECT_LE(help.y + help.h, 600);
    const Rect stats = rectOf(state, "window_stats");
    EXPECT_LE(static_cast<double>(stats.w) * stats.h, 0.05 * view.w * view.h);
}

// A window narrower than 640 pixels starts with the side bar collapsed to its strip; >> opens it.
TEST_F(ViewerGui, ANarrowWindowStartsWithTheSideBarCollapsed) {
    REQUIRE_XDOTOOL();
    Outcome r = driveSteps("pause 0.3", "--size 500x400");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("sidebar"), "collapsed");
    EXPECT_GE(rectOf(state, "view").w, 460);
    r = driveSteps("at 16 14; click 1; pause 0.3", "--size 500x400");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    state = readState(path("state.txt"));
    EXPECT_EQ(state.at("sidebar"), "open");
}

}  // namespace
