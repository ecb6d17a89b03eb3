#pragma once
// What the scalar and vector loops share: which triangles take the span loop and which the block
// loop, and a row's covered pixels found exactly from the integer edge functions. The vector
// loops themselves are span_loop-inl.hpp, compiled once per SIMD target
// (pipeline/span_targets.cpp).

#include <algorithm>
#include <cstdint>
#include <limits>

#include "shading/fragment.hpp"

namespace facet::detail {

/// Boxes narrower than this take the block loop (or the scalar one): a dense mesh's small
/// triangles cover one to three pixels per row, too few to fill the lanes of a row or to pay
/// for the span's divisions.
inline constexpr int kNarrowBox = 16;

/// Boxes whose width plus height (in pixels) is below this take the scalar loop: a triangle of
/// one to three pixels pays less for a few scalar pixels than for a block's setup and division
/// (measured on a 1M-triangle sphere at 1080p, about two pixels per triangle).
inline constexpr int kTinyBox = 6;

/// Whether variant V has the vector loops (span and block): affine or perspective, without
/// derivatives.
template <class V>
inline constexpr bool kHasSpanLoop = V::kInterp != Interp::Subdivided && !V::kDerivatives;

/// The largest block side of any SIMD target (4×4 pixels on 16 lanes): a box padded to whole
/// blocks reaches at most this many pixels minus one past its last column and row.
inline constexpr int kMaxBlockSide = 4;

/// Whether the block loop can take `s`: its lanes hold edge values in 32-bit integers, so every
/// value it forms over the box padded to whole blocks (block corner plus lane offset) must fit.
/// The bound is the triangle inequality on E(x, y) = e0 + i·stepX + j·stepY, with each of |e0|,
/// |stepX| and |stepY| bounded by the OR of the three edges' (at most twice the largest): a few
/// operations, where the exact maximum per edge cost 70 instructions per triangle. Small
/// triangles pass by orders of magnitude; big ones clipped to a small box may not (then: scalar
/// loop, which gives the same pixels).
///
/// A dense mesh's small triangle passes a shorter test first: every value in [−2^23, 2^23)
/// (one add per value, their OR below 2^24) and a box of at most 254 columns plus rows. That
/// implies the bound below (each OR'ed magnitude + 1 is then at most 2^23, and 2^23 · 255 <
/// 2^31), so the same triangles take the block loop, for about half the instructions.
[[gnu::always_inline]] inline bool fitsBlockLoop(const CoverageSetup& s) {
    constexpr std::uint64_t kSmall = std::uint64_t{1} << 23;
    const auto shifted = [&](std::int64_t v) { return static_cast<std::uint64_t>(v) + kSmall; };
    const std::uint64_t all = shifted(s.e0[0]) | shifted(s.e0[1]) | shifted(s.e0[2]) |
                              shifted(s.stepX[0]) | shifted(s.stepX[1]) | shifted(s.stepX[2]) |
                              shifted(s.stepY[0]) | shifted(s.stepY[1]) | shifted(s.stepY[2]);
    const int extent = s.box.x1 - s.box.x0 + s.box.y1 - s.box.y0 + 2 * kMaxBlockSide;
    static_assert(kSmall * 255 <= std::numeric_limits<std::int32_t>::max());
    if (all < 2 * kSmall && extent <= 254) return true;
    // |v| − 1 for v < 0, |v| otherwise: one's complement, no branch, no overflow at INT64_MIN.
    const auto magnitude = [](std::int64_t v) { return v ^ (v >> 63); };
    const auto largest = [&](const std::int64_t(&v)[3]) {
        return (magnitude(v[0]) | magnitude(v[1]) | magnitude(v[2])) + 1;  // ≥ each |v[i]|
    };
    const std::int64_t e = largest(s.e0), sx = largest(s.stepX), sy = largest(s.stepY);
    constexpr std::int64_t kMax = std::numeric_limits<std::int32_t>::max();
    // Each term first, so that the sum cannot overflow 64 bits (boxes are < 2^16 pixels).
    if ((e | sx | sy) > kMax) return false;
    const std::int64_t columns = s.box.x1 - s.box.x0 + kMaxBlockSide;
    const std::int64_t rows = s.box.y1 - s.box.y0 + kMaxBlockSide;
    return e + columns * sx + rows * sy <= kMax;
}

/// The covered pixels [lo, hi] of a row whose edge values at pixel x0 are e[i] (steps stepX[i]
/// per pixel), within [x0, x1]; false when none. Exact: E(x) ≥ 0 solved in integers per edge.
/// (s · width fits: steps are bounded by the guard band, widths by the image.)
inline bool coveredSpan(const std::int64_t (&e)[3], const std::int64_t (&stepX)[3], int x0, int x1,
                        int& lo, int& hi) {
    const std::int64_t width = x1 - x0;
    std::int64_t first = 0, last = width;
    for (int i = 0; i < 3; ++i) {
        const std::int64_t v = e[i], s = stepX[i];
        if (s == 0) {
            if (v < 0) return false;
        } else if (s > 0) {  // rising: inside from k ≥ ceil(−v / s)
            if (v < 0) {
                if (v + s * width < 0) return false;  // still outside at the row's end
                first = std::max(first, (-v + s - 1) / s);
            }
        } else {  // falling: inside up to k ≤ floor(v / −s)
            if (v < 0) return false;
            // Divided only where the edge leaves the row (a 64-bit division costs tens of
            // cycles; in a large triangle most rows of a tile lie wholly inside most edges).
            if (v + s * width < 0) last = std::min(last, v / -s);
        }
    }
    if (first > last) return false;
    lo = x0 + static_cast<int>(first);
    hi = x0 + static_cast<int>(last);
    return true;
}

}  // namespace facet::detail
