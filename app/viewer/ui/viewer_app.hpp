#pragma once
// The running viewer: the window, the document, and the state each panel and feature owns
// (declared in its own header), tied together by the frame loop (frame_loop.hpp: events →
// panels → engine render → upload → draw → UI → swap).

#include <string>

#include "camera_input.hpp"
#include "frame_loop.hpp"
#include "inspector.hpp"
#include "key_actions.hpp"
#include "layout.hpp"
#include "light_input.hpp"
#include "options.hpp"
#include "panels_accuracy.hpp"
#include "panels_compare.hpp"
#include "panels_scene.hpp"
#include "panels_screenshot.hpp"
#include "panels_stats.hpp"
#include "popups.hpp"
#include "twin_view.hpp"
#include "viewer_model.hpp"
#include "workspace_ui.hpp"

struct GLFWwindow;

namespace facet::view {

/// The whole viewer: the window and the document, and each panel's and feature's own state.
struct App {
    ViewerOptions options;
    GLFWwindow* window = nullptr;
    std::string iniPath;  ///< ImGui's layout file (kept alive for ImGui)
    int fbWidth = 0;      ///< framebuffer size, pixels
    int fbHeight = 0;
    Rect view;  ///< where the frame is shown in the window
    ViewerModel model;
    FrameLoop loop;              ///< renderers, the pictures in hand, vsync and pipelining
    TwinView twin;               ///< the OpenGL twin, in this window's context
    WorkspaceUi work;            ///< side bar, overlays, fullscreen, UI scale
    ScenePanelState files;       ///< Scene and Texture panels, the file being opened
    CompareState compare;        ///< the Compare panel
    AccuracyState accuracy;      ///< Compare's ground-truth section and table
    InspectorState inspector;    ///< the pixel inspector (Shift + click)
    StatsState stats;            ///< the frame times the Stats panel shows
    ScreenshotState screenshot;  ///< the Screenshot panel
    PopupState popups;           ///< the error popup and the quit question
    LightMarkerState light;      ///< the light's marker and its drag
    DragState drag;              ///< a mouse drag over the image
    KeyEvents keys;              ///< what the keys asked for since the last frame

    /// Runs until the window closes, --frames is reached or SIGTERM/SIGINT; returns the exit code.
    int run();
};

/// The window's title for a scene: "facet-view - " and its file name.
std::string windowTitle(const Scene& scene);

}  // namespace facet::view
