// The viewer's workspace without a window: the side bar and the image area never overlap and
// the frame stays inside the image area at any window size; the opening size holds the scene
// beside the side bar within the work area; every key of the help dispatches to its action;
// the shininess slider's log mapping; where screenshots go.

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "compare.hpp"
#include "facet/scene_io.hpp"
#include "key_map.hpp"
#include "log_slider.hpp"
#include "screenshot_folder.hpp"
#include "viewer_model.hpp"
#include "workspace.hpp"

namespace {

using namespace facet;
using namespace facet::view;
namespace fs = std::filesystem;

const std::string kDefaultScene = std::string(FACET_ASSETS_DIR) + "/default.scene";

bool inside(const Rect& inner, const Rect& outer) {
    return inner.x >= outer.x && inner.y >= outer.y && inner.x + inner.w <= outer.x + outer.w &&
           inner.y + inner.h <= outer.y + outer.h;
}

TEST(Workspace, SideBarAndFrameNeverOverlapAtAnySize) {
    for (const SidebarState state :
         {SidebarState::Open, SidebarState::Collapsed, SidebarState::Hidden}) {
        for (const double scale : {1.0, 1.5, 2.0}) {
            for (int w : {200, 640, 800, 1280, 1920, 3840}) {
                for (int h : {150, 480, 720, 1080}) {
                    const Workspace ws = workspaceLayout(w, h, 380, state, scale);
                    EXPECT_FALSE(overlaps(ws.sidebar, ws.image)) << w << "x" << h;
                    // Together they are the window, side by side.
                    EXPECT_EQ(ws.sidebar.w + ws.image.w, w);
                    EXPECT_EQ(ws.image.h, h);
                    EXPECT_EQ(ws.image.x, ws.sidebar.w);
                    for (const auto& [fw, fh] : {std::pair{512, 512}, {800, 600}, {1920, 1080}}) {
                        const Rect f = frameRect(ws, fw, fh);
                        EXPECT_TRUE(inside(f, ws.image)) << w << "x" << h << " " << fw;
                        ASSERT_GT(f.w, 0) << "the frame never vanishes";
                        EXPECT_FALSE(overlaps(f, ws.sidebar));
                        // The aspect is the frame's, to the rounding of one pixel.
                        EXPECT_NEAR(static_cast<double>(f.w) / f.h, static_cast<double>(fw) / fh,
                                    1.0 / std::min(f.w, f.h) * 2.0);
                    }
                }
            }
        }
    }
}

TEST(Workspace, TheSideBarWidthIsClampedAndScaled) {
    EXPECT_EQ(workspaceLayout(1280, 720, 380, SidebarState::Open, 1.0).sidebar.w, 380);
    // Dragged too narrow or too wide: the least width, or 70 % of the window.
    EXPECT_EQ(workspaceLayout(1280, 720, 10, SidebarState::Open, 1.0).sidebar.w, kSidebarMinWidth);
    EXPECT_EQ(workspaceLayout(1280, 720, 5000, SidebarState::Open, 1.0).sidebar.w, 896);
    EXPECT_EQ(workspaceLayout(1280, 720, 10, SidebarState::Open, 2.0).sidebar.w,
              2 * kSidebarMinWidth);
    EXPECT_EQ(workspaceLayout(1280, 720, 380, SidebarState::Collapsed, 2.0).sidebar.w,
              2 * kSidebarCollapsedWidth);
    const Workspace hidden = workspaceLayout(1280, 720, 380, SidebarState::Hidden, 1.0);
    EXPECT_EQ(hidden.sidebar.w, 0);
    EXPECT_EQ(hidden.image.w, 1280);
    EXPECT_EQ(workspaceLayout(0, 720, 380, SidebarState::Open, 1.0).image.w, 0);
    // A window narrower than the side bar's least width: the image keeps its 30 %.
    EXPECT_EQ(workspaceLayout(200, 300, 380, SidebarState::Open, 1.0).image.w, 60);
}

TEST(Workspace, TheWindowOpensWithTheSceneBesideTheSideBar) {
    // Fits: the image area is the scene's size exactly.
    OpeningSize o = openingSize(512, 512, 380, 1920, 1080);
    EXPECT_FALSE(o.scaled);
    EXPECT_EQ(o.width, 892);
    EXPECT_EQ(o.height, 512);
    EXPECT_EQ(o.imageWidth, 512);
    o = openingSize(1280, 720, 380, 1920, 1080);
    EXPECT_EQ(o.width, 1660);
    EXPECT_EQ(o.imageHeight, 720);
    // 1920x1080 beside a side bar on a 1920x1080 screen: scaled down, aspect kept, all fits.
    o = openingSize(1920, 1080, 380, 1920, 1080);
    EXPECT_TRUE(o.scaled);
    EXPECT_LE(o.width, 1920);
    EXPECT_LE(o.height, 1080);
    EXPECT_EQ(o.imageWidth, 1540);
    EXPECT_NEAR(static_cast<double>(o.imageWidth) / o.imageHeight, 16.0 / 9.0, 0.01);
    // A tall work area (a taskbar at the side) limits the height instead.
    o = openingSize(1920, 1080, 380, 3840, 700);
    EXPECT_EQ(o.imageHeight, 700);
    EXPECT_EQ(o.imageWidth, 1244);
    // Unknown work area: no cap.
    o = openingSize(4000, 3000, 380, 0, 0);
    EXPECT_EQ(o.width, 4380);
    EXPECT_EQ(o.height, 3000);
}

TEST(Workspace, CornerRectsSitInTheirCorners) {
    const Rect area{380, 0, 1280, 720};
    const Rect tr = cornerRect(area, 200, 50, Corner::TopRight, 8);
    EXPECT_EQ(tr.x, 380 + 1280 - 8 - 200);
    EXPECT_EQ(tr.y, 8);
    const Rect bl = cornerRect(area, 200, 50, Corner::BottomLeft, 8);
    EXPECT_EQ(bl.x, 388);
    EXPECT_EQ(bl.y, 720 - 8 - 50);
    EXPECT_TRUE(inside(tr, area));
    EXPECT_TRUE(overlaps(Rect{0, 0, 10, 10}, Rect{9, 9, 5, 5}));
    EXPECT_FALSE(overlaps(Rect{0, 0, 10, 10}, Rect{10, 0, 5, 5}));
}

TEST(KeyMap, EveryKeyInTheHelpDispatchesToItsAction) {
    std::set<Action> seen;
    for (const KeyBinding& k : keyBindings()) {
        EXPECT_FALSE(k.keys.empty());
        EXPECT_FALSE(k.what.empty());
        EXPECT_TRUE(seen.insert(k.action).second) << "twice in the table: " << k.keys;
        EXPECT_TRUE(!k.chars.empty() || k.named) << k.keys << " has no key";
        for (const char c : k.chars) EXPECT_EQ(actionForChar(static_cast<unsigned>(c)), k.action);
        if (k.named) {
            EXPECT_EQ(actionForKey(*k.named), k.action);
        }
        EXPECT_EQ(keysFor(k.action), k.keys);
    }
    EXPECT_EQ(actionForKey(NamedKey::F1), Action::Help);
    EXPECT_EQ(actionForChar('?'), Action::Help);
    EXPECT_EQ(actionForChar('f'), Action::FrameModel);
    EXPECT_EQ(actionForChar('F'), Action::FrameModel);
    EXPECT_EQ(actionForKey(NamedKey::Home), Action::ResetCamera);
    EXPECT_EQ(actionForKey(NamedKey::F11), Action::Fullscreen);
    EXPECT_EQ(actionForKey(NamedKey::F12), Action::Screenshot);
    EXPECT_EQ(actionForChar('1'), Action::ModeSolid);
    EXPECT_EQ(actionForChar('x'), std::nullopt);
    EXPECT_EQ(actionForChar(0x263A), std::nullopt);  // a smiley: no key
    EXPECT_GE(mouseBindings().size(), 5u);
}

TEST(KeyMap, DocumentActionsChangeTheDocumentAndTheOthersAreLeftToTheWindow) {
    ViewerModel m;
    ASSERT_TRUE(m.load(kDefaultScene));
    CompareSettings compare;
    EXPECT_TRUE(applyDocumentAction(Action::ModeWireframe, m, compare));
    EXPECT_EQ(m.settings.mode, DrawMode::Wireframe);
    EXPECT_TRUE(applyDocumentAction(Action::ShaderDepth, m, compare));
    EXPECT_EQ(m.settings.shader, ShaderKind::Depth);
    const Lighting before = m.settings.lighting;
    for (int i = 0; i < 3; ++i) applyDocumentAction(Action::NextLighting, m, compare);
    EXPECT_EQ(m.settings.lighting, before);  // three steps: round
    applyDocumentAction(Action::NextLighting, m, compare);
    EXPECT_NE(m.settings.lighting, before);
    EXPECT_TRUE(applyDocumentAction(Action::ToggleCompare, m, compare));
    EXPECT_TRUE(compare.enabled);
    EXPECT_TRUE(applyDocumentAction(Action::ToggleDifference, m, compare));
    EXPECT_EQ(compare.display, CompareDisplay::Difference);
    m.prepareFrame(1280, 720);
    EXPECT_TRUE(applyDocumentAction(Action::FrameModel, m, compare));
    EXPECT_TRUE(m.orbitMoved);
    EXPECT_TRUE(applyDocumentAction(Action::ResetCamera, m, compare));
    EXPECT_FALSE(m.orbitMoved);
    for (const Action a : {Action::Help, Action::Back, Action::Quit, Action::Fullscreen,
                           Action::Screenshot, Action::TogglePanels, Action::ToggleStats})
        EXPECT_FALSE(applyDocumentAction(a, m, compare));
}

TEST(LogSlider, EqualTravelMultipliesByEqualFactors) {
    EXPECT_DOUBLE_EQ(logSliderValue(0.0, 1.0, 1000.0), 1.0);
    EXPECT_DOUBLE_EQ(logSliderValue(1.0, 1.0, 1000.0), 1000.0);
    EXPECT_NEAR(logSliderValue(1.0 / 3.0, 1.0, 1000.0), 10.0, 1e-9);
    EXPECT_NEAR(logSliderValue(2.0 / 3.0, 1.0, 1000.0), 100.0, 1e-9);
    EXPECT_NEAR(logSliderPosition(30.0, 1.0, 1000.0), std::log10(30.0) / 3.0, 1e-12);
    for (double v : {1.0, 2.5, 30.0, 128.0, 999.0})
        EXPECT_NEAR(logSliderValue(logSliderPosition(v, 1.0, 1000.0), 1.0, 1000.0), v, 1e-9 * v);
    // The complaint: on the linear slider 100 px of a 200 px slider took s from 30 to
    // 0.07. Here 100 px of 200 from s = 30 is a factor of 1000^(1/2) ≈ 31.6 either way.
    const double t = logSliderPosition(30.0, 1.0, 1000.0);
    EXPECT_NEAR(logSliderValue(t - 0.5, 1.0, 1000.0), 1.0, 1e-9);  // clamped at the end
    EXPECT_NEAR(logSliderValue(t + 0.25, 1.0, 1000.0) / 30.0, std::sqrt(std::sqrt(1000.0)), 1e-9);
    // Typed values beyond the range sit at the ends and are not changed by the mapping.
    EXPECT_EQ(logSliderPosition(5000.0, 1.0, 1000.0), 1.0);
    EXPECT_EQ(logSliderPosition(0.5, 1.0, 1000.0), 0.0);
    EXPECT_EQ(logSliderPosition(std::nan(""), 1.0, 1000.0), 0.0);
    EXPECT_EQ(logSliderValue(std::nan(""), 1.0, 1000.0), 1.0);
    EXPECT_DOUBLE_EQ(roundSignificant(29.99731, 3), 30.0);
    EXPECT_DOUBLE_EQ(roundSignificant(0.012345, 2), 0.012);
    EXPECT_DOUBLE_EQ(roundSignificant(0.0, 3), 0.0);
}

TEST(ScreenshotFolder, PicturesFolderThenUserDirsThenHome) {
    PicturesEnv e;
    e.home = "/home/ada";
    EXPECT_EQ(screenshotFolder(e), "/home/ada/Pictures/facet");
    e.userDirs =
        "# written by xdg-user-dirs-update\nXDG_DESKTOP_DIR=\"$HOME/Desktop\"\n"
        "XDG_PICTURES_DIR=\"$HOME/Bilder\"\n";
    EXPECT_EQ(screenshotFolder(e), "/home/ada/Bilder/facet");
    e.userDirs = "XDG_PICTURES_DIR=\"/data/photos\"\n";
    EXPECT_EQ(screenshotFolder(e), "/data/photos/facet");
    e.userDirs = "XDG_PICTURES_DIR=\"$HOME/\"\n";  // disabled: back to ~/Pictures
    EXPECT_EQ(screenshotFolder(e), "/home/ada/Pictures/facet");
    e.xdgPicturesDir = "/tmp/shots";
    EXPECT_EQ(screenshotFolder(e), "/tmp/shots/facet");
    EXPECT_EQ(screenshotFolder(PicturesEnv{}), "facet");
}

TEST(ScreenshotFolder, IsCreatedOnDemandAndAFileInTheWayIsAnError) {
    const fs::path dir = fs::temp_directory_path() / ("facet_shots_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const std::string folder = (dir / "Pictures" / "facet").string();
    EXPECT_TRUE(ensureFolder(folder));
    EXPECT_TRUE(fs::is_directory(folder));
    EXPECT_TRUE(ensureFolder(folder));  // already there
    const std::string blocked = (dir / "file").string();
    { std::ofstream(blocked) << "x"; }
    const Status error = ensureFolder(blocked + "/facet");
    ASSERT_FALSE(error);
    EXPECT_NE(error.error().what().find(blocked), std::string::npos) << error.error().what();
    fs::remove_all(dir);
}

}  // namespace

namespace {

// Esc closes one thing, the innermost, and has nothing to do (never quits) when all is closed.
TEST(EscKey, ClosesTheInnermostOpenThingAndNeverQuits) {
    using facet::view::EscTarget;
    using facet::view::OpenThings;
    EXPECT_EQ(escTarget(OpenThings{}), EscTarget::None);
    EXPECT_EQ(escTarget(OpenThings{true, true, true, true, true}), EscTarget::Popup);
    EXPECT_EQ(escTarget(OpenThings{false, true, true, true, true}), EscTarget::Inspector);
    EXPECT_EQ(escTarget(OpenThings{false, false, true, true, true}), EscTarget::MeasureTable);
    EXPECT_EQ(escTarget(OpenThings{false, false, false, true, true}), EscTarget::Help);
    EXPECT_EQ(escTarget(OpenThings{false, false, false, false, true}), EscTarget::Fullscreen);
    // The key table: Esc goes back, Ctrl+Q quits; no printable key quits.
    EXPECT_EQ(actionForKey(NamedKey::Escape), Action::Back);
    EXPECT_EQ(actionForKey(NamedKey::CtrlQ), Action::Quit);
    for (unsigned c = 1; c < 128; ++c) EXPECT_NE(actionForChar(c), Action::Quit) << c;
}

// Camera, light, material and settings count as unsaved changes; saving clears them.
TEST(UnsavedChanges, CameraLightMaterialAndSettingsCountAndSavingClearsThem) {
    ViewerModel m;
    ASSERT_TRUE(m.load(kDefaultScene));
    EXPECT_FALSE(m.unsaved());
    m.prepareFrame(800, 600);  // the window's size is no change of the scene
    EXPECT_FALSE(m.unsaved());
    m.rotate(40.0, 0.0);
    EXPECT_TRUE(m.unsaved());
    m.resetCamera();
    EXPECT_FALSE(m.unsaved());
    m.scene.lighting.light.position.x += 1.0;
    EXPECT_TRUE(m.unsaved());
    m.markSaved();
    m.scene.lighting.material.ks = 0.9;
    EXPECT_TRUE(m.unsaved());
    m.markSaved();
    m.settings.cullBackFaces = !m.settings.cullBackFaces;
    EXPECT_TRUE(m.unsaved());
    const fs::path out =
        fs::temp_directory_path() / ("facet_unsaved_" + std::to_string(::getpid())) / "saved.scene";
    fs::create_directories(out.parent_path());
    m.prepareFrame(800, 600);
    ASSERT_TRUE(m.saveScene(out.string()));
    EXPECT_FALSE(m.unsaved());
    fs::remove_all(out.parent_path());
}

}  // namespace

namespace {

// The side bar narrows itself in a small window (the frame keeps most of it) and collapses
// below kCollapseBelow; a large window gets the full width.
TEST(Workspace, TheSideBarNarrowsInASmallWindow) {
    EXPECT_EQ(autoSidebarWidth(1920, 1.0), kSidebarWidth);
    EXPECT_EQ(autoSidebarWidth(1660, 1.0), kSidebarWidth);
    EXPECT_EQ(autoSidebarWidth(3840, 2.0), 2 * kSidebarWidth);
    EXPECT_EQ(autoSidebarWidth(800, 1.0), 272);
    EXPECT_EQ(autoSidebarWidth(600, 1.0), kSidebarMinWidth);
    // At 800x600 a frame that follows the window keeps 60 % of its area or more.
    const Workspace w =
        workspaceLayout(800, 600, autoSidebarWidth(800, 1.0), SidebarState::Open, 1.0);
    EXPECT_GE(w.image.w * w.image.h, 0.6 * 800 * 600);
    EXPECT_FALSE(autoCollapsed(800, 1.0));
    EXPECT_TRUE(autoCollapsed(500, 1.0));
    EXPECT_FALSE(autoCollapsed(1000, 1.5));
    EXPECT_TRUE(autoCollapsed(900, 1.5));
}

}  // namespace

namespace {

// D without two pictures does nothing to the document (the window says why): it no longer
// silently turns on difference mode for a later Compare.
TEST(KeyMap, DWithoutComparisonChangesNothing) {
    ViewerModel m;
    ASSERT_TRUE(m.load(kDefaultScene));
    CompareSettings compare;
    EXPECT_FALSE(applyDocumentAction(Action::ToggleDifference, m, compare));
    EXPECT_EQ(compare.display, CompareDisplay::Split);
    EXPECT_TRUE(applyDocumentAction(Action::ToggleCompare, m, compare));
    EXPECT_TRUE(applyDocumentAction(Action::ToggleDifference, m, compare));
    EXPECT_EQ(compare.display, CompareDisplay::Difference);
}

}  // namespace
