#pragma once
// What the window tests share: running facet-view (and facet) as real processes under their own
// virtual X display (xvfb-run), driving it with xdotool through viewer_drive.sh, and reading
// back the PNGs and the --state file it writes.

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "facet/evaluation/image_diff.hpp"
#include "facet/framebuffer.hpp"
#include "facet/texture.hpp"
#include "run_process.hpp"
#include "shared_data.hpp"
#include "state_file.hpp"
#include "workspace.hpp"

namespace viewer_gui {

namespace fs = std::filesystem;

inline const std::string kViewer = FACET_VIEWER;
inline const std::string kDriver = FACET_VIEWER_DRIVER;
inline const std::string kScene = std::string(FACET_ASSETS_DIR) + "/default.scene";
inline const std::string kXvfb = "xvfb-run -a -s '-screen 0 1920x1080x24' ";

// The side bar takes the window's left 380 pixels (UI scale 1, as under Xvfb): a window of
// 1660x720 shows a 1280x720 frame at x = 380, the default scene's own size.
static_assert(facet::view::kSidebarWidth == 380, "the window sizes below assume it");
inline constexpr int kFrameX = facet::view::kSidebarWidth;
inline const std::string kWindow1280 = "1660x720";

using facet_test::Outcome;

inline Outcome run(const std::string& cmd) {
    return facet_test::runCommand(cmd);
}

inline bool have(const char* program) {
    return std::system((std::string("command -v ") + program + " >/dev/null 2>&1").c_str()) == 0;
}

/// A PNG as a frame (through the engine's image loader); empty when unreadable.
inline facet::Framebuffer readPng(const fs::path& path) {
    facet::Framebuffer f;
    facet::Result<facet::Texture> t = facet::loadTexture(path.string());
    if (!t) return f;
    const facet::MipLevel& l = t->level(0);
    f.resize(l.width, l.height);
    f.color = l.texels;
    return f;
}

inline std::map<std::string, std::string> readState(const fs::path& path) {
    std::ifstream f(path);
    std::stringstream s;
    s << f.rdbuf();
    return facet::view::parseState(s.str());
}

inline double number(const std::map<std::string, std::string>& state, const std::string& key) {
    const auto it = state.find(key);
    return it == state.end() ? NAN : std::stod(it->second);
}

/// Share of the pixels in [x0, x1) × [y0, y1) that differ between a and b.
inline double differingShare(const facet::Framebuffer& a, const facet::Framebuffer& b, int x0,
                             int y0, int x1, int y1) {
    std::size_t n = 0, differ = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++n)
            differ += facet::pixelError(a.color[a.index(x, y)], b.color[b.index(x, y)]) > 0;
    return n ? static_cast<double>(differ) / static_cast<double>(n) : 0.0;
}

/// Share of the frame's pixels in [x0, x1) × [y0, y1) that differ from the window's pixels
/// `dx` further right (the frame shown beside the side bar).
inline double differingShareAt(const facet::Framebuffer& window, const facet::Framebuffer& frame,
                               int dx, int x0, int y0, int x1, int y1) {
    std::size_t n = 0, differ = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++n)
            differ += facet::pixelError(window.color[window.index(x + dx, y)],
                                        frame.color[frame.index(x, y)]) > 0;
    return n ? static_cast<double>(differ) / static_cast<double>(n) : 0.0;
}

/// A rectangle "x y w h" from the --state file.
inline facet::view::Rect rectOf(const std::map<std::string, std::string>& state,
                                const std::string& key) {
    facet::view::Rect r;
    const auto it = state.find(key);
    if (it == state.end()) return r;
    std::istringstream in(it->second);
    in >> r.x >> r.y >> r.w >> r.h;
    return r;
}

/// A fresh folder per test, kept when the test failed; the viewer runs in it.
class ViewerGui : public ::testing::Test {
  protected:
    fs::path dir;

    void SetUp() override {
        dir = fs::temp_directory_path() /
              ("facet_viewer_gui_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(dir);  // kept for a look when something failed
    }
    std::string path(const std::string& name) const { return (dir / name).string(); }

    /// The viewer's config folder (recent files, imgui.ini) inside the test's folder, so no run
    /// reads another's panel layout or writes to the user's own.
    std::string configEnv() const { return "XDG_CONFIG_HOME=" + (dir / "config").string(); }

    /// `facet render` (or another facet command) of the default scene with extra options, as
    /// the reference picture.
    facet::Framebuffer cliRender(const std::string& name, const std::string& options = "",
                                 const std::string& command = "render") {
        const Outcome r = run(std::string(FACET_CLI) + " " + command + " " + kScene + " -o " +
                              path(name) + " " + options);
        EXPECT_EQ(r.exitCode, 0) << r.out;
        return readPng(path(name));
    }

    /// Runs the viewer under its own Xvfb, in `dir`; `env` goes before it ("NAME=value ...").
    Outcome viewer(const std::string& args, const std::string& env = "") {
        return run("cd " + dir.string() + " && env " + configEnv() + " " + env + " timeout 60 " +
                   kXvfb + kViewer + " " + args);
    }

    /// Drives the viewer with xdotool through tests/gui/viewer_drive.sh.
    Outcome drive(const std::string& scenario, const std::string& args = "--size " + kWindow1280,
                  const std::string& env = "") {
        return run("env " + env + " " + configEnv() + " timeout 90 " + kXvfb + "sh " + kDriver +
                   " " + scenario + " " + dir.string() + " " + kViewer + " --no-vsync " + args);
    }

    /// Drives the viewer through `steps` (viewer_drive.sh's commands, ';'-separated), then
    /// stops it with SIGTERM; with `selfQuit` the steps quit it (Ctrl+Q) and it must end alone
    /// (else the output says "still running").
    Outcome driveSteps(const std::string& steps, const std::string& args, bool selfQuit = false,
                       const std::string& env = "") {
        return drive("steps", args,
                     "FACET_DRIVE_STEPS='" + steps + "'" +
                         (selfQuit ? " FACET_DRIVE_QUIT=wait" : "") +
                         (env.empty() ? "" : " " + env));
    }
};

}  // namespace viewer_gui

// Without the tools the window tests skip, or fail under CI=true (shared_data.hpp).
#define REQUIRE_XVFB()                                 \
    REQUIRE_PREREQUISITE(viewer_gui::have("xvfb-run"), \
                         "xvfb-run is not installed (Debian package xvfb)")
#define REQUIRE_XDOTOOL()                             \
    REQUIRE_XVFB();                                   \
    REQUIRE_PREREQUISITE(viewer_gui::have("xdotool"), \
                         "xdotool is not installed (Debian package xdotool)")
