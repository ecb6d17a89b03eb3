#pragma once
// The whole-frame passes around a draw: the clear before it and the depth shader's colouring
// after it. Both split the frame into row bands over the threads.

#include <cstdint>

#include "facet/colormap.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "shading/fragment.hpp"

namespace facet::detail {

/// Fills colour with `rgba` and depth with kEmptyDepth.
void clearFrame(Framebuffer& fb, std::uint32_t rgba, int threads);

/// The depth shader's colour of a drawn pixel at `depth`, the frame's visible range being
/// [lo, hi]: viridis from near (dark) to far (bright).
inline std::uint32_t depthColor(float depth, float lo, float hi) {
    const double range = hi > lo ? static_cast<double>(hi) - lo : 1.0;
    return packColor(glm::vec3(viridis((depth - static_cast<double>(lo)) / range)));
}

/// The depth shader's second pass: the visible depth range mapped through viridis (near dark,
/// far bright); records the range in `stats`.
void resolveDepthColors(Framebuffer& fb, RenderStats& stats, int threads);

}  // namespace facet::detail
