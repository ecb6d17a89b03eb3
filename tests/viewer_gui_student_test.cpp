// The viewer as a first-time student meets it, in real windows (xvfb-run, xdotool): Esc never
// loses the work, Ctrl+Q asks once before throwing changes away, a dragged light stays on the
// side the camera sees, a saved scene reopens as it looked, a Z-up model stands upright, and a
// small window keeps most of its area for the picture.

#include <cmath>
#include <string>

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

}  // namespace
