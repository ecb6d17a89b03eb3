#pragma once
// The depth shader's legend: a viridis bar with the near and far depth it spans, drawn into the
// frame so a PNG from `facet render --legend` says what its colours mean. Text uses a built-in
// 3×5 pixel font (digits, '.', '-', '+', 'e'), so the engine needs no font file.

#include <string_view>

#include "facet/framebuffer.hpp"

namespace facet {

/// Draws the legend in the bottom-left corner: near (dark) on the left, far (bright) on the
/// right, each labelled with its value in 4 significant digits. Does nothing if the frame is
/// too small to hold it (under 64×32) or the range is not finite.
void drawDepthLegend(Framebuffer& frame, float depthNear, float depthFar);

}  // namespace facet
