// A frame against the reference (reference_compare.hpp).

#include "facet/evaluation/reference_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

namespace facet {
namespace {

/// Failure messages name this many offending pixels at most.
constexpr int kExamples = 8;

}  // namespace

ReferenceDiff compareWithReference(const Framebuffer& frame, const reference::Image& ref,
                                   ShaderKind shader, std::uint32_t backgroundHex,
                                   DiffHistogram* drawnInBoth) {
    ReferenceDiff d;
    const std::vector<std::uint32_t> refRgba = ref.toRgba();
    const std::uint32_t background = rgbaFromHex(backgroundHex);
    const bool byColour = shader == ShaderKind::Simple;
    // NaN depth anywhere is a failure on its own, even outside the compared area.
    for (float z : frame.depth) d.nanDepth += std::isnan(z) ? 1 : 0;
    const std::size_t n = std::min({refRgba.size(), frame.color.size(), frame.depth.size()});
    d.pixels = n;
    std::ostringstream examples;
    int shown = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const bool refCovered = byColour ? refRgba[i] != background : std::isfinite(ref.depth[i]);
        // NaN compares as "not finite", so a NaN pixel counts as not drawn: it shows up as a
        // coverage difference wherever the reference drew, besides in nanDepth.
        const bool fastCovered =
            byColour ? frame.color[i] != background : std::isfinite(frame.depth[i]);
        d.refCovered += refCovered ? 1 : 0;
        d.fastCovered += fastCovered ? 1 : 0;
        if (ref.ambiguous[i]) {
            ++d.ambiguous;
            continue;
        }
        ++d.compared;
        d.comparedCovered += refCovered ? 1 : 0;
        const int diff = pixelError(refRgba[i], frame.color[i]);
        if (refCovered != fastCovered) {
            ++d.coverageDiffers;
        } else {
            d.maxColorDiff = std::max(d.maxColorDiff, diff);
            d.offByOne += diff == 1 ? 1 : 0;
            if (drawnInBoth && refCovered) drawnInBoth->add(diff);
        }
        if ((refCovered != fastCovered || diff > 1) && shown < kExamples) {
            ++shown;
            const auto w = static_cast<std::size_t>(ref.width);
            examples << "\n  pixel (" << i % w << "," << i / w << "): ref "
                     << hexFromRgba(refRgba[i]) << " depth " << ref.depth[i] << ", frame "
                     << hexFromRgba(frame.color[i]) << " depth " << frame.depth[i];
        }
    }
    d.examples = examples.str();
    return d;
}

ImageError errorAgainstReference(const Framebuffer& frame, const reference::Image& ref) {
    const std::vector<std::uint32_t> refRgba = ref.toRgba();
    const std::size_t n = std::min(refRgba.size(), frame.color.size());
    std::vector<std::uint8_t> include(n);
    for (std::size_t i = 0; i < n; ++i)
        include[i] = std::isfinite(ref.depth[i]) && !ref.ambiguous[i] ? 1 : 0;
    return measureError(std::span(frame.color).first(n),
                        std::span<const std::uint32_t>(refRgba).first(n), include);
}

}  // namespace facet
