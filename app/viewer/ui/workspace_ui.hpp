#pragma once
// The window side of the workspace: the side bar at the left holds every panel, the image area
// beside it shows the frame and nothing else but the overlays the user turns on (a compact stats
// box in its top right corner, the help, a notice, the light marker, Compare's labels). Its
// state (side bar, overlays, fullscreen, UI scale) and the functions that lay it out and draw
// it. The arithmetic lives in viewer_core (workspace.hpp, key_map.hpp, light_marker.hpp); this
// is the ImGui and GLFW side.

#include <chrono>
#include <map>
#include <string>

#include <glm/vec2.hpp>

#include "workspace.hpp"

namespace facet::view {

struct App;

/// A message shown over the image for a few seconds (the saved screenshot's path).
struct Notice {
    std::string text;
    std::chrono::steady_clock::time_point until{};
};

/// How long a notice stays.
inline constexpr double kNoticeSeconds = 4.0;

/// Side bar, overlays and the rest of the workspace between frames.
struct WorkspaceUi {
    bool showPanels = true;       ///< Tab hides the side bar (and its strip)
    bool collapsed = false;       ///< the side bar is the thin strip
    bool collapseChosen = false;  ///< << or >> was clicked: a narrow window no longer decides
    bool sidebarDragged = false;  ///< the user set the width (its edge): no longer automatic
    /// The framebuffer width the window opened with when the viewer sized it for the scene
    /// beside the full side bar (−1: the first frame sets it; 0: none, or resized since): at
    /// that width the side bar keeps its full width and stays open.
    int keepWidthAt = 0;
    bool keepSidebar = false;     ///< this frame: the opening layout is kept (keepWidthAt)
    int sidebarWidth = 0;         ///< pixels when open; 0 until the first frame sets the default
    bool sidebarSizeSet = false;  ///< the side bar's width must be (re)applied next frame
    float scale = 1.0f;           ///< UI scale: the monitor's content scale, or --ui-scale
    bool scaleChanged = false;    ///< the monitor's scale changed: rebuild fonts and style
    bool help = false;            ///< the keys and mouse overlay shows
    glm::vec2 helpSize{0.0f};     ///< the help's size last frame
    bool helpScrolls = false;     ///< the help did not fit the window (it scrolls)
    bool statsOverlay = true;     ///< the compact stats in the image's corner (S)
    bool fullscreen = false;
    int windowed[4] = {0, 0, 0, 0};  ///< x, y, w, h before going fullscreen
    Notice notice;
    Workspace layout;                                ///< this frame's side bar and image area
    SidebarState sidebarState = SidebarState::Open;  ///< this frame's (a narrow window collapses)
    Backdrop backdrop;  ///< the side bar's background, left to GlFrame (empty: ImGui draws it)
    std::map<std::string, Rect> drawn;  ///< windows drawn this frame, by name (for --state)
};

/// Lays out side bar and image area for the window, prepares the frame's camera for the image
/// area and places the frame in it (App::view). Called before and after the panels.
void placeFrame(App& app);

/// Remembers where the current ImGui window went this frame (call inside its Begin/End), for
/// the --state file.
void noteWindow(WorkspaceUi& work, const char* name);

/// Side bar (or its collapsed strip), the overlays (stats, help, notice, light marker, Compare
/// labels and colour bar), the ground-truth table's window, the inspector and the pop-ups.
void drawPanels(App& app);

/// Shows `text` over the image for kNoticeSeconds.
void showNotice(WorkspaceUi& work, const std::string& text);

}  // namespace facet::view
