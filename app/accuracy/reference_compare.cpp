#include "reference_compare.hpp"

#include "sweep_table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace facet::app {

std::vector<std::string> referenceDiffColumns() {
    return {"fast_covered",  "ref_covered",    "ambiguous",
            "coverage_diff", "max_color_diff", "nan_depth"};
}

std::vector<std::string> referenceDiffCells(const ReferenceDiff& d) {
    return {cell(static_cast<double>(d.fastCovered)),
            cell(static_cast<double>(d.refCovered)),
            cell(static_cast<double>(d.ambiguous)),
            cell(static_cast<double>(d.coverageDiffers)),
            cell(d.maxColorDiff),
            cell(static_cast<double>(d.nanDepth))};
}
namespace {

/// Largest per-channel difference of two packed RGBA pixels, alpha ignored.
int channelDiff(std::uint32_t a, std::uint32_t b) {
    int worst = 0;
    for (int shift = 0; shift < 24; shift += 8) {
        const int ca = static_cast<int>((a >> shift) & 0xFF);
        const int cb = static_cast<int>((b >> shift) & 0xFF);
        worst = std::max(worst, std::abs(ca - cb));
    }
    return worst;
}

}  // namespace

ReferenceDiff compareWithReference(const Framebuffer& fast, const reference::Image& ref,
                                   ShaderKind shader, std::uint32_t backgroundHex) {
    ReferenceDiff d;
    const std::vector<std::uint32_t> refRgba = ref.toRgba();
    const std::uint32_t background = rgbaFromHex(backgroundHex);
    const bool byColour = shader == ShaderKind::Simple;
    // NaN depth anywhere is a failure on its own, even outside the compared area.
    for (float z : fast.depth) d.nanDepth += std::isnan(z) ? 1 : 0;
    const std::size_t n = std::min({refRgba.size(), fast.color.size(), fast.depth.size()});
    d.pixels = n;
    for (std::size_t i = 0; i < n; ++i) {
        const bool refCovered = byColour ? refRgba[i] != background : std::isfinite(ref.depth[i]);
        // NaN compares as "not finite", so a NaN pixel counts as not drawn: it shows up as a
        // coverage difference wherever the reference drew, besides in nanDepth.
        const bool fastCovered =
            byColour ? fast.color[i] != background : std::isfinite(fast.depth[i]);
        d.refCovered += refCovered ? 1 : 0;
        d.fastCovered += fastCovered ? 1 : 0;
        if (ref.ambiguous[i]) {
            ++d.ambiguous;
            continue;
        }
        if (refCovered != fastCovered)
            ++d.coverageDiffers;
        else
            d.maxColorDiff = std::max(d.maxColorDiff, channelDiff(refRgba[i], fast.color[i]));
    }
    return d;
}

}  // namespace facet::app
