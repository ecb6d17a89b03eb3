#pragma once
// Clipping for the fast path: the near plane in homogeneous space (attributes follow the clip
// parameter, which is exact for perspective-correct interpolation), and the guard band in 2D
// screen space for coverage only. Both compute a crossing point from the inside endpoint, so two
// triangles sharing an edge get bit-identical new vertices: no cracks along clipped edges.

#include <array>
#include <cstddef>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "frontend/fetch.hpp"

namespace facet::detail {

/// A convex polygon with a fixed upper bound on its vertex count (no allocation).
template <class V, std::size_t N>
struct SmallPolygon {
    std::array<V, N> v;
    std::size_t size = 0;
    void push(const V& x) { v[size++] = x; }
};

/// Clipping a triangle by one plane adds at most one vertex.
using NearPolygon = SmallPolygon<ClipVertex, 4>;
/// A triangle clipped by four guard-band lines has at most seven vertices.
using ScreenPolygon = SmallPolygon<glm::dvec2, 8>;

/// Where the edge a-b crosses w = near (a and b on opposite sides of it). Computed from the
/// inside end whatever the edge's direction,
/// so both triangles sharing the edge (and its wireframe line) get the same vertex.
inline ClipVertex crossNear(const ClipVertex& a, const ClipVertex& b, float near) {
    const bool aInside = a.pos.w >= near;
    const ClipVertex& in = aInside ? a : b;
    const ClipVertex& out = aInside ? b : a;
    // In double: the new vertex lands at x/near, y/near in pixels, which for a small near plane
    // magnifies float rounding of t or x by thousands; in double it stays far below 1/256 px.
    const double din = static_cast<double>(in.pos.w) - near;
    const double dout = static_cast<double>(out.pos.w) - near;
    const double t = din / (din - dout);
    const glm::dvec4 p = glm::dvec4(in.pos) + t * (glm::dvec4(out.pos) - glm::dvec4(in.pos));
    ClipVertex v{glm::vec4(p), {}};
    // The new vertex lies on the plane by construction; rounding w could put it off it, and far
    // vertices (w ~ 1e7) even below 0, which made whole triangles vanish.
    v.pos.w = near;
    const auto tf = static_cast<float>(t);
    for (std::size_t k = 0; k < v.a.size(); ++k) v.a[k] = in.a[k] + tf * (out.a[k] - in.a[k]);
    return v;
}

/// Sutherland–Hodgman of a triangle against w >= near; keeps the input winding.
inline NearPolygon clipNear(const ClipVertex (&tri)[3], float near) {
    NearPolygon out;
    for (int i = 0; i < 3; ++i) {
        const ClipVertex& a = tri[i];
        const ClipVertex& b = tri[(i + 1) % 3];
        const float da = a.pos.w - near;
        const float db = b.pos.w - near;
        if (da >= 0.0f) out.push(a);
        if ((da >= 0.0f) != (db >= 0.0f)) out.push(crossNear(a, b, near));
    }
    return out;
}

/// Clips the segment a-b against w >= near in place; false when nothing is left.
inline bool clipSegmentNear(ClipVertex& a, ClipVertex& b, float near) {
    const float da = a.pos.w - near;
    const float db = b.pos.w - near;
    if (!(da >= 0.0f) && !(db >= 0.0f)) return false;  // also drops NaN ends
    if (!(da >= 0.0f) || !(db >= 0.0f)) (da >= 0.0f ? b : a) = crossNear(a, b, near);
    return true;
}

/// Clips a screen-space triangle to the rectangle [lo, hi] (the guard band), keeping winding.
inline ScreenPolygon clipToRect(const glm::dvec2 (&tri)[3], glm::dvec2 lo, glm::dvec2 hi) {
    ScreenPolygon poly;
    for (const auto& p : tri) poly.push(p);
    // Each of the four lines as (axis, bound, keep-side sign).
    const int axes[4] = {0, 0, 1, 1};
    const double bounds[4] = {lo.x, hi.x, lo.y, hi.y};
    const double signs[4] = {1.0, -1.0, 1.0, -1.0};
    for (int k = 0; k < 4 && poly.size > 0; ++k) {
        ScreenPolygon next;
        for (std::size_t i = 0; i < poly.size; ++i) {
            const glm::dvec2& a = poly.v[i];
            const glm::dvec2& b = poly.v[(i + 1) % poly.size];
            const double da = signs[k] * (a[axes[k]] - bounds[k]);
            const double db = signs[k] * (b[axes[k]] - bounds[k]);
            if (da >= 0.0) next.push(a);
            if ((da >= 0.0) != (db >= 0.0)) {
                const glm::dvec2& in = da >= 0.0 ? a : b;
                const glm::dvec2& outside = da >= 0.0 ? b : a;
                const double din = da >= 0.0 ? da : db;
                const double dout = da >= 0.0 ? db : da;
                glm::dvec2 p = in + (din / (din - dout)) * (outside - in);
                p[axes[k]] = bounds[k];  // exactly on the line, whatever the rounding
                next.push(p);
            }
        }
        poly = next;
    }
    return poly;
}

}  // namespace facet::detail
