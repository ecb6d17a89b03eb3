#pragma once
// What the scalar and span loops share about spans: which triangles take the span loop, and a
// row's covered pixels found exactly from the integer edge functions. The span loop itself is
// span_loop-inl.hpp, compiled once per SIMD target (pipeline/span_targets.cpp).

#include <algorithm>
#include <cstdint>

#include "shading/fragment.hpp"

namespace facet::detail {

/// Boxes narrower than this take the scalar loop: a dense mesh's small triangles cover one to
/// three pixels per row, too few to fill the lanes or to pay for the span's divisions.
inline constexpr int kNarrowBox = 16;

/// Whether variant V has a span loop: affine or perspective, without derivatives.
template <class V>
inline constexpr bool kHasSpanLoop = V::kInterp != Interp::Subdivided && !V::kDerivatives;

/// The covered pixels [lo, hi] of a row whose edge values at pixel x0 are e[i] (steps stepX[i]
/// per pixel), within [x0, x1]; false when none. Exact: E(x) ≥ 0 solved in integers per edge.
inline bool coveredSpan(const std::int64_t (&e)[3], const std::int64_t (&stepX)[3], int x0, int x1,
                        int& lo, int& hi) {
    const std::int64_t width = x1 - x0;
    std::int64_t first = 0, last = width;
    for (int i = 0; i < 3; ++i) {
        const std::int64_t v = e[i], s = stepX[i];
        if (s == 0) {
            if (v < 0) return false;
        } else if (s > 0) {  // rising: inside from k ≥ ceil(−v / s)
            if (v < 0) first = std::max(first, (-v + s - 1) / s);
        } else {  // falling: inside up to k ≤ floor(v / −s)
            if (v < 0) return false;
            last = std::min(last, v / -s);
        }
    }
    if (first > last) return false;
    lo = x0 + static_cast<int>(first);
    hi = x0 + static_cast<int>(last);
    return true;
}

}  // namespace facet::detail
