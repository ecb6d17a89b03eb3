#pragma once
// Bresenham lines between integer pixels, with every pixel's step index so attributes can be
// interpolated along the line. Steep lines step along y: the course's routine interpolated them
// on the transposed pixel and its colours collapsed to one end (spec §8).
//
// Pixel k of n has major coordinate start + k·sign and minor coordinate
// m0 + floor((2·k·dm + n) / (2·n)): round to nearest, ties towards +inf. The loop below is the
// incremental form of that formula, entered directly at the first pixel inside the image so that
// a line crossing a huge guard band costs only its visible pixels.

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace facet::detail {

__extension__ using Int128 = __int128;

/// Calls visit(x, y, k, n) for the pixels of the line (x0,y0)-(x1,y1), endpoints included, that
/// lie inside [0,width) × [0,height). n is the step count (0 for a one-pixel line).
template <class Visit>
inline void forEachLinePixel(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1,
                             int width, int height, Visit&& visit) {
    const std::int64_t dx = x1 - x0;
    const std::int64_t dy = y1 - y0;
    const std::int64_t n = std::max(std::llabs(dx), std::llabs(dy));
    if (n == 0) {
        if (x0 >= 0 && x0 < width && y0 >= 0 && y0 < height)
            visit(static_cast<int>(x0), static_cast<int>(y0), std::int64_t{0}, std::int64_t{0});
        return;
    }
    const bool xMajor = std::llabs(dx) >= std::llabs(dy);
    const std::int64_t major0 = xMajor ? x0 : y0;
    const std::int64_t minor0 = xMajor ? y0 : x0;
    const std::int64_t dMajor = xMajor ? dx : dy;
    const std::int64_t dMinor = xMajor ? dy : dx;
    const std::int64_t majorLimit = xMajor ? width : height;
    const std::int64_t minorLimit = xMajor ? height : width;
    const std::int64_t sign = dMajor > 0 ? 1 : -1;

    // Steps whose major coordinate is inside the image.
    std::int64_t kLo = sign > 0 ? -major0 : major0 - (majorLimit - 1);
    std::int64_t kHi = sign > 0 ? majorLimit - 1 - major0 : major0;
    kLo = std::max<std::int64_t>(kLo, 0);
    kHi = std::min<std::int64_t>(kHi, n);
    if (kLo > kHi) return;

    // Minor offset q and remainder r of (2·k·dm + n) / (2n) at k = kLo, then stepped.
    const Int128 twoN = Int128{2} * n;
    const Int128 num = Int128{2} * kLo * dMinor + n;
    Int128 q = num / twoN;
    Int128 r = num % twoN;
    if (r < 0) {  // C++ division truncates; the formula wants floor
        r += twoN;
        q -= 1;
    }
    const Int128 step = Int128{2} * dMinor;
    for (std::int64_t k = kLo; k <= kHi; ++k) {
        const std::int64_t major = major0 + sign * k;
        const std::int64_t minor = minor0 + static_cast<std::int64_t>(q);
        if (minor >= 0 && minor < minorLimit) {
            const auto px = static_cast<int>(xMajor ? major : minor);
            const auto py = static_cast<int>(xMajor ? minor : major);
            visit(px, py, k, n);
        }
        r += step;
        if (r >= twoN) {
            r -= twoN;
            q += 1;
        } else if (r < 0) {
            r += twoN;
            q -= 1;
        }
    }
}

}  // namespace facet::detail
