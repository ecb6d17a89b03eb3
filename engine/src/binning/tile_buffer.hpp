#pragma once
// Where the one-sample solid draw writes a tile's pixels, and what it knows of their depth.
// A PixelTarget is either the frame itself or a per-thread tile buffer (64×64 colour and depth,
// contiguous, in L1/L2) that the tile is cleared in, drawn in and written to the frame from once
// (TileRenderer, tiles.cpp). TileDepth is the tile's hierarchical depth: a far bound on every
// depth stored in the tile, lowered by triangles that cover the whole tile, and one per 8×8-pixel
// block, recomputed from the stored depths when a test needs it, so that a triangle wholly behind
// the blocks its box overlaps is rejected before any of its pixels is visited.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "coverage/coverage.hpp"
#include "facet/framebuffer.hpp"
#include "frontend/front_end.hpp"

namespace facet::detail {

/// Pixels on a side of a hierarchical-depth block, and blocks on a side of a tile (64 pixels).
inline constexpr int kDepthBlock = 8;
inline constexpr int kDepthBlocksPerSide = 8;

/// A tile's hierarchical depth: `far` is not below any depth stored in the tile (kEmptyDepth
/// when nothing is known), nor `blockFar[i]` below any stored in block i (row-major, 8 per row,
/// from the tile's corner). A LESS test only lowers stored depths, so a bound stays true however
/// much is drawn after it; bit i of `stale` says block i was drawn in since its bound was
/// computed (a recompute may lower it). `rejected` counts the triangle parts rejected.
struct TileDepth {
    float far = kEmptyDepth;
    std::uint64_t stale = 0;
    int skip = 0;  ///< tests left that pass over stale blocks' recomputes (kRecomputeSkip)
    std::size_t rejected = 0;
    float blockFar[kDepthBlocksPerSide * kDepthBlocksPerSide];
    bool blocks = false;  ///< the blocks' bounds are kept and tested (enableBlockHiZ())

    /// Nothing known; every block stale when `drawnBefore` (the frame was not cleared); the
    /// blocks' bounds kept when `withBlocks`.
    explicit TileDepth(bool drawnBefore = false, bool withBlocks = false)
        : stale(drawnBefore ? ~std::uint64_t{0} : 0), blocks(withBlocks) {
        for (float& f : blockFar) f = kEmptyDepth;
    }
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

/// The blocks (bit i: block i of TileDepth) that `box`, inside `tile`, overlaps.
inline std::uint64_t blockMask(const PixelRect& box, const PixelRect& tile) {
    // The box is inside the tile: the offsets are ≥ 0, unsigned division is a shift.
    const auto block = [](int offset) {
        return static_cast<unsigned>(offset) / unsigned{kDepthBlock};
    };
    const unsigned bx0 = block(box.x0 - tile.x0), bx1 = block(box.x1 - tile.x0);
    const unsigned by0 = block(box.y0 - tile.y0), by1 = block(box.y1 - tile.y0);
    const std::uint64_t columns = (0xFFu >> (7 - bx1)) & (0xFFu << bx0);
    const std::uint64_t rows =
        (~std::uint64_t{0} >> (56 - 8 * by1)) & (~std::uint64_t{0} << (8 * by0));
    return columns * 0x0101010101010101u & rows;
}

/// The largest depth stored in block `i` of `target`'s tile (its pixels inside the tile's
/// rectangle: a block at the frame's edge may be cut). A NaN stored (that no depth passes) is
/// left out. Out of line: only a test that the stale bound would fail asks.
[[gnu::noinline]] inline float blockMaxDepth(const PixelTarget& target, int i) {
    const PixelRect& t = target.tile;
    const int x0 = t.x0 + i % kDepthBlocksPerSide * kDepthBlock;
    const int y0 = t.y0 + i / kDepthBlocksPerSide * kDepthBlock;
    const int x1 = std::min(x0 + kDepthBlock - 1, t.x1), y1 = std::min(y0 + kDepthBlock - 1, t.y1);
    const float* row = target.depth + target.index(x0, y0);
    const auto stride = static_cast<std::size_t>(target.stride);
    float far = -kEmptyDepth;
#if defined(__SSE2__)
    static_assert(kDepthBlock == 8);
    if (x1 - x0 == kDepthBlock - 1) {  // a whole row: two vectors (max(a, m) keeps m when a is NaN)
        __m128 m = _mm_set1_ps(far);
        for (int y = y0; y <= y1; ++y, row += stride)
            m = _mm_max_ps(_mm_loadu_ps(row + 4), _mm_max_ps(_mm_loadu_ps(row), m));
        m = _mm_max_ps(_mm_movehl_ps(m, m), m);
        m = _mm_max_ps(_mm_shuffle_ps(m, m, 1), m);
        return _mm_cvtss_f32(m);
    }
#endif
    for (int y = y0; y <= y1; ++y, row += stride)
        for (int x = 0; x <= x1 - x0; ++x) far = row[x] > far ? row[x] : far;
    return far;
}

/// Tests that may pass over a stale block's recompute after one failed: a triangle in front of
/// what a block holds (most of a dense mesh's, drawn in front) would pay a recompute each; one
/// behind is then rejected a few triangles later, and the block's bound, exact again, rejects
/// the rest without a recompute. (Passing over a recompute never rejects more.)
inline constexpr int kRecomputeSkip = 4;

/// Boxes this wide or tall (pixels − 1) are tested against the tile's bound alone: a loop over
/// their many blocks per tile cost more than it rejected (8 full-screen layers at 4K drawn back
/// to front: +1.1 % instructions with every box tested against its blocks).
inline constexpr int kBlockTestBox = 16;

/// Whether no pixel of `box` (inside target.tile) can pass a LESS depth test against what the
/// tile holds: the nearest depth the plane `p` takes over the box is not in front of the tile's
/// far bound, or of the far bound of every block the box overlaps (`blocks`, blockMask()). The
/// blocks' bounds known exactly come first (one in front decides: no reject); then a stale bound
/// that would fail is recomputed from the stored depths. A few compares when nothing is known.
/// `blocks` 0: the tile's bound alone (the blocks' bounds are not kept).
inline bool hiddenBehind(const Planes& p, const PixelRect& box, std::uint64_t blocks,
                         const PixelTarget& target, TileDepth& bound) {
    if (blocks == 0 || box.x1 - box.x0 >= kBlockTestBox || box.y1 - box.y0 >= kBlockTestBox) {
        if (!(bound.far < kEmptyDepth)) [[likely]]
            return false;
        float lo = 0.0f, hi = 0.0f;
        return depthRange(p, box, lo, hi) && lo >= bound.far;
    }
    std::uint64_t stale = blocks & bound.stale;
    if (stale != 0 && bound.skip != 0) {  // this test uses the stale bounds as they are
        --bound.skip;
        stale = 0;
    }
    float far = 0.0f;
    for (std::uint64_t m = blocks & ~stale; m != 0; m &= m - 1) {
        const float f = bound.blockFar[std::countr_zero(m)];
        far = f > far ? f : far;
    }
    // Neither bound can reject when the plane's depth at its base point (the triangle's box's
    // corner, where it is not cut by the tile) is in front of both: a few instructions that
    // spare most triangles drawn in front of a block their box's range. (Only a shortcut to
    // "not rejected": never a wrong reject, wherever the base point is.)
    const float nearer = bound.far < far ? bound.far : far;
    if (!(nearer * p.q[0] <= 1.0f)) [[likely]]
        return false;
    float lo = 0.0f, hi = 0.0f;
    if (!depthRange(p, box, lo, hi)) return false;
    if (lo >= bound.far) return true;
    if (!(lo >= far)) return false;
    for (; stale != 0; stale &= stale - 1) {
        const int i = std::countr_zero(stale);
        float& f = bound.blockFar[i];
        if (lo >= f) continue;
        f = std::fmin(f, blockMaxDepth(target, i));
        bound.stale &= ~(std::uint64_t{1} << i);
        if (!(lo >= f)) {
            bound.skip = kRecomputeSkip;
            return false;
        }
    }
    return true;
}

}  // namespace facet::detail
