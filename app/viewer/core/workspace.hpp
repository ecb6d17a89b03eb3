#pragma once
// The viewer's workspace: a side bar for the panels at the left and the image area beside it,
// where the frame is drawn and nothing else is laid out (only the small overlays the user asks
// for: stats, help, light marker). Pure arithmetic on window pixels, so tests check that the
// panels and the frame never overlap at any size.

#include "layout.hpp"

namespace facet::view {

/// How the side bar shows.
enum class SidebarState {
    Open,       ///< full width, panels inside
    Collapsed,  ///< a thin strip with the button that opens it again
    Hidden,     ///< gone (Tab): the image area is the whole window
};

/// Side bar widths at a UI scale of 1 (multiplied by the monitor's content scale).
inline constexpr int kSidebarWidth = 380;
inline constexpr int kSidebarMinWidth = 260;
inline constexpr int kSidebarCollapsedWidth = 32;  // ImGui's least window width
/// The image area never gets narrower than this share of the window when the bar is dragged.
inline constexpr double kMinImageShare = 0.3;

/// Until the user drags its edge, the side bar takes at most this share of the window's width
/// (never less than kSidebarMinWidth): a small window keeps most of its area for the picture.
inline constexpr double kSidebarShare = 0.34;

/// Below this window width (at a UI scale of 1) the side bar starts collapsed to its strip.
inline constexpr int kCollapseBelow = 640;

/// The side bar's width before the user drags it: kSidebarWidth·scale, narrowed to
/// kSidebarShare of a smaller window, never under kSidebarMinWidth·scale.
int autoSidebarWidth(int windowWidth, double scale);

/// True when a window this wide starts with the side bar collapsed (kCollapseBelow).
bool autoCollapsed(int windowWidth, double scale);

/// Where the side bar and the image area are in a window.
struct Workspace {
    Rect sidebar;  ///< empty when hidden
    Rect image;    ///< the rest of the window
};

/// The side bar's width as it can be: at least kSidebarMinWidth·scale, and leaving at least
/// kMinImageShare of the window to the image (the image's share wins in a tiny window: the
/// frame never disappears).
int clampSidebarWidth(int width, int windowWidth, double scale);

/// Side bar at the left, `sidebarWidth` wide when open (clamped by clampSidebarWidth), the
/// collapsed strip kSidebarCollapsedWidth·scale wide, nothing when hidden; the image area is
/// what is left (never negative).
Workspace workspaceLayout(int windowWidth, int windowHeight, int sidebarWidth, SidebarState state,
                          double scale);

/// The frame's place: letterboxed (aspect kept) and centred in the image area, window pixels.
Rect frameRect(const Workspace& workspace, int frameWidth, int frameHeight);

/// The window size to open with, and the image area it leaves.
struct OpeningSize {
    int width = 0;  ///< window (client area) size
    int height = 0;
    int imageWidth = 0;  ///< image area: the scene's size, or scaled down to fit
    int imageHeight = 0;
    bool scaled = false;  ///< the scene did not fit the work area: the frame is shown smaller
};

/// The window that holds the scene's frame at its size beside the side bar, within a work area
/// (the monitor's, minus the window's decorations). When it does not fit, the image area is the
/// scene's size scaled down uniformly (aspect kept) until window and all fit; a work area of 0
/// means "unknown" and puts no cap.
OpeningSize openingSize(int sceneWidth, int sceneHeight, int sidebarWidth, int workWidth,
                        int workHeight);

/// True when the two rectangles share at least one pixel.
bool overlaps(const Rect& a, const Rect& b);

/// A w×h rectangle in a corner of `area`, `margin` pixels in from both edges.
enum class Corner { TopLeft, TopRight, BottomLeft, BottomRight };
Rect cornerRect(const Rect& area, int w, int h, Corner corner, int margin);

}  // namespace facet::view
