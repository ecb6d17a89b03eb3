#pragma once
// A fast-path frame against the reference image of the same input, judged only where the
// reference says a correct fast path must agree (outside its ambiguity mask): the numbers the
// stability sweeps chart and their tests assert. Same rules as tests/image_compare.hpp's
// test::compare (coverage by depth, or by colour for the Simple shader), plus the totals a
// chart needs (covered pixels in each image, NaN depth).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/settings.hpp"

namespace facet::app {

/// What a frame-against-reference comparison found.
struct ReferenceDiff {
    std::size_t pixels = 0;           ///< pixels compared (the smaller image's count)
    std::size_t ambiguous = 0;        ///< pixels the reference flags as rounding-dependent
    std::size_t fastCovered = 0;      ///< pixels the fast frame drew, ambiguous ones included
    std::size_t refCovered = 0;       ///< pixels the reference drew, ambiguous ones included
    std::size_t coverageDiffers = 0;  ///< outside the ambiguity mask, drawn in one image only
    int maxColorDiff = 0;      ///< largest channel difference (8-bit steps) where coverage agrees
    std::size_t nanDepth = 0;  ///< NaN depth values in the fast frame (must be none)
};

/// The sweep tables' columns for a ReferenceDiff: fast_covered, ref_covered, ambiguous,
/// coverage_diff, max_color_diff, nan_depth.
std::vector<std::string> referenceDiffColumns();

/// The cells of those columns for `d`.
std::vector<std::string> referenceDiffCells(const ReferenceDiff& d);

/// Compares `fast` with `ref`. Coverage is judged by depth (finite: drawn) for depth-tested
/// shaders and by colour against the background for Simple, which never writes depth.
ReferenceDiff compareWithReference(const Framebuffer& fast, const reference::Image& ref,
                                   ShaderKind shader, std::uint32_t backgroundHex);

}  // namespace facet::app
