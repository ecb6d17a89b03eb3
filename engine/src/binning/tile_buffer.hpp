#pragma once
// Where the one-sample solid draw writes a tile's pixels, and what it knows of their depth.
// A PixelTarget is either the frame itself or a per-thread tile buffer (64×64 colour and depth,
// contiguous, in L1/L2) that the tile is cleared in, drawn in and written to the frame from once
// (TileRenderer, tiles.cpp). TileDepth is the tile's hierarchical depth: a far bound on every
// depth stored in the tile, lowered by triangles that cover the whole tile, so that a triangle
// wholly behind it is rejected before any of its pixels is visited.

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "coverage/coverage.hpp"
#include "facet/framebuffer.hpp"
#include "frontend/front_end.hpp"

namespace facet::detail {

/// A tile's hierarchical depth: `far` is not below any depth stored in the tile (kEmptyDepth
/// when nothing is known), `rejected` counts the triangle parts it rejected.
struct TileDepth {
    float far = kEmptyDepth;
    std::size_t rejected = 0;
};

/// Pixel (x, y) of the frame at color[index(x, y)] and depth[index(x, y)]: rows `stride` apart
/// from an origin pixel (x0, y0). The frame itself is origin (0, 0) and stride = its width.
struct PixelTarget {
    std::uint32_t* color = nullptr;
    float* depth = nullptr;
    int stride = 0;
    /// y0·stride + x0 of the origin (x0, y0): what index() subtracts.
    std::size_t origin = 0;
    /// The tile these pixels belong to, and its hierarchical depth (null: none, e.g. a draw into
    /// the frame outside the tile renderer).
    PixelRect tile{0, 0, -1, -1};
    TileDepth* bound = nullptr;

    /// The whole frame, without hierarchical depth.
    static PixelTarget frame(Framebuffer& fb) {
        return {fb.color.data(), fb.depth.data(), fb.width, 0, {0, 0, fb.width - 1, fb.height - 1},
                nullptr};
    }
    /// Offset of pixel (x, y) (in the target: x ≥ x0, y ≥ y0), one subtraction more than the
    /// frame's index (unsigned, so y·stride + x below the origin wraps and the sum is exact).
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(stride) +
               static_cast<std::size_t>(x) - origin;
    }
};

/// The range [lo, hi] that every pixel loop's 1/q lies in over `box` (pixel centres, q the depth
/// plane of `p`), with margins for the loops' float rounding (the loops evaluate
/// q0 + q1·dx + q2·dy in a few orders; each is within a few ulps of the sum of the terms'
/// magnitudes): false when q may reach 0 or below there, or is not finite (no bound then).
[[gnu::noinline]] inline bool depthRange(const Planes& p, const PixelRect& box, float& lo,
                                         float& hi) {
    const float dx0 = static_cast<float>(box.x0 - p.baseX),
                dx1 = static_cast<float>(box.x1 - p.baseX);
    const float dy0 = static_cast<float>(box.y0 - p.baseY),
                dy1 = static_cast<float>(box.y1 - p.baseY);
    const float ax0 = p.q[1] * dx0, ax1 = p.q[1] * dx1, ay0 = p.q[2] * dy0, ay1 = p.q[2] * dy1;
    // q is linear: its extremes over the box are at its corners.
    const float qmax = p.q[0] + std::fmax(ax0, ax1) + std::fmax(ay0, ay1);
    const float qmin = p.q[0] + std::fmin(ax0, ax1) + std::fmin(ay0, ay1);
    const float err = 1e-5f * (std::fabs(p.q[0]) + std::fmax(std::fabs(ax0), std::fabs(ax1)) +
                               std::fmax(std::fabs(ay0), std::fabs(ay1)));
    const float q0 = qmin - err, q1 = qmax + err;
    if (!(q0 > 0.0f) || !(q1 < kEmptyDepth)) return false;  // NaN too
    lo = (1.0f / q1) * (1.0f - 1e-5f);
    hi = (1.0f / q0) * (1.0f + 1e-5f);
    return true;
}

/// Whether no pixel of `box` can pass a LESS depth test against a tile whose stored depths are
/// all at most `far`: the nearest depth the triangle's plane takes over the box is not below it.
/// One compare when nothing is known of the tile (far = kEmptyDepth).
[[gnu::always_inline]] inline bool hiddenBehind(const Planes& p, const PixelRect& box, float far) {
    if (!(far < kEmptyDepth)) [[likely]]
        return false;
    float lo = 0.0f, hi = 0.0f;
    return depthRange(p, box, lo, hi) && lo >= far;
}

/// Whether the triangle `s` covers every pixel of its box (its four corners are inside all three
/// edges: the triangle is convex). Out of line: only triangles whose box is a whole tile ask.
[[gnu::noinline]] inline bool coversBox(const CoverageSetup& s) {
    const PixelRect& b = s.box;
    const std::int64_t w = b.x1 - b.x0, h = b.y1 - b.y0;
    for (int i = 0; i < 3; ++i) {
        const std::int64_t e = s.e0[i], x = w * s.stepX[i], y = h * s.stepY[i];
        if ((e | (e + x) | (e + y) | (e + x + y)) < 0) return false;
    }
    return true;
}

/// Whether the triangle `s` covers every pixel of `tile` (its box is the tile and the four
/// corners are inside all three edges: the triangle is convex).
inline bool coversTile(const CoverageSetup& s, const PixelRect& tile) {
    const PixelRect& b = s.box;
    if (b.x0 != tile.x0 || b.y0 != tile.y0 || b.x1 != tile.x1 || b.y1 != tile.y1) return false;
    return coversBox(s);
}

/// After a LESS-tested draw of `s` whose pixels all got `p`'s depth or kept a nearer one: when
/// `s` covers the whole tile, every stored depth is now at most its farthest, the tile's new
/// far bound if lower.
[[gnu::always_inline]] inline void lowerBound(const CoverageSetup& s, const Planes& p,
                                              const PixelRect& tile, TileDepth& bound) {
    if (!coversTile(s, tile)) return;
    float lo = 0.0f, hi = 0.0f;
    if (depthRange(p, s.box, lo, hi) && hi < bound.far) bound.far = hi;
}

}  // namespace facet::detail
