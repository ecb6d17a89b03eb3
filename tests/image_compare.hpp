#pragma once
// Fast path against reference: the comparison every accuracy test uses.

#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/settings.hpp"

namespace facet::test {

/// Counts over the pixels where the reference is not ambiguous.
struct Comparison {
    std::size_t compared = 0;         ///< pixels outside the ambiguity mask
    std::size_t ambiguous = 0;        ///< pixels the reference flags as rounding-dependent
    std::size_t coverageDiffers = 0;  ///< covered in one image only
    int maxColorDiff = 0;             ///< largest channel difference in 8-bit steps
    std::size_t colorDiffers = 0;     ///< pixels with any channel difference > 1
};

/// Compares a fast-path frame with a reference image of the same size. Coverage is judged by
/// depth for depth-tested shaders and by colour against the background for Simple.
inline Comparison compare(const Framebuffer& fb, const reference::Image& ref, ShaderKind shader,
                          std::uint32_t backgroundHex) {
    Comparison c;
    const std::vector<std::uint32_t> refRgba = ref.toRgba();
    const std::uint32_t bg = rgbaFromHex(backgroundHex);
    for (std::size_t i = 0; i < fb.color.size(); ++i) {
        if (ref.ambiguous[i]) {
            ++c.ambiguous;
            continue;
        }
        ++c.compared;
        bool fastCovered, refCovered;
        if (shader == ShaderKind::Simple) {
            fastCovered = fb.color[i] != bg;
            refCovered = refRgba[i] != bg;
        } else {
            fastCovered = fb.depth[i] != kEmptyDepth;
            refCovered = std::isfinite(ref.depth[i]);
        }
        if (fastCovered != refCovered && shader != ShaderKind::Simple) {
            ++c.coverageDiffers;
            continue;
        }
        int worst = 0;
        for (int k = 0; k < 3; ++k) {
            const int a = static_cast<int>((fb.color[i] >> (8 * k)) & 0xFF);
            const int r = static_cast<int>((refRgba[i] >> (8 * k)) & 0xFF);
            worst = std::max(worst, std::abs(a - r));
        }
        c.maxColorDiff = std::max(c.maxColorDiff, worst);
        c.colorDiffers += worst > 1;
        // With Simple a fragment the colour of the background is indistinguishable from none,
        // so coverage is checked through the colour difference itself.
        if (shader == ShaderKind::Simple && fastCovered != refCovered && worst > 1)
            ++c.coverageDiffers;
    }
    return c;
}

}  // namespace facet::test
