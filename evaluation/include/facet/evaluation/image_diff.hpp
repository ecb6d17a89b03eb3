#pragma once
// Per-pixel comparison of two frames: the numbers and the heat map behind the viewer's Compare
// panel (affine against perspective-correct, say), and the histogram of differences the twin's
// tests bound.

#include <array>
#include <cstddef>
#include <cstdint>

#include "facet/framebuffer.hpp"

namespace facet {

/// What a comparison found. Errors are in 8-bit steps (0..255).
struct ImageDiff {
    bool sameSize = true;             ///< false: nothing was compared, every count is 0
    std::size_t pixels = 0;           ///< pixels compared
    std::size_t pixelsDiffering = 0;  ///< pixels whose error is above 0
    double meanError = 0.0;           ///< mean error over every compared pixel
    int maxError = 0;                 ///< largest error of any pixel
};

/// Error of one pixel: the largest absolute difference of its R, G and B bytes (alpha ignored).
int pixelError(std::uint32_t a, std::uint32_t b);

/// Which pixels a comparison counts and averages over.
enum class DiffPixels {
    all,     ///< every pixel of the frame
    covered  ///< those either frame drew: a fragment in either depth plane, or a colour that
             ///< differs (drawn without depth: normals, a legend); every pixel without depth planes
};

/// Compares the colour planes of two frames. `over` picks the pixels `pixels` counts and
/// `meanError` averages over; the maximum and the differing pixels are the whole frame's (no
/// uncovered pixel differs). When `heat` is given it becomes a frame of the same
/// size showing each pixel's error: black where the pixels are equal, else viridis over
/// error / scale (dark purple for small errors, yellow at `scale` and above); `scale` <= 0 means
/// the largest error found, so any difference is visible. Its depth plane is left as is.
ImageDiff diffImages(const Framebuffer& a, const Framebuffer& b, Framebuffer* heat = nullptr,
                     int scale = 0, DiffPixels over = DiffPixels::all);

/// How many pixels have each error (pixelError, 0..255): for bounds on the tail of the errors,
/// not only their largest.
struct DiffHistogram {
    std::array<std::size_t, 256> count{};  ///< pixels by error
    std::size_t total = 0;                 ///< pixels counted

    /// Counts one pixel of error `error` (0..255).
    void add(int error);
    /// The smallest error at or below which lie `fraction` (0..1) of the pixels; 0 when empty.
    int percentile(double fraction) const;
    /// The largest error counted; 0 when empty.
    int max() const;
    /// Pixels whose error is above `error`.
    std::size_t above(int error) const;
    /// above(error) as a share of the pixels counted (of 1 when none were).
    double shareAbove(int error) const;
};

}  // namespace facet
