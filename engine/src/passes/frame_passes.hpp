#pragma once
// The whole-frame passes around a draw: the clear before it and the depth shader's colouring
// after it. Both split the frame into row bands over the threads.

#include <cstddef>
#include <cstdint>

#include "facet/colormap.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "shading/fragment.hpp"

namespace facet::detail {

/// Fills colour with `rgba` and depth with kEmptyDepth.
void clearFrame(Framebuffer& fb, std::uint32_t rgba, int threads);

/// clearFrame() of the pixels [begin, end) of `fb` (indices into both planes), on this thread.
void clearPixels(Framebuffer& fb, std::uint32_t rgba, std::size_t begin, std::size_t end);

/// The depth shader's second pass: the visible depth range mapped through viridis (near dark,
/// far bright); records the range in `stats`.
void resolveDepthColors(Framebuffer& fb, RenderStats& stats, int threads);

}  // namespace facet::detail
