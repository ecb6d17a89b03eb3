#pragma once
// Plane setup, the front end's last stage: the barycentric, 1/w and varying planes of one screen
// triangle, as the pixel loops evaluate them. Computed in double from the unsnapped vertices, so
// interpolation does not inherit the snapping error; only coverage uses the sub-pixel grid.

#include <cmath>
#include <cstddef>

#include <glm/vec2.hpp>

#include "frontend/fetch.hpp"

namespace facet::detail {

/// Linear functions of the pixel position for one triangle, relative to a base pixel so that
/// float keeps its precision far from the origin: value = p[0] + p[1]·dx + p[2]·dy.
struct Planes {
    int baseX = 0, baseY = 0;
    float l1[3], l2[3];        ///< screen-linear barycentrics of vertices 1 and 2
    float u1[3], u2[3], q[3];  ///< λ1/w1, λ2/w2 and Σλi/wi, for perspective and depth
    /// Varying k is a0[k] + m1·d1[k] + m2·d2[k], (m1, m2) the weights of vertices 1 and 2.
    float a0[kMaxVaryings], d1[kMaxVaryings], d2[kMaxVaryings];

    /// The plane p at offset (dx, dy) from the base pixel's centre.
    static float eval(const float (&p)[3], float dx, float dy) {
        return p[0] + p[1] * dx + p[2] * dy;
    }
    /// The fragment's depth (camera-space z, the reciprocal of interpolated 1/w) there.
    float depthAt(float dx, float dy) const { return 1.0f / eval(q, dx, dy); }
};

/// Twice the signed area of a screen triangle; positive means back-facing (y-down pixels).
inline double signedArea2(const glm::dvec2 (&s)[3]) {
    return (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[1].y - s[0].y) * (s[2].x - s[0].x);
}

/// One plane's three coefficients, rounded to float.
inline void setPlane(float (&dst)[3], double c, double a, double b) {
    dst[0] = static_cast<float>(c);
    dst[1] = static_cast<float>(a);
    dst[2] = static_cast<float>(b);
}

/// The varyings' part of the planes: a0, d1 and d2 of the first `count` varyings of vertices
/// with packed varyings a0, a1 and a2.
inline void setVaryingPlanes(const float* a0, const float* a1, const float* a2, int count,
                             Planes& p) {
    for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
        p.a0[k] = a0[k];
        p.d1[k] = a1[k] - a0[k];
        p.d2[k] = a2[k] - a0[k];
    }
}

/// Builds the planes of screen triangle `s` (vertices `v`, `count` varyings) relative to pixel
/// (baseX, baseY); returns false for a degenerate triangle.
inline bool makePlanes(const glm::dvec2 (&s)[3], const ClipVertex (&v)[3], int count, int baseX,
                       int baseY, Planes& p) {
    const double area = signedArea2(s);
    if (!(area != 0.0) || !std::isfinite(area)) return false;
    const double bx = baseX + 0.5, by = baseY + 0.5;
    const double l1 =
        ((s[0].x - s[2].x) * (by - s[2].y) - (s[0].y - s[2].y) * (bx - s[2].x)) / area;
    const double l2 =
        ((s[1].x - s[0].x) * (by - s[0].y) - (s[1].y - s[0].y) * (bx - s[0].x)) / area;
    const double l1x = -(s[0].y - s[2].y) / area, l1y = (s[0].x - s[2].x) / area;
    const double l2x = -(s[1].y - s[0].y) / area, l2y = (s[1].x - s[0].x) / area;
    const double r0 = 1.0 / v[0].pos.w, r1 = 1.0 / v[1].pos.w, r2 = 1.0 / v[2].pos.w;
    p.baseX = baseX;
    p.baseY = baseY;
    setPlane(p.l1, l1, l1x, l1y);
    setPlane(p.l2, l2, l2x, l2y);
    setPlane(p.u1, l1 * r1, l1x * r1, l1y * r1);
    setPlane(p.u2, l2 * r2, l2x * r2, l2y * r2);
    setPlane(p.q, r0 + l1 * (r1 - r0) + l2 * (r2 - r0), l1x * (r1 - r0) + l2x * (r2 - r0),
             l1y * (r1 - r0) + l2y * (r2 - r0));
    setVaryingPlanes(v[0].a.data(), v[1].a.data(), v[2].a.data(), count, p);
    return true;
}

}  // namespace facet::detail
