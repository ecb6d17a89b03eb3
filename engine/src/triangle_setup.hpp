#pragma once
// The triangle front end of the fast path, shared by every pipeline variant: fetch, reject,
// near-clip, guard band, snap, cull, then one call per covered triangle to a rasterizer that
// knows the variant. That call is per triangle, not per pixel, so the front end is compiled once
// and the variants only instantiate the pixel loop.

#include <cstddef>

#include <glm/vec2.hpp>

#include "facet/render.hpp"
#include "triangle_raster.hpp"
#include "varyings.hpp"

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
};

/// The per-triangle rasterizer of a variant: covers `setup` and shades with `planes`; returns
/// the number of pixels covered (fragments before the depth test).
using RasterizeFn = std::size_t (*)(void* context, const CoverageSetup& setup,
                                    const Planes& planes);

/// Runs the front end over triangles [first, end) of the draw and calls `emit` for each part
/// that covers pixels, with the planes of the (whole, unclipped by the guard band) triangle.
/// Returns the sum of what `emit` returned. Coverage uses a grid of 1/2^subPixelBits px.
std::size_t drawTriangles(const DrawInput& in, const VaryingLayout& layout, bool cull, int width,
                          int height, std::size_t first, std::size_t end, RasterizeFn emit,
                          void* context, RenderStats& stats, int subPixelBits = kSubPixelBits);

}  // namespace facet::detail
