#pragma once
// Legends drawn into the frame, so a PNG says what its colours mean: the depth shader's
// near/far bar and the debug views' heat-map bars and colour keys. Text uses a built-in 3×5
// pixel font (digits, capital letters, '.', '-', '+', 'e', '/', ':', '(', ')'), so the engine
// needs no font file.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "facet/framebuffer.hpp"

namespace facet {

/// One label under a legend bar, centred on position t in [0, 1] along it (kept inside it).
struct LegendTick {
    double t = 0.0;
    std::string text;

    /// Every field equal.
    bool operator==(const LegendTick&) const = default;
};

/// A viridis bar with labels: continuous (bands = 0) or in `bands` equal steps coloured
/// viridis(k / (bands − 1)), for counts.
struct LegendBar {
    std::string title;  ///< drawn above the bar; empty: no title line
    int bands = 0;      ///< 0: continuous; N: N equal bands
    std::vector<LegendTick> ticks;

    /// Every field equal.
    bool operator==(const LegendBar&) const = default;
};

/// One coloured square and what it means.
struct LegendSwatch {
    std::uint32_t rgba = 0;  ///< packed as Framebuffer::color
    std::string text;

    /// Every field equal.
    bool operator==(const LegendSwatch&) const = default;
};

/// Frame pixels per font pixel for a legend on a frame `height` pixels tall: 1 below 400, 2
/// below 900, 3 above, so the text stays readable when the viewer shows a large frame.
int legendScale(int height);

/// Draws `bar` in a black box in the bottom-left corner, `scale` frame pixels per font pixel.
/// Does nothing if the frame is under 64×32.
void drawLegend(Framebuffer& frame, const LegendBar& bar, int scale);

/// Draws the swatches, one row each under `title`, in a black box in the bottom-left corner.
/// Does nothing if the frame is under 64×32.
void drawLegend(Framebuffer& frame, std::string_view title,
                const std::vector<LegendSwatch>& swatches, int scale);

/// Draws the legend in the bottom-left corner: near (dark) on the left, far (bright) on the
/// right, each labelled with its value in 4 significant digits. Does nothing if the frame is
/// too small to hold it (under 64×32) or the range is not finite.
void drawDepthLegend(Framebuffer& frame, float depthNear, float depthFar);

}  // namespace facet
