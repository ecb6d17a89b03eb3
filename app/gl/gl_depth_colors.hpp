#pragma once
// The Depth shader's second pass on the CPU after readback, as the engine runs it after
// drawing: the visible depth range mapped through viridis (near dark, far bright). A post-
// process over the finished frame, so it runs on the twin's readback like on the engine's.

#include <span>

#include "facet/framebuffer.hpp"

namespace facet::gl {

/// Smallest and largest finite depth found (both 0 when none).
struct DepthRange {
    float nearest = 0.0f;
    float farthest = 0.0f;
};

/// Colours the pixels twin.frag marked (alpha 0: the Depth shader's fragments that nothing
/// drew over) by their depth in frame.depth, over the range of `rangeDepth` (the depth before
/// the normals display, which the engine also leaves out of the range).
DepthRange colorDepth(Framebuffer& frame, std::span<const float> rangeDepth);

}  // namespace facet::gl
