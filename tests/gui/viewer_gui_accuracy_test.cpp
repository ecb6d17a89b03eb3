// The Compare panel's "Against the ground truth" as a user meets it: a real facet-view window in
// a virtual X display, Measure clicked with xdotool, the viewer's announcement of the finished
// measurement waited for, a row of the table clicked, and the --state file and the window read
// back. Like viewer_gui_test, one Xvfb at a time (RESOURCE_LOCK in CMakeLists.txt).

#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "facet/framebuffer.hpp"
#include "viewer_gui_support.hpp"

namespace {

using namespace facet;
using namespace viewer_gui;

// Starts the viewer in the Compare panel (so the layout is fixed: Measure at (57, 458) of the
// window, in the side bar), clicks Measure, waits up to 40 s for "accuracy measured" on its
// stdout, clicks the table's third row (subdivided:16) in the table's own window at the image
// area's bottom left, then ends it with SIGTERM (which writes the outputs).
const char* const kScript = R"(set -u
cd "$1" || exit 1
shift
"$@" --state state.txt --screenshot frame.png --window-shot window.png >viewer.log 2>&1 &
pid=$!
wid=$(timeout 20 xdotool search --sync --onlyvisible --name '^facet-view' 2>/dev/null | head -n 1)
if [ -z "$wid" ]; then
  echo "no facet-view window appeared" >&2
  kill -TERM "$pid" 2>/dev/null
  wait "$pid"
  exit 1
fi
sleep 1
xdotool mousemove --window "$wid" 57 458 click 1
i=0
while ! grep -q "accuracy measured" viewer.log && [ "$i" -lt 400 ]; do sleep 0.1; i=$((i + 1)); done
sleep 0.5
xdotool mousemove --window "$wid" 508 468 click 1
sleep 0.5
kill -TERM "$pid"
i=0
while kill -0 "$pid" 2>/dev/null && [ "$i" -lt 50 ]; do sleep 0.1; i=$((i + 1)); done
kill -0 "$pid" 2>/dev/null && kill -TERM "$pid"
wait "$pid"
status=$?
cat viewer.log
exit "$status"
)";

TEST_F(ViewerGui, MeasuringAgainstTheGroundTruthFillsTheTableAndARowPicksTheMethod) {
    REQUIRE_XDOTOOL();
    {
        std::ofstream script(path("measure.sh"));
        script << kScript;
    }
    const Outcome r =
        run("timeout 90 " + kXvfb + "sh " + path("measure.sh") + " " + dir.string() + " " +
            kViewer + " --compare --size " + kWindow1280 + " --no-vsync --lighting phong");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("accuracy measured, 12 methods at 1280x720, ground truth 4x4 samples"),
              std::string::npos)
        << r.out;

    // Painter with Phong on the default knot: five interpolations, two lightings, 1x1, 2x2
    // samples and MSAA 2, 4, 8 (4x4 left out: not coarser than the 4x4 truth), measured for the
    // window's frame;
    // perspective and Phong are the exact forms, so never worse than subdivided or Gouraud.
    const auto state = readState(path("state.txt"));
    ASSERT_EQ(state.count("accuracy_rows"), 1u);
    EXPECT_EQ(state.at("accuracy_rows"), "12");
    EXPECT_EQ(state.at("accuracy_samples"), "4");
    EXPECT_EQ(state.at("accuracy_left_out"), "4x4");
    EXPECT_EQ(state.count("accuracy_samples_4x4"), 0u);
    EXPECT_EQ(state.at("accuracy_size"), "1280 720");
    auto rmse = [&](const std::string& key) {  // "ms rmse psnr max over2 pareto"
        std::istringstream in(state.at(key));
        double ms = 0.0, value = 0.0;
        in >> ms >> value;
        EXPECT_GT(ms, 0.0) << key;
        return value;
    };
    EXPECT_LE(rmse("accuracy_interp_perspective"), rmse("accuracy_interp_subdivided:32"));
    EXPECT_LE(rmse("accuracy_lighting_phong"), rmse("accuracy_lighting_gouraud"));
    EXPECT_GT(rmse("accuracy_interp_perspective"), 0.0);

    // The click on the subdivided:16 row switched the viewer to it.
    EXPECT_EQ(state.at("interp"), "subdivided");
    EXPECT_EQ(state.at("lighting"), "phong");

    // The table has a window of its own over the image (the side bar keeps its width).
    const Framebuffer window = readPng(path("window.png"));
    const Framebuffer frame = readPng(path("frame.png"));
    ASSERT_EQ(window.width, 1660);
    ASSERT_EQ(frame.width, 1280);
    EXPECT_EQ(state.at("window_sidebar"), "0 0 380 720");
    const facet::view::Rect table = rectOf(state, "window_table");
    ASSERT_GT(table.w, 300);
    EXPECT_GE(table.x, kFrameX);
    EXPECT_GT(differingShareAt(window, frame, kFrameX, table.x - kFrameX + 10, table.y + 30,
                               table.x - kFrameX + table.w - 10, table.y + table.h - 10),
              0.5);
}

}  // namespace
