// The workspace as a user meets it, in a real window under Xvfb driven by xdotool: at the size
// the window opens at, the side bar never covers the frame (every course and shared scene); F1
// and ? open the help; F frames the model; dragging the light's marker moves the light; P saves
// into the pictures folder and shows the path; the UI follows the monitor's content scale.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/scene_io.hpp"
#include "framing.hpp"
#include "light_marker.hpp"
#include "viewer_gui_support.hpp"

namespace {

using namespace facet;
using namespace viewer_gui;
using facet::view::Rect;

const std::string kShared = facet::test::sharedDir() + "/data";

bool insideRect(const Rect& inner, const Rect& outer) {
    return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.w <= outer.x + outer.w &&
           inner.y + inner.h <= outer.y + outer.h;
}

/// Share of the pixels of `r` (window coordinates) where the window differs from the frame
/// shown at `view` (1:1).
double differingIn(const Framebuffer& window, const Framebuffer& frame, const Rect& view,
                   const Rect& r) {
    return differingShareAt(window, frame, view.x, r.x - view.x, r.y - view.y, r.x - view.x + r.w,
                            r.y - view.y + r.h);
}

// ---------------------------------------------------------------------------------------------
// The opening size, for every course and shared scene.

class OpeningLayout : public ViewerGui, public ::testing::WithParamInterface<const char*> {};

TEST_P(OpeningLayout, NoPanelPixelCoversTheFrame) {
    REQUIRE_XVFB();
    const std::string scene =
        std::string(GetParam()) == "default" ? kScene : kShared + "/" + GetParam();
    REQUIRE_SHARED_DATA(scene);
    Result<Scene> loaded = loadScene(scene);
    ASSERT_TRUE(loaded.ok());
    const Camera& sc = loaded->camera;
    const Outcome r = viewer(scene +
                             " --frames 5 --no-vsync --screenshot frame.png "
                             "--window-shot window.png --state state.txt");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    const Rect view = rectOf(state, "view");
    const Rect sidebar = rectOf(state, "window_sidebar");
    const Rect image = rectOf(state, "image_area");
    const Framebuffer frame = readPng(path("frame.png"));
    const Framebuffer window = readPng(path("window.png"));
    ASSERT_GT(view.w, 0);
    ASSERT_EQ(frame.width, view.w) << "the frame is shown 1:1";
    ASSERT_EQ(frame.height, view.h);

    // The window opened for the scene beside the side bar: the frame at the scene's own size,
    // or (1920x1080 on a 1920x1080 screen) scaled down with the aspect kept.
    if (sc.width + kFrameX <= 1920 && sc.height <= 1080) {
        EXPECT_EQ(view.w, sc.width);
        EXPECT_EQ(view.h, sc.height);
        EXPECT_EQ(window.width, sc.width + kFrameX);
        EXPECT_EQ(window.height, sc.height);
        EXPECT_EQ(state.at("frame_focal"), state.at("focal"));
    } else {
        EXPECT_LE(window.width, 1920);
        EXPECT_LE(window.height, 1080);
        EXPECT_NEAR(static_cast<double>(view.w) / view.h, static_cast<double>(sc.width) / sc.height,
                    0.01);
    }

    // The side bar and the frame share no pixel; the frame fills its image area.
    EXPECT_EQ(sidebar.x, 0);
    EXPECT_GT(sidebar.w, 0);
    EXPECT_LE(sidebar.x + sidebar.w, view.x);
    EXPECT_TRUE(insideRect(view, image));
    // Of the windows drawn, only the stats box lies over the image, in its top right corner,
    // small.
    for (const auto& [key, value] : state) {
        if (key.rfind("window_", 0) != 0 || key == "window_sidebar") continue;
        EXPECT_EQ(key, "window_stats") << "over the frame at opening: " << key;
    }
    const Rect stats = rectOf(state, "window_stats");
    EXPECT_TRUE(insideRect(stats, view));
    EXPECT_NEAR(stats.x + stats.w, view.x + view.w - 8, 1);
    EXPECT_LT(static_cast<double>(stats.w) * stats.h, 0.1 * view.w * view.h);

    // Pixels: the window shows the frame texel for texel everywhere but in the stats box and,
    // when the scene opens lit (a textured scene opens with Gouraud), the light's marker: a
    // small sun, or a pointer on the border, within 28 px of its place (light_input.cpp).
    int markerShown = 0, markerInside = 0;
    double markerX = 0.0, markerY = 0.0;
    std::istringstream(state.at("light_marker")) >> markerShown >> markerX >> markerY >>
        markerInside;
    const Rect note = rectOf(state, "light_marker_note_rect");
    std::size_t differ = 0;
    for (int y = 0; y < view.h; ++y)
        for (int x = 0; x < view.w; ++x) {
            const int wx = view.x + x, wy = view.y + y;
            if (wx >= stats.x && wx < stats.x + stats.w && wy >= stats.y && wy < stats.y + stats.h)
                continue;
            if (markerShown && std::hypot(wx - markerX, wy - markerY) <= 28.0) continue;
            if (wx >= note.x && wx < note.x + note.w && wy >= note.y && wy < note.y + note.h)
                continue;  // "light off screen" beside a marker on the border
            differ +=
                pixelError(window.color[window.index(wx, wy)], frame.color[frame.index(x, y)]) > 0;
        }
    EXPECT_EQ(differ, 0u);
    // And the side bar is really there (not the frame's pixels).
    EXPECT_GT(differingShare(window, frame, 10, 10, std::min(sidebar.w, frame.width) - 10, 300),
              0.3);
}

/// "course/example0.scene" → "example0" (a function: gtest's lambda form warns under -Wshadow).
std::string sceneName(const ::testing::TestParamInfo<const char*>& param) {
    std::string n = param.param;
    n = n.substr(n.find('/') + 1);
    return n.substr(0, n.find('.'));
}

INSTANTIATE_TEST_SUITE_P(
    Scenes, OpeningLayout,
    ::testing::Values("default", "course/example0.scene", "course/example1.scene",
                      "course/example2.scene", "course/example_textured.scene",
                      "scenes/bunny_1280x720.scene", "scenes/bunny_1920x1080.scene",
                      "scenes/spot_1280x720.scene", "scenes/spot_1920x1080.scene"),
    sceneName);

// ---------------------------------------------------------------------------------------------
// Keys.

TEST_F(ViewerGui, F1AndQuestionMarkOpenTheHelpOverTheImage) {
    REQUIRE_XDOTOOL();
    for (const char* key : {"F1", "question"}) {
        SCOPED_TRACE(key);
        const Outcome r = driveSteps(std::string("at 800 400; key ") + key + "; pause 0.5",
                                     "--size " + kWindow1280 + " --window-shot window.png");
        ASSERT_EQ(r.exitCode, 0) << r.out;
        const auto state = readState(path("state.txt"));
        EXPECT_EQ(state.at("help"), "1");
        const Rect view = rectOf(state, "view");
        const Rect help = rectOf(state, "window_help");
        ASSERT_GT(help.w, 200);
        EXPECT_TRUE(insideRect(help, view));
        const Framebuffer window = readPng(path("window.png"));
        const Framebuffer frame = readPng(path("frame.png"));
        EXPECT_GT(differingIn(window, frame, view, help), 0.5);
    }
    // Esc closes the help first; F1 again toggles it off too.
    const Outcome r =
        driveSteps("at 800 400; key F1; key Escape; key F1; key F1", "--size 800x600");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    EXPECT_EQ(readState(path("state.txt")).at("help"), "0");
}

TEST_F(ViewerGui, FFramesTheModelAndHomeGoesBack) {
    REQUIRE_XDOTOOL();
    // Turn and zoom far out, then F.
    const Outcome r =
        driveSteps("drag 1 800 400 150 40 5; at 800 400; click 5; click 5; click 5; click 5; key f",
                   "--size " + kWindow1280);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    Result<Scene> scene = loadScene(kScene);
    ASSERT_TRUE(scene.ok());
    const view::Sphere sphere = view::boundingSphere(*scene->mesh);
    std::istringstream target(state.at("target"));
    glm::dvec3 t;
    target >> t.x >> t.y >> t.z;
    EXPECT_LT(glm::length(t - sphere.centre), 1e-9 * sphere.radius);
    EXPECT_NEAR(number(state, "distance"),
                view::framingDistance(sphere.radius, number(state, "frame_focal"), 1280, 720),
                1e-6);
    EXPECT_LT(number(state, "yaw"), -10.0);  // the turn stayed
    // The picture: the model whole and centred.
    const Framebuffer frame = readPng(path("frame.png"));
    const std::uint32_t bg = frame.color[0];
    int x0 = frame.width, x1 = -1, y0 = frame.height, y1 = -1;
    for (int y = 0; y < frame.height; ++y)
        for (int x = 0; x < frame.width; ++x)
            if (frame.color[frame.index(x, y)] != bg) {
                x0 = std::min(x0, x);
                x1 = std::max(x1, x);
                y0 = std::min(y0, y);
                y1 = std::max(y1, y);
            }
    ASSERT_GE(x1, 0);
    EXPECT_GT(x0, 0);
    EXPECT_GT(y0, 0);
    EXPECT_LT(x1, frame.width - 1);
    EXPECT_LT(y1, frame.height - 1);
    // The knot fills much of the height (its bounding sphere 90 % of it).
    EXPECT_GT(y1 - y0, frame.height * 2 / 5);
    EXPECT_NEAR(0.5 * (x0 + x1), 640.0, 60.0);
    EXPECT_NEAR(0.5 * (y0 + y1), 360.0, 60.0);

    // Home: the scene's own camera again.
    const Outcome home = driveSteps("drag 1 800 400 150 40 5; key f; key Home", "--size 800x600");
    ASSERT_EQ(home.exitCode, 0) << home.out;
    EXPECT_EQ(readState(path("state.txt")).at("moved"), "0");
}

TEST_F(ViewerGui, TheSideBarResizesAndCollapsesAndTheFrameMakesRoom) {
    REQUIRE_XDOTOOL();
    // Its right edge dragged 120 pixels right.
    Outcome r = driveSteps("drag 1 379 300 120 0 6", "--size 1200x500");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("window_sidebar"), "0 0 500 500");
    EXPECT_EQ(state.at("view"), "500 0 700 500");
    // "<<" at the title row's right end: a strip, the frame beside it.
    r = driveSteps("at 348 18; click 1", "--size 1200x500");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    state = readState(path("state.txt"));
    EXPECT_EQ(state.at("sidebar"), "collapsed");
    const Rect strip = rectOf(state, "window_sidebar");
    EXPECT_EQ(strip.w, facet::view::kSidebarCollapsedWidth);
    EXPECT_EQ(rectOf(state, "view").x, strip.w);
}

TEST_F(ViewerGui, F11GoesFullscreenAndTheFrameFollows) {
    REQUIRE_XDOTOOL();
    const Outcome r = driveSteps("at 500 300; key F11; pause 1", "--size 800x600");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("fullscreen"), "1");
    EXPECT_EQ(state.at("window"), "1920 1080");
    EXPECT_EQ(state.at("view"), "380 0 1540 1080");
}

TEST_F(ViewerGui, NumberKeysSwitchDrawModeAndShader) {
    REQUIRE_XDOTOOL();
    const Outcome r = driveSteps("at 800 400; key 2; key 5; key l; key l", "--size 800x600");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("mode"), "wireframe");
    EXPECT_EQ(state.at("shader"), "depth");
    EXPECT_EQ(state.at("lighting"), "phong");
}

// ---------------------------------------------------------------------------------------------
// The light's marker.

TEST_F(ViewerGui, DraggingTheLightMarkerMovesTheLight) {
    REQUIRE_XDOTOOL();
    const std::string args = "--size " + kWindow1280 + " --lighting phong";
    // Where the marker is at the start.
    Outcome r = viewer(args + " --frames 3 --no-vsync --state start.txt --screenshot start.png");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto start = readState(path("start.txt"));
    // "shown x y in-frame": the default scene's light is behind the camera, its marker on the
    // frame's border, grabbed from there.
    std::istringstream at(start.at("light_marker"));
    int shown = 0, inFrame = 0;
    double mx = 0.0, my = 0.0;
    at >> shown >> mx >> my >> inFrame;
    ASSERT_EQ(shown, 1) << start.at("light_marker");
    const int x = static_cast<int>(std::lround(mx)), y = static_cast<int>(std::lround(my));
    const int dx = x > kFrameX + 640 ? -200 : 200, dy = y > 360 ? -120 : 120;

    r = driveSteps("drag 1 " + std::to_string(x) + " " + std::to_string(y) + " " +
                       std::to_string(dx) + " " + std::to_string(dy) + " 8",
                   args);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("moved"), "0") << "the drag moved the light, not the camera";
    EXPECT_NE(state.at("light"), start.at("light"));
    // The marker followed the pointer to where the drag ended.
    std::istringstream end(state.at("light_marker"));
    end >> shown >> mx >> my >> inFrame;
    EXPECT_EQ(shown, 1);
    EXPECT_EQ(inFrame, 1);
    EXPECT_NEAR(mx, x + dx, 2.0);
    EXPECT_NEAR(my, y + dy, 2.0);
    // At the same distance from the look-at point.
    auto lightOf = [](const std::string& s) {
        std::istringstream in(s);
        glm::dvec4 l;
        in >> l.x >> l.y >> l.z >> l.w;
        return glm::dvec3(l) / l.w;
    };
    std::istringstream tin(state.at("target"));
    glm::dvec3 t;
    tin >> t.x >> t.y >> t.z;
    // No farther than it was (a light beyond 0.9 of the camera's distance comes nearer, so it
    // stays on the side the camera sees: light_marker.hpp).
    EXPECT_LE(glm::length(lightOf(state.at("light")) - t),
              glm::length(lightOf(start.at("light")) - t) + 1e-6);
    // And the picture's lighting changed with it.
    EXPECT_GT(diffImages(readPng(path("frame.png")), readPng(path("start.png"))).pixelsDiffering,
              1000u);

    // Ctrl + drag anywhere on the image turns it around the look-at point.
    r = driveSteps("ctrldrag 900 500 -150 0 6", args);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto turned = readState(path("state.txt"));
    EXPECT_EQ(turned.at("moved"), "0");
    EXPECT_NE(turned.at("light"), start.at("light"));
}

// ---------------------------------------------------------------------------------------------
// Screenshots.

TEST_F(ViewerGui, TheScreenshotLandsInThePicturesFolderAndItsPathIsShown) {
    REQUIRE_XDOTOOL();
    const std::string pictures = path("pics");
    const Outcome r = driveSteps("at 800 400; key p; pause 0.3",
                                 "--size " + kWindow1280 + " --window-shot window.png", false,
                                 "XDG_PICTURES_DIR=" + pictures);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const std::string saved = pictures + "/facet/facet-frame-0001.png";
    const Framebuffer shot = readPng(saved);
    ASSERT_EQ(shot.width, 1280) << r.out;
    const Framebuffer frame = readPng(path("frame.png"));
    EXPECT_EQ(diffImages(shot, frame).pixelsDiffering, 0u);
    std::ifstream log(path("viewer.log"));
    std::stringstream text;
    text << log.rdbuf();
    EXPECT_NE(text.str().find("saved " + saved), std::string::npos) << text.str();
    // On screen: the notice with the path, over the bottom of the image, while it lasts.
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("screenshot_folder"), pictures + "/facet");
    EXPECT_EQ(state.at("notice"), "Saved " + saved);
    const Rect view = rectOf(state, "view");
    const Rect notice = rectOf(state, "window_notice");
    ASSERT_GT(notice.w, 100);
    EXPECT_TRUE(insideRect(notice, view));
    EXPECT_GT(notice.y, view.y + view.h / 2);
    EXPECT_GT(differingIn(readPng(path("window.png")), frame, view, notice), 0.3);
}

// ---------------------------------------------------------------------------------------------
// High DPI.

TEST_F(ViewerGui, FontsAndTheSideBarFollowTheMonitorsContentScale) {
    REQUIRE_XVFB();
    REQUIRE_PREREQUISITE(have("xprop"), "xprop is not installed (Debian package x11-utils)");
    // GLFW reads the X server's Xft.dpi (192: a scale of 2) as the monitor's content scale.
    // -noreset: the server would otherwise drop the property when xprop disconnects.
    {
        std::ofstream script(path("dpi.sh"));
        script << "xprop -root -f RESOURCE_MANAGER 8s -set RESOURCE_MANAGER 'Xft.dpi:\t192' && "
                  "exec \"$@\"\n";
    }
    const Outcome r = run("cd " + dir.string() +
                          " && timeout 60 xvfb-run -a -s '-screen 0 2400x1080x24 -noreset' sh "
                          "dpi.sh " +
                          kViewer + " --frames 3 --no-vsync --size 2300x800 --state state.txt");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("ui_scale"), "2.000");
    // (A window wide enough that the side bar keeps its full width: kSidebarShare.)
    const Rect sidebar = rectOf(state, "window_sidebar");
    EXPECT_EQ(sidebar.w, 2 * kFrameX);
    EXPECT_EQ(rectOf(state, "view").x, 2 * kFrameX);
    // --ui-scale overrides it.
    const Outcome forced = viewer(
        "--frames 3 --no-vsync --size 1600x800 --ui-scale 1.5 "
        "--state state.txt");
    ASSERT_EQ(forced.exitCode, 0) << forced.out;
    EXPECT_EQ(readState(path("state.txt")).at("ui_scale"), "1.500");
}

}  // namespace
