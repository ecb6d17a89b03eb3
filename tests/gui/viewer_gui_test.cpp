// facet-view as a user meets it: real processes in a virtual X display (xvfb-run), real input
// events (xdotool), the pictures it writes checked against `facet render` of the same scene.
// Each test starts its own Xvfb; ctest runs them one at a time (RESOURCE_LOCK), since two
// `xvfb-run -a` starting together can pick the same display number.

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "facet/evaluation/image_diff.hpp"
#include "facet/framebuffer.hpp"
#include "facet/scene_io.hpp"
#include "large_mesh.hpp"
#include "viewer_gui_support.hpp"

namespace {

using namespace facet;
using namespace viewer_gui;
using facet::view::Rect;

TEST_F(ViewerGui, WithoutADisplayItSaysWhatToDoAndExits2) {
    const Outcome r = run("env -u DISPLAY -u WAYLAND_DISPLAY " + kViewer + " " + kScene);
    EXPECT_EQ(r.exitCode, 2) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_NE(r.out.find("xvfb-run"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("facet render"), std::string::npos) << r.out;
}

TEST_F(ViewerGui, BadInputIsOneLineAndExitCode2) {
    const Outcome scene = run(kViewer + " " + FACET_TEST_DATA + "/scene_light_3_numbers.scene");
    EXPECT_EQ(scene.exitCode, 2) << scene.out;
    EXPECT_NE(scene.out.find("scene_light_3_numbers.scene:16: point light needs 4 or 5 numbers"),
              std::string::npos)
        << scene.out;
    for (const char* args : {"--size 0x0", "--frobnicate", "--shader chalk"}) {
        const Outcome r = run(kViewer + " " + args);
        EXPECT_EQ(r.exitCode, 2) << args << ": " << r.out;
        EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    }
    const Outcome help = run(kViewer + " --help");
    EXPECT_EQ(help.exitCode, 0);
    EXPECT_NE(help.out.find("--window-shot"), std::string::npos) << help.out;
}

TEST_F(ViewerGui, SmokeShowsTheEngineFrameAndThePanels) {
    REQUIRE_XVFB();
    const Outcome r = viewer("--frames 5 --size " + kWindow1280 +
                             " --no-vsync --screenshot frame.png "
                             "--window-shot window.png --state state.txt --fps-report");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("fps"), std::string::npos) << r.out;

    // The engine frame is what `facet render` draws with the same settings.
    const Framebuffer cli = cliRender("cli.png");
    const Framebuffer frame = readPng(path("frame.png"));
    ASSERT_EQ(frame.width, 1280);
    ASSERT_EQ(frame.height, 720);
    const ImageDiff d = diffImages(frame, cli);
    EXPECT_TRUE(d.sameSize);
    EXPECT_EQ(d.pixelsDiffering, 0u) << "max error " << d.maxError;

    // The window shows that frame texel for texel right of the side bar (below the stats box in
    // the top right corner)...
    const Framebuffer window = readPng(path("window.png"));
    ASSERT_EQ(window.width, 1660);
    ASSERT_EQ(window.height, 720);
    const auto shifted = [&](int x0, int y0, int x1, int y1) {
        return differingShareAt(window, frame, kFrameX, x0, y0, x1, y1);
    };
    EXPECT_EQ(shifted(0, 100, 1280, 720), 0.0);
    // ...the side bar at the left, the stats box in the image's top right corner.
    EXPECT_GT(differingShare(window, frame, 15, 15, 365, 300), 0.5);
    EXPECT_GT(shifted(1280 - 150, 12, 1280 - 12, 40), 0.2);
    // The side bar's background (GlFrame clears it in ImGui's WindowBg, #0F0F0F) down its
    // left padding, where no widget draws.
    for (int y = 100; y < 720; y += 100)
        EXPECT_EQ(window.color[window.index(2, y)] & 0xFFFFFFu, 0x0F0F0Fu) << y;

    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("frames"), "5");
    EXPECT_EQ(state.at("moved"), "0");
    EXPECT_EQ(state.at("size"), "1280 720");
}

TEST_F(ViewerGui, CompareSplitsAffineAndPerspective) {
    REQUIRE_XVFB();
    const Outcome r = viewer("--compare --frames 3 --size " + kWindow1280 +
                             " --no-vsync --screenshot compare.png");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const Framebuffer shown = readPng(path("compare.png"));
    const Framebuffer affine = cliRender("affine.png", "--interp affine");
    const Framebuffer perspective = cliRender("perspective.png", "--interp perspective");
    ASSERT_EQ(shown.width, 1280);
    EXPECT_EQ(differingShare(shown, affine, 0, 0, 640, 720), 0.0);
    EXPECT_EQ(differingShare(shown, perspective, 641, 0, 1280, 720), 0.0);
    for (int y = 0; y < 720; y += 10) EXPECT_EQ(shown.color[shown.index(640, y)], 0xFFFFFFFFu);
}

TEST_F(ViewerGui, KeepingTheSceneSizeLetterboxesTheFrame) {
    REQUIRE_XVFB();
    const Outcome r = viewer(
        "--keep-scene-size --size 1020x480 --frames 3 --no-vsync "
        "--window-shot window.png --state state.txt");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("size"), "1280 720");
    // The side bar narrowed to a third of the 1020-pixel window (346): 1280x720 fits the
    // 674x480 image area as 674x379 with 50-pixel bars above and below.
    EXPECT_EQ(state.at("view"), "346 50 674 379");
    const Framebuffer window = readPng(path("window.png"));
    ASSERT_EQ(window.width, 1020);
    ASSERT_EQ(window.height, 480);
    const int x = 346 + 600;
    const std::uint32_t bar = window.color[window.index(x, 470)];
    EXPECT_EQ(bar & 0xFFFFFFu, 0x141414u);
    EXPECT_NE(window.color[window.index(x, 400)], bar);  // the frame's background
    EXPECT_EQ(window.color[window.index(x, 428)], window.color[window.index(x, 400)]);
    EXPECT_EQ(window.color[window.index(x, 429)], bar);
    // Letterboxed, the side bar's background is a clear of its own, in ImGui's WindowBg.
    for (int y = 100; y < 480; y += 100)
        EXPECT_EQ(window.color[window.index(2, y)] & 0xFFFFFFu, 0x0F0F0Fu) << y;
}

TEST_F(ViewerGui, DraggingOverTheImageOrbitsAndTheWheelZooms) {
    REQUIRE_XDOTOOL();
    const Outcome r = drive("orbit");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    Result<Scene> scene = loadScene(kScene);
    ASSERT_TRUE(scene.ok());
    const double distance = glm::length(scene->camera.eye - scene->camera.look);
    EXPECT_EQ(state.at("moved"), "1");
    EXPECT_LT(number(state, "yaw"), -10.0);   // dragged right: the eye went left
    EXPECT_GT(number(state, "pitch"), 30.0);  // dragged down from 24.6°: the eye went up
    EXPECT_LT(number(state, "distance"), 0.9 * distance);  // wheel towards the scene
    const Framebuffer frame = readPng(path("frame.png"));
    const Framebuffer cli = cliRender("cli.png");
    EXPECT_GT(diffImages(frame, cli).pixelsDiffering, 10000u);
}

TEST_F(ViewerGui, ADragStartingOnThePanelsLeavesTheCameraAlone) {
    REQUIRE_XDOTOOL();
    const Outcome r = drive("panel", "--size " + kWindow1280 + " --window-shot window.png");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "0");
    EXPECT_EQ(number(state, "yaw"), 0.0);
    const Framebuffer frame = readPng(path("frame.png"));
    EXPECT_EQ(diffImages(frame, cliRender("cli.png")).pixelsDiffering, 0u);
    // The side bar stayed where it is (it does not move), the frame beside it.
    EXPECT_EQ(state.at("window_sidebar"), "0 0 380 720");
    EXPECT_EQ(state.at("view"), "380 0 1280 720");
}

TEST_F(ViewerGui, RightDragPansEyeAndLookTogether) {
    REQUIRE_XDOTOOL();
    const Outcome r = drive("pan");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "1");
    EXPECT_EQ(number(state, "yaw"), 0.0);
    EXPECT_NE(state.at("target"), "0 0 0");
    Result<Scene> scene = loadScene(kScene);
    ASSERT_TRUE(scene.ok());
    EXPECT_NEAR(number(state, "distance"), glm::length(scene->camera.eye - scene->camera.look),
                1e-9);
}

TEST_F(ViewerGui, DraggingTheCompareDividerMovesItNotTheCamera) {
    REQUIRE_XDOTOOL();
    const Outcome r = drive("divider", "--size " + kWindow1280 + " --compare");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "0");
    // The white divider column followed the pointer from the frame's x = 640 to x = 900.
    const Framebuffer shown = readPng(path("frame.png"));
    ASSERT_EQ(shown.width, 1280);
    const auto whiteColumn = [&](int x) {
        for (int y = 0; y < shown.height; y += 8)
            if (shown.color[shown.index(x, y)] != 0xFFFFFFFFu) return false;
        return true;
    };
    EXPECT_FALSE(whiteColumn(640));
    int found = -1;
    for (int x = 880; x <= 920; ++x)
        if (whiteColumn(x)) found = x;
    EXPECT_NEAR(found, 900, 2);
}

TEST_F(ViewerGui, TheFrameFollowsAResizedWindowWithTheSameFraming) {
    REQUIRE_XDOTOOL();
    const Outcome r = drive("resize");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    // 800x600 less the side bar (narrowed to 272): a 528x600 frame, the same vertical field of
    // view.
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("size"), "528 600");
    EXPECT_NEAR(number(state, "frame_focal"), 1100.0 * 600.0 / 720.0, 1e-9);
    const Framebuffer frame = readPng(path("frame.png"));
    EXPECT_EQ(frame.width, 528);
    EXPECT_EQ(frame.height, 600);
    // The stats box followed the window's right edge.
    const Rect stats = rectOf(state, "window_stats");
    EXPECT_GT(stats.w, 0);
    EXPECT_NEAR(stats.x + stats.w, 800 - 8, 1);
}

TEST_F(ViewerGui, TheScreenshotKeySavesTheFrame) {
    REQUIRE_XDOTOOL();
    // No pictures folder configured: ~/Pictures/facet, made on demand.
    const Outcome r =
        drive("key", "--size " + kWindow1280,
              "-u XDG_PICTURES_DIR HOME=" + path("home") + " XDG_CONFIG_HOME=" + path("config"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const Framebuffer shot = readPng(path("home/Pictures/facet/facet-frame-0001.png"));
    ASSERT_EQ(shot.width, 1280) << r.out;
    EXPECT_EQ(diffImages(shot, readPng(path("frame.png"))).pixelsDiffering, 0u);
}

}  // namespace

// Issue 14: a bare model opened, orbited and saved with Ctrl+S; the saved .scene renders the
// viewer's frame byte for byte, and the viewer's files went to its config folder.
TEST_F(ViewerGui, CtrlSSavesABareModelAfterOrbitingAsASceneThatRendersTheFrame) {
    REQUIRE_XDOTOOL();
    const std::string teapot = facet::test::sharedData("models/teapot.obj");
    REQUIRE_SHARED_DATA(teapot);
    const Outcome r = drive("save", "--size " + kWindow1280 + " " + teapot,
                            "FACET_DRIVE_SAVE_AS=" + path("teapot.scene"));
    ASSERT_EQ(r.exitCode, 0) << r.out;
    ASSERT_TRUE(fs::exists(path("teapot.scene"))) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "1");
    // The viewer opened the bare mesh lit (Gouraud); the scene file holds no settings.
    const Outcome cli = run(std::string(FACET_CLI) + " render " + path("teapot.scene") + " -o " +
                            path("cli.png") + " --lighting gouraud");
    ASSERT_EQ(cli.exitCode, 0) << cli.out;
    const Framebuffer frame = readPng(path("frame.png"));
    ASSERT_EQ(frame.width, 1280);
    EXPECT_EQ(diffImages(frame, readPng(path("cli.png"))).pixelsDiffering, 0u);
    // Recent files and ImGui's layout in $XDG_CONFIG_HOME/facet, nothing in the working folder.
    std::ifstream recent(path("config/facet/recent.txt"));
    std::string first;
    std::getline(recent, first);
    EXPECT_EQ(fs::path(first).filename(), "teapot.scene");
    EXPECT_TRUE(fs::exists(path("config/facet/imgui.ini")));
    EXPECT_FALSE(fs::exists(path("imgui.ini")));
}

// Issue 14: a 2M-triangle model named on the command line opens on the loading thread: the
// window is up with the default scene and a progress bar; Cancel stops the read and the default
// scene stays. (The OBJ, with v, vt and vn, takes seconds to read, so both runs act while it
// loads: they start 0.2 s after the window appears.)
TEST_F(ViewerGui, ALargeModelShowsItsProgressAndCancelKeepsTheSceneShown) {
    REQUIRE_XDOTOOL();
    const std::string big = path("grid2m.obj");
    std::ofstream(big, std::ios::binary) << facet::test::gridObj(1000);
    const std::string soon = "FACET_DRIVE_SETTLE=0.2";
    const auto loading = [](const std::map<std::string, std::string>& state, int& running,
                            double& fraction) {
        std::istringstream in(state.at("loading"));
        in >> running >> fraction;
    };

    // Stopped (SIGTERM) while it reads.
    Outcome r =
        driveSteps("pause 0.3", "--size " + kWindow1280 + " --window-shot window.png " + big,
                   /*selfQuit=*/false, soon);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    auto state = readState(path("state.txt"));
    EXPECT_EQ(fs::path(state.at("scene")).filename(), "default.scene");
    int running = 0;
    double fraction = 0.0;
    loading(state, running, fraction);
    ASSERT_EQ(running, 1) << "the load ended before the viewer was stopped";
    EXPECT_GT(fraction, 0.0);
    EXPECT_LT(fraction, 1.0);
    const Rect box = rectOf(state, "window_loading");
    const Rect cancel = rectOf(state, "window_loading_cancel");
    ASSERT_GT(box.w, 200);
    ASSERT_GT(cancel.w, 20);
    // The loading window is drawn over the frame.
    const Framebuffer window = readPng(path("window.png"));
    const Framebuffer frame = readPng(path("frame.png"));
    ASSERT_EQ(frame.width, 1280);
    EXPECT_GT(differingShareAt(window, frame, kFrameX, box.x - kFrameX, box.y,
                               box.x + box.w - kFrameX, box.y + box.h),
              0.5);

    // Cancel clicked: no load in flight, the default scene still shown, no error.
    r = driveSteps("at " + std::to_string(cancel.x + cancel.w / 2) + " " +
                       std::to_string(cancel.y + cancel.h / 2) + "; click 1; pause 0.5",
                   "--size " + kWindow1280 + " " + big, /*selfQuit=*/false, soon);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    state = readState(path("state.txt"));
    loading(state, running, fraction);
    EXPECT_EQ(running, 0);
    EXPECT_EQ(fs::path(state.at("scene")).filename(), "default.scene");
    EXPECT_EQ(state.count("window_loading"), 0u);
    std::stringstream log;
    log << std::ifstream(path("viewer.log")).rdbuf();
    EXPECT_EQ(log.str().find("facet-view:"), std::string::npos) << log.str();
    fs::remove(big);
}
