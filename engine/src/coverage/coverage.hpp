#pragma once
// Triangle coverage on a fixed-point sub-pixel grid (spec §5).
//
// Vertices are snapped to 1/256 px. Edge functions are then exact 64-bit integers, so the
// top-left rule is decided without rounding: two triangles sharing an edge see the same integers
// with opposite signs, and every pixel centre on the edge goes to exactly one of them.
//
// A coarser grid (RenderSettings::subPixelBits < 8) only changes the snap: a vertex is rounded to
// 1/2^b px and then written in 1/256 px units, which is exact. Coverage is then exactly a b-bit
// rasterizer's while the edge arithmetic below stays the same, so the choice costs nothing per
// pixel.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include <glm/vec2.hpp>

namespace facet::detail {

/// Fractional bits of the sub-pixel grid.
inline constexpr int kSubPixelBits = 8;
inline constexpr std::int64_t kSubPixel = std::int64_t{1} << kSubPixelBits;

/// Pixel rectangle [x0, x1] × [y0, y1], inclusive.
struct PixelRect {
    int x0, y0, x1, y1;
    bool empty() const { return x0 > x1 || y0 > y1; }
};

/// A snapped triangle ready for coverage: three edges and a pixel bounding box.
struct CoverageSetup {
    // Edge i runs from vertex i to vertex i+1 (mod 3); value at the bbox's first pixel centre,
    // bias folded in, and steps per pixel in x and y.
    std::int64_t e0[3];
    std::int64_t stepX[3];
    std::int64_t stepY[3];
    PixelRect box;
    std::int64_t area2;  ///< twice the signed area in 1/65536 px², after orientation fix (> 0)
};

/// The top-left rule: a top edge (horizontal, going right) or a left edge (going up), for the
/// winding that puts the inside at E ≥ 0. Pixel centres exactly on such an edge are inside.
inline bool isTopLeft(std::int64_t dx, std::int64_t dy) {
    return dy < 0 || (dy == 0 && dx > 0);
}

/// Result of snapping: which way the triangle faces on screen.
enum class Facing { Degenerate, Front, Back };

/// Snapping to a grid of 1/2^bits px, results in 1/256 px units: v·2^bits is exact in double, so
/// the rounding is the b-bit rasterizer's, and the product with `step` is exact in integers.
struct SnapGrid {
    double scale = static_cast<double>(kSubPixel);  ///< 2^bits
    std::int64_t step = 1;                          ///< 2^(kSubPixelBits − bits)

    /// The grid of `bits` fractional bits, clamped to 1…kSubPixelBits.
    static SnapGrid ofBits(int bits) {
        const int b = std::clamp(bits, 1, kSubPixelBits);
        return {static_cast<double>(std::int64_t{1} << b), std::int64_t{1} << (kSubPixelBits - b)};
    }
    /// `v` snapped to this grid, in 1/256 px units: std::llround (halves away from zero) done
    /// inline, since the libm call was a tenth of the front end. Exact for |v·scale| < 2^52,
    /// which the guard band ensures: the truncation and the fraction are exact in double.
    std::int64_t operator()(double v) const {
        const double x = v * scale;
        auto i = static_cast<std::int64_t>(x);
        const double fraction = x - static_cast<double>(i);
        if (fraction >= 0.5) ++i;
        if (fraction <= -0.5) --i;
        return i * step;
    }
};

/// Floor division by the grid size (arithmetic shift rounds toward -inf in C++20).
inline std::int64_t floorDivSub(std::int64_t v) {
    return v >> kSubPixelBits;
}

/// A snapped triangle as coverage needs it, before its edges: the vertices wound so that the
/// inside is E ≥ 0, relative to the corner of the box's first pixel (box.x0·256, box.y0·256), so
/// they fit 32 bits (the guard band bounds them); edgesOf() derives the edges from them.
struct SnappedTriangle {
    std::int64_t x[3], y[3];  ///< grid units, relative to the box's first pixel corner
    PixelRect box;            ///< pixels whose centre (or samples, with reach) may be covered
    std::int64_t area2;       ///< as CoverageSetup::area2
};

/// Stage one of setupCoverage(): winding, area and the pixel box of the snapped triangle (x[i],
/// y[i]) (grid units) within `clip`. Returns the facing; only Front/Back triangles get a usable
/// `out`. Back means clockwise on a y-up screen (positive area in y-down pixel space), matching
/// the reference path. `reach` (grid units) widens the box to every pixel with a point within
/// `reach` of its centre inside the triangle's bounds: multisampling's samples lie off the
/// centre (0: centres only).
inline Facing snapTriangle(const std::int64_t (&xs)[3], const std::int64_t (&ys)[3],
                           const PixelRect& clip, SnappedTriangle& out, std::int64_t reach = 0) {
    std::int64_t x[3] = {xs[0], xs[1], xs[2]};
    std::int64_t y[3] = {ys[0], ys[1], ys[2]};
    std::int64_t area = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (area == 0) return Facing::Degenerate;
    const Facing facing = area < 0 ? Facing::Front : Facing::Back;
    if (area < 0) {  // make the winding positive so "inside" is E >= 0 for all edges
        std::swap(x[1], x[2]);
        std::swap(y[1], y[2]);
        area = -area;
    }
    out.area2 = area;

    const std::int64_t minX = std::min({x[0], x[1], x[2]}), maxX = std::max({x[0], x[1], x[2]});
    const std::int64_t minY = std::min({y[0], y[1], y[2]}), maxY = std::max({y[0], y[1], y[2]});
    const std::int64_t half = kSubPixel / 2;
    // Pixel i's centre is at i*256 + 128: first centre >= min, last centre <= max.
    const std::int64_t bx0 =
        std::max<std::int64_t>(clip.x0, floorDivSub(minX - reach - half + kSubPixel - 1));
    const std::int64_t bx1 = std::min<std::int64_t>(clip.x1, floorDivSub(maxX + reach - half));
    const std::int64_t by0 =
        std::max<std::int64_t>(clip.y0, floorDivSub(minY - reach - half + kSubPixel - 1));
    const std::int64_t by1 = std::min<std::int64_t>(clip.y1, floorDivSub(maxY + reach - half));
    out.box = {static_cast<int>(bx0), static_cast<int>(by0), static_cast<int>(bx1),
               static_cast<int>(by1)};
    for (int i = 0; i < 3; ++i) {
        out.x[i] = x[i] - bx0 * kSubPixel;
        out.y[i] = y[i] - by0 * kSubPixel;
    }
    return facing;
}

/// Stage two of setupCoverage(): the edges of `t` at its box's first pixel centre, with the
/// top-left rule's bias, and their steps per pixel (for a non-empty box).
inline void edgesOf(const SnappedTriangle& t, CoverageSetup& out) {
    out.box = t.box;
    out.area2 = t.area2;
    const std::int64_t half = kSubPixel / 2;  // the first centre, relative to the box's corner
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        const std::int64_t dx = t.x[j] - t.x[i];
        const std::int64_t dy = t.y[j] - t.y[i];
        // Centres on a top-left edge are inside: the bias makes E = 0 fail on the others.
        out.e0[i] = dx * (half - t.y[i]) - dy * (half - t.x[i]) - (isTopLeft(dx, dy) ? 0 : 1);
        out.stepX[i] = -dy * kSubPixel;
        out.stepY[i] = dx * kSubPixel;
    }
}

/// Sets up coverage of the snapped triangle (x[i], y[i]) (already in grid units) within `clip`:
/// snapTriangle() then edgesOf(). Returns the facing; only Front/Back triangles get a usable
/// `out`, whose box is empty when the triangle covers no pixel centre of `clip`.
inline Facing setupCoverage(const std::int64_t (&xs)[3], const std::int64_t (&ys)[3],
                            const PixelRect& clip, CoverageSetup& out, std::int64_t reach = 0) {
    SnappedTriangle t;
    const Facing facing = snapTriangle(xs, ys, clip, t, reach);
    if (facing == Facing::Degenerate) return facing;
    out.box = t.box;
    out.area2 = t.area2;
    if (!t.box.empty()) edgesOf(t, out);
    return facing;
}

/// The setup restricted to `rect`; the edge values move to the new first pixel exactly, in
/// integers, so coverage inside the rectangle is unchanged (tiles, the pixel inspector).
inline CoverageSetup restrictSetup(const CoverageSetup& s, const PixelRect& rect) {
    CoverageSetup out = s;
    out.box = {std::max(s.box.x0, rect.x0), std::max(s.box.y0, rect.y0),
               std::min(s.box.x1, rect.x1), std::min(s.box.y1, rect.y1)};
    if (out.box.empty()) return out;
    const std::int64_t dx = out.box.x0 - s.box.x0, dy = out.box.y0 - s.box.y0;
    for (int i = 0; i < 3; ++i) out.e0[i] = s.e0[i] + dx * s.stepX[i] + dy * s.stepY[i];
    return out;
}

/// Calls visit(x, y) for every covered pixel centre, row by row, left to right.
template <class Visit>
inline void forEachCovered(const CoverageSetup& s, Visit&& visit) {
    std::int64_t row[3] = {s.e0[0], s.e0[1], s.e0[2]};
    for (int y = s.box.y0; y <= s.box.y1; ++y) {
        std::int64_t e[3] = {row[0], row[1], row[2]};
        for (int x = s.box.x0; x <= s.box.x1; ++x) {
            if ((e[0] | e[1] | e[2]) >= 0) visit(x, y);
            e[0] += s.stepX[0];
            e[1] += s.stepX[1];
            e[2] += s.stepX[2];
        }
        row[0] += s.stepY[0];
        row[1] += s.stepY[1];
        row[2] += s.stepY[2];
    }
}

/// Pixels each way of the boxes whose centres coversNoCentre() tests. Up to 2×2 left slivers
/// through: on the 1M sphere at 1080p 77,000 of 1.13 M triangles reaching the tiles covered no
/// centre, all but 816 of them in boxes of 1×3 to 4×2 pixels.
inline constexpr int kNoCentreSide = 4;

/// Whether `t` (a non-empty box of pixel centres, no sample reach) covers none of its box's
/// pixel centres, tested for boxes of at most kNoCentreSide × kNoCentreSide pixels (false for
/// larger ones: not tested). Most triangles of a dense mesh have such boxes and many cover no
/// centre: they end here instead of costing plane setup, a record and a tile's visit (the front
/// end's last exit).
inline bool coversNoCentre(const SnappedTriangle& t) {
    if (t.box.x1 - t.box.x0 >= kNoCentreSide || t.box.y1 - t.box.y0 >= kNoCentreSide) return false;
    CoverageSetup s;
    edgesOf(t, s);
    bool none = true;
    forEachCovered(s, [&](int, int) { none = false; });
    return none;
}

}  // namespace facet::detail
