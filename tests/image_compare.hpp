#pragma once
// Fast path against reference: the one comparison every accuracy test uses.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>

#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/settings.hpp"

namespace facet::test {

/// Counts over the pixels where the reference is not ambiguous.
struct Comparison {
    std::size_t compared = 0;         ///< pixels outside the ambiguity mask
    std::size_t covered = 0;          ///< of those, pixels the reference drew
    std::size_t ambiguous = 0;        ///< pixels the reference flags as rounding-dependent
    std::size_t coverageDiffers = 0;  ///< drawn in one image only
    std::size_t offByOne = 0;         ///< covered in both, largest channel difference exactly 1
    int maxColorDiff = 0;             ///< largest channel difference where coverage agrees
    std::string examples;             ///< the first few offending pixels, for failure messages
};

/// Largest per-channel difference of two packed RGBA pixels, in 8-bit steps.
inline int channelDiff(std::uint32_t a, std::uint32_t b) {
    int worst = 0;
    for (int shift = 0; shift < 24; shift += 8) {
        const int ca = static_cast<int>((a >> shift) & 0xFF);
        const int cb = static_cast<int>((b >> shift) & 0xFF);
        worst = std::max(worst, std::abs(ca - cb));
    }
    return worst;
}

/// #RRGGBB of a packed pixel.
inline std::string hex(std::uint32_t rgba) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "#%02X%02X%02X", rgba & 0xFF, (rgba >> 8) & 0xFF,
                  (rgba >> 16) & 0xFF);
    return buf;
}

/// Compares a fast-path frame with a reference image of the same size. Coverage is judged by
/// depth for depth-tested shaders and by colour against the background for Simple, which never
/// writes depth.
inline Comparison compare(const Framebuffer& fast, const reference::Image& ref, ShaderKind shader,
                          std::uint32_t backgroundHex) {
    Comparison c;
    const std::vector<std::uint32_t> refRgba = ref.toRgba();
    const std::uint32_t background = rgbaFromHex(backgroundHex);
    const bool byColour = shader == ShaderKind::Simple;
    std::ostringstream examples;
    int shown = 0;
    for (std::size_t i = 0; i < refRgba.size() && i < fast.color.size(); ++i) {
        if (ref.ambiguous[i]) {
            ++c.ambiguous;
            continue;
        }
        ++c.compared;
        const bool refCovered = byColour ? refRgba[i] != background : std::isfinite(ref.depth[i]);
        const bool fastCovered =
            byColour ? fast.color[i] != background : std::isfinite(fast.depth[i]);
        const int diff = channelDiff(refRgba[i], fast.color[i]);
        c.covered += refCovered ? 1 : 0;
        if (refCovered != fastCovered) {
            ++c.coverageDiffers;
        } else {
            c.maxColorDiff = std::max(c.maxColorDiff, diff);
            c.offByOne += diff == 1 ? 1 : 0;
        }
        if ((refCovered != fastCovered || diff > 1) && shown < 8) {
            ++shown;
            const auto w = static_cast<std::size_t>(ref.width);
            examples << "\n  pixel (" << i % w << "," << i / w << "): ref " << hex(refRgba[i])
                     << " depth " << ref.depth[i] << ", fast " << hex(fast.color[i]) << " depth "
                     << fast.depth[i];
        }
    }
    c.examples = examples.str();
    return c;
}

}  // namespace facet::test
