#pragma once
// Where the frame sits in the window: a letterboxed rectangle that never distorts the aspect,
// and the mapping from window points to frame pixels (for pan speed and the Compare divider).

#include <cstdint>

#include <glm/vec2.hpp>

namespace facet::view {

/// A rectangle in window pixels, origin at the top left.
struct Rect {
    int x = 0;
    int y = 0;
    int w = 0;
    int h = 0;
};

/// A rectangle of one opaque colour under the panels (window pixels, top-left origin; empty:
/// none): the side bar's background, which GlFrame fills with a clear because llvmpipe would
/// shade ImGui's quad for it pixel by pixel, blending included (a third of the panels' cost).
struct Backdrop {
    Rect rect;
    std::uint32_t rgba = 0;  ///< bytes R, G, B, A (packRgba's order); alpha ignored
};

/// The largest rectangle of the frame's aspect centred in the area (integer pixels, at least
/// 1×1 when the area is non-empty). A frame of the area's size fills it exactly.
Rect letterbox(int frameWidth, int frameHeight, int areaWidth, int areaHeight);

/// Continuous frame pixel coordinates of a window point shown in `view` (may lie outside).
glm::dvec2 windowToFrame(const Rect& view, int frameWidth, int frameHeight, glm::dvec2 point);

/// Frame pixels per window pixel in `view` (1 when the frame is shown 1:1).
double frameScale(const Rect& view, int frameWidth);

}  // namespace facet::view
