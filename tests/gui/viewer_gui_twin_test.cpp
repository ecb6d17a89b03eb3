// The OpenGL twin inside the real viewer (xvfb-run, so Mesa's llvmpipe through GLX): chosen at
// start (--renderer), with the G key and with the Render panel's combo, it draws a picture that
// matches the CPU engine's within the twin's stated tolerances; side by side puts the engine's
// picture left of the divider bit for bit and the twin's right of it; switching back and forth
// keeps both working; a twin that cannot draw (its shader broken) is a message and the engine
// takes over; a broken frame shader is one message naming the file.

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "facet/evaluation/image_diff.hpp"
#include "facet/framebuffer.hpp"
#include "viewer_gui_support.hpp"

namespace {

using namespace facet;
using namespace viewer_gui;

/// How two pictures of one view agree, measured like gl_twin_test but from PNGs: coverage by
/// the background colour (a PNG has no depth), colour as the largest channel difference.
struct Agreement {
    std::size_t covered = 0;          ///< pixels the first picture drew
    std::size_t coverageDiffers = 0;  ///< drawn in one picture only
    DiffHistogram both;               ///< the colour differences of the pixels both drew

    double coverageShare() const {
        return static_cast<double>(coverageDiffers) /
               static_cast<double>(std::max<std::size_t>(1, covered));
    }
};

/// Columns [x0, x1) of a and b, the background being RenderSettings' default grey.
Agreement agreement(const Framebuffer& a, const Framebuffer& b, int x0, int x1) {
    Agreement r;
    const std::uint32_t background = rgbaFromHex(RenderSettings{}.background) & 0xFFFFFFu;
    for (int y = 0; y < a.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::uint32_t pa = a.color[a.index(x, y)], pb = b.color[b.index(x, y)];
            const bool ca = (pa & 0xFFFFFFu) != background, cb = (pb & 0xFFFFFFu) != background;
            r.covered += ca;
            if (ca != cb) {
                ++r.coverageDiffers;
            } else if (ca) {
                r.both.add(pixelError(pa, pb));
            }
        }
    return r;
}

/// The twin's triangle tolerances (gl_twin_test's kTriangles: each renderer within 1 step of
/// the reference, so 2 between them) with the reference's ambiguous pixels, which gl_twin_test
/// leaves out, allowed here as coverage differences. Measured on the default scene: 0 coverage
/// differences of 225,097 covered pixels, 10 pixels 1 step apart.
void expectTwinAgrees(const Framebuffer& cpu, const Framebuffer& gl, int x0, int x1) {
    ASSERT_EQ(cpu.width, gl.width);
    ASSERT_EQ(cpu.height, gl.height);
    const Agreement a = agreement(cpu, gl, x0, x1);
    // Non-empty: the knot covers about a quarter of the frame.
    EXPECT_GT(a.covered, static_cast<std::size_t>(0.1 * (x1 - x0) * cpu.height));
    EXPECT_LE(a.coverageShare(), 1e-3) << a.coverageDiffers << " of " << a.covered;
    EXPECT_LE(a.both.max(), 2);
    EXPECT_LE(a.both.shareAbove(1), 2e-4);
}

/// The shaders folder with `file` broken, for $FACET_SHADERS.
std::string brokenShaders(const fs::path& dir, const std::string& file) {
    const fs::path source = fs::path(FACET_ASSETS_DIR).parent_path() / "shaders";
    const fs::path copy = dir / "shaders";
    fs::create_directories(copy);
    for (const auto& entry : fs::directory_iterator(source))
        fs::copy_file(entry.path(), copy / entry.path().filename());
    std::ofstream(copy / file, std::ios::app) << "\nthis is not GLSL;\n";
    return copy.string();
}

TEST_F(ViewerGui, TheOpenGLTwinDrawsWhatTheEngineDraws) {
    REQUIRE_XVFB();
    const Outcome r = viewer(
        "--renderer gl --frames 5 --size 1660x720 --no-vsync --screenshot gl.png "
        "--window-shot window.png --state state.txt --fps-report");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("renderer"), "gl");
    EXPECT_EQ(state.at("engine_frames"), "0");  // the twin alone: the engine sat out
    EXPECT_EQ(state.at("twin_frames"), "5");
    EXPECT_EQ(state.at("twin_error"), "");
    EXPECT_FALSE(state.at("twin_device").empty());
    EXPECT_NE(r.out.find("twin "), std::string::npos) << r.out;  // --fps-report's twin time

    const Framebuffer gl = readPng(path("gl.png"));
    const Framebuffer cpu = cliRender("cpu.png");
    expectTwinAgrees(cpu, gl, 0, 1280);
    // The twin in the window's context is the twin of `facet render-gl` (EGL) on one driver.
    const Outcome egl =
        run(std::string(FACET_CLI) + " render-gl " + kScene + " -o " + path("egl.png"));
    ASSERT_EQ(egl.exitCode, 0) << egl.out;
    if (egl.out.find(state.at("twin_device")) != std::string::npos) {
        EXPECT_EQ(diffImages(gl, readPng(path("egl.png"))).pixelsDiffering, 0u);
    }

    // The window shows the twin's picture texel for texel where no panel covers it, and the
    // panels over it: the twin left ImGui's state and the frame's drawing alone.
    const Framebuffer window = readPng(path("window.png"));
    ASSERT_EQ(window.width, 1660);
    EXPECT_LT(differingShareAt(window, gl, kFrameX, 200, 100, 1280, 720),
              0.001);  // "OpenGL twin" label at bottom left
    EXPECT_GT(differingShare(window, gl, 15, 15, 365, 300), 0.5);
    EXPECT_GT(differingShareAt(window, gl, kFrameX, 1280 - 150, 12, 1280 - 12, 40), 0.2);
}

TEST_F(ViewerGui, SideBySideIsTheEngineLeftAndTheTwinRight) {
    REQUIRE_XVFB();
    for (const bool serial : {false, true}) {
        SCOPED_TRACE(serial ? "serial" : "pipelined");
        const Outcome r =
            viewer(std::string("--renderer split --frames 4 --size 1660x720 --no-vsync ") +
                   (serial ? "--serial " : "") + "--screenshot split.png --state state.txt");
        ASSERT_EQ(r.exitCode, 0) << r.out;
        const auto state = readState(path("state.txt"));
        EXPECT_EQ(state.at("renderer"), "split");
        EXPECT_EQ(state.at("engine_frames"), "4");
        EXPECT_EQ(state.at("twin_frames"), "4");
        const Framebuffer shown = readPng(path("split.png"));
        const Framebuffer cpu = cliRender("cpu.png");
        ASSERT_EQ(shown.width, 1280);
        EXPECT_EQ(differingShare(shown, cpu, 0, 0, 640, 720), 0.0);
        for (int y = 0; y < 720; y += 10) EXPECT_EQ(shown.color[shown.index(640, y)], 0xFFFFFFFFu);
        expectTwinAgrees(cpu, shown, 641, 1280);
    }

    // The difference of the two: black where they agree, which is nearly everywhere.
    const Outcome r = viewer(
        "--renderer split --difference --frames 3 --size 1660x720 --no-vsync "
        "--screenshot heat.png");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const Framebuffer heat = readPng(path("heat.png"));
    ASSERT_EQ(heat.width, 1280);
    const std::size_t black = static_cast<std::size_t>(
        std::count_if(heat.color.begin(), heat.color.end(),
                      [](std::uint32_t p) { return (p & 0xFFFFFFu) == 0; }));
    EXPECT_GT(static_cast<double>(black) / static_cast<double>(heat.color.size()), 0.999);
}

TEST_F(ViewerGui, SwitchingRenderersBackAndForthKeepsWorking) {
    REQUIRE_XDOTOOL();
    // G four times: CPU → OpenGL → side by side → CPU → OpenGL, a second each.
    const Outcome r = drive("renderers");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("renderer"), "gl");
    EXPECT_EQ(state.at("renderer_switches"), "4");
    EXPECT_EQ(state.at("twin_error"), "");
    EXPECT_GT(number(state, "engine_frames"), 2.0);
    EXPECT_GT(number(state, "twin_frames"), 2.0);
    std::ifstream log(path("viewer.log"));
    std::stringstream text;
    text << log.rdbuf();
    EXPECT_EQ(text.str().find("OpenGL twin:"), std::string::npos) << text.str();
    expectTwinAgrees(cliRender("cpu.png"), readPng(path("frame.png")), 0, 1280);
}

TEST_F(ViewerGui, TheRenderPanelsComboSelectsTheTwin) {
    REQUIRE_XDOTOOL();
    const Outcome r = drive("combo");
    ASSERT_EQ(r.exitCode, 0) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("renderer"), "gl");
    EXPECT_EQ(state.at("moved"), "0");  // the clicks went to the panel, not the camera
    EXPECT_GT(number(state, "twin_frames"), 2.0);
    expectTwinAgrees(cliRender("cpu.png"), readPng(path("frame.png")), 0, 1280);
}

TEST_F(ViewerGui, ATwinThatCannotDrawSaysWhyAndTheEngineTakesOver) {
    REQUIRE_XVFB();
    const std::string shaders = brokenShaders(dir, "twin.frag");
    const Outcome r = viewer(
        "--renderer gl --frames 4 --size 1660x720 --no-vsync --screenshot frame.png "
        "--window-shot window.png --state state.txt",
        "FACET_SHADERS=" + shaders);
    ASSERT_EQ(r.exitCode, 0) << r.out;
    // The message names the file and carries the driver's GLSL log.
    EXPECT_NE(r.out.find("facet-view: OpenGL twin: " + shaders + "/twin.frag"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("error"), std::string::npos) << r.out;
    const auto state = readState(path("state.txt"));
    EXPECT_EQ(state.at("renderer"), "cpu");
    EXPECT_NE(state.at("twin_error").find("twin.frag"), std::string::npos);
    EXPECT_EQ(state.at("twin_frames"), "0");
    // The engine drew every frame instead, the first one included.
    EXPECT_EQ(state.at("engine_frames"), "4");
    const Framebuffer frame = readPng(path("frame.png"));
    EXPECT_EQ(diffImages(frame, cliRender("cpu.png")).pixelsDiffering, 0u);
    // ...under the error popup, in the middle of the window.
    const Framebuffer window = readPng(path("window.png"));
    ASSERT_EQ(window.width, 1660);
    EXPECT_GT(differingShareAt(window, frame, kFrameX, 330, 330, 950, 390), 0.3);
}

TEST_F(ViewerGui, ABrokenFrameShaderIsOneMessageNamingTheFile) {
    REQUIRE_XVFB();
    const std::string shaders = brokenShaders(dir, "frame.frag");
    const Outcome r = viewer("--frames 2 --size 640x360", "FACET_SHADERS=" + shaders);
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_NE(r.out.find("facet-view: " + shaders + "/frame.frag: "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("error"), std::string::npos) << r.out;
}

}  // namespace
