#pragma once
// A frame against the reference image of the same input, judged only where the reference says
// a correct renderer must agree (outside its ambiguity mask): the rules fast_vs_reference_test,
// near_plane_test, stability_test and gl_twin_test assert and `facet sweeps` charts, and the
// error interp_accuracy_test bounds. A correct fast path draws exactly the reference's pixels
// there (no coverage difference) with colours within 1 LSB.

#include <cstddef>
#include <cstdint>
#include <string>

#include "facet/evaluation/image_diff.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/settings.hpp"

namespace facet {

/// What a frame-against-reference comparison found. Coverage is judged by depth (finite:
/// drawn) for depth-tested shaders and by colour against the background for Simple, which never
/// writes depth.
struct ReferenceDiff {
    std::size_t pixels = 0;           ///< pixels looked at (the smaller image's count)
    std::size_t ambiguous = 0;        ///< pixels the reference flags as rounding-dependent
    std::size_t compared = 0;         ///< pixels outside the ambiguity mask
    std::size_t comparedCovered = 0;  ///< of those, pixels the reference drew
    std::size_t fastCovered = 0;      ///< pixels the frame drew, ambiguous ones included
    std::size_t refCovered = 0;       ///< pixels the reference drew, ambiguous ones included
    std::size_t coverageDiffers = 0;  ///< outside the ambiguity mask, drawn in one image only
    int maxColorDiff = 0;      ///< largest channel difference (8-bit steps) where coverage agrees
    std::size_t offByOne = 0;  ///< coverage agrees and the largest channel difference is exactly 1
    std::size_t nanDepth = 0;  ///< NaN depth values in the frame (must be none)
    std::string examples;      ///< the first few offending pixels, one a line, for test messages
};

/// Compares `frame` with `ref`. With `drawnInBoth`, also counts the error (pixelError) of each
/// pixel outside the mask that both images drew.
ReferenceDiff compareWithReference(const Framebuffer& frame, const reference::Image& ref,
                                   ShaderKind shader, std::uint32_t backgroundHex,
                                   DiffHistogram* drawnInBoth = nullptr);

/// The frame's error against the reference's own 8-bit picture over the pixels the reference
/// drew (finite depth: depth-tested shaders) and does not flag ambiguous; interiorRmse is not
/// filled.
ImageError errorAgainstReference(const Framebuffer& frame, const reference::Image& ref);

}  // namespace facet
