#pragma once
// The window-side state of the workspace (side bar, overlays, fullscreen, UI scale, the key
// actions waiting for the next frame, a light drag) and the functions that lay it out and draw
// it. The arithmetic lives in viewer_core (workspace.hpp, key_map.hpp, light_marker.hpp); this
// is the ImGui and GLFW side.

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "key_map.hpp"
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

/// A drag that moves the light.
enum class LightDrag {
    None,
    Follow,  ///< the marker follows the pointer
    Turn,    ///< Ctrl + drag: the light turns around the look-at point
};

/// Side bar, overlays and the rest of the workspace between frames.
struct WorkspaceUi {
    bool collapsed = false;       ///< the side bar is the thin strip (Tab hides it: UiState)
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
    bool lightMarker = true;      ///< the light's marker in the picture, when lighting is on (M)
    bool fullscreen = false;
    int windowed[4] = {0, 0, 0, 0};       ///< x, y, w, h before going fullscreen
    bool accuracyTable = false;           ///< the ground-truth table's window is open
    std::uint64_t accuracyTableSeen = 0;  ///< reports for which the table opened by itself
    std::vector<Action> actions;          ///< keys pressed since the last frame, in order
    bool quitAsked = false;    ///< the quit question is open: the next Ctrl+Q or close quits
    bool quitPending = false;  ///< the quit question opens in the next frame
    Notice notice;
    LightDrag lightDrag = LightDrag::None;
    std::string markerNote;  ///< the words beside an off-screen light's marker, this frame
    Rect markerNoteRect;     ///< where they are drawn (window pixels), empty when none
    Workspace layout;        ///< this frame's side bar and image area
    SidebarState sidebarState = SidebarState::Open;  ///< this frame's (a narrow window collapses)
    Backdrop backdrop;  ///< the side bar's background, left to GlFrame (empty: ImGui draws it)
    std::map<std::string, Rect> drawn;  ///< windows drawn this frame, by name (for --state)
};

/// Lays out side bar and image area for the window, prepares the frame's camera for the image
/// area and places the frame in it (App::view). Called before and after the panels.
void placeFrame(App& app);

/// Remembers where the current ImGui window went this frame (call inside its Begin/End), for
/// the --state file.
void noteWindow(App& app, const char* name);

/// Side bar (or its collapsed strip), the overlays (stats, help, notice, light marker, Compare
/// labels and colour bar), the ground-truth table's window and the error popup.
void drawPanels(App& app);

/// The key actions queued since the last frame; call after ImGui::NewFrame().
void applyActions(App& app);

/// Starts a light drag when the left button went down over the marker (or with Ctrl); true
/// when it did, and the press is the light's.
bool startLightDrag(App& app);

/// Moves the light during a drag by this frame's pointer; ends the drag on release.
void dragLightStep(App& app);

/// Draws the light's marker over the frame.
void drawLightMarker(App& app);

/// Where the light's marker is drawn, in frame pixels (its projection, or on the frame's border
/// when the light is off-screen).
glm::dvec2 lightMarkerPlace(const App& app);

/// Whether the marker shows: turned on and lighting on.
bool lightMarkerShown(const App& app);

/// The light's homogeneous position in the scene (one place to change when Scene changes).
glm::dvec4& lightPosition(App& app);
const glm::dvec4& lightPosition(const App& app);

/// Shows `text` over the image for kNoticeSeconds.
void showNotice(App& app, const std::string& text);

/// Fonts and widget sizes for `scale`; `rebuild` when the GL backend already made its font
/// texture. Pop-ups and windows are opaque.
void applyUiStyle(float scale, bool rebuild);

/// The UI scale of the window: --ui-scale when given, else its monitor's content scale
/// (glfwGetWindowContentScale) over the framebuffer's scale, within 0.5…4.
float windowUiScale(const App& app);

/// Ctrl+Q or the window's close button: quits, or first asks once when the scene has unsaved
/// changes (ViewerModel::unsaved).
void askToQuit(App& app);

/// The question askToQuit opens: save and quit, quit without saving, or cancel (Esc).
void quitPopup(App& app);

/// Fullscreen on the monitor under the window, or back to the window it was.
void toggleFullscreen(App& app);

/// The workspace lines of the --state file: window, side bar, view, overlays, UI scale,
/// notice, screenshot folder, light marker.
std::string workspaceStateText(const App& app);

}  // namespace facet::view
