#pragma once
// The triangle front end of the fast path, shared by every pipeline variant. Its stages, in
// front_end.cpp: fetch (indices, trivial reject, varyings), near clip (near_clip.hpp), project
// and snap (screen positions, the sub-pixel grid, the guard band), cull, and plane setup
// (planes.hpp); then one call per covered triangle to a rasterizer that knows the variant. That
// call is per triangle, not per pixel, so the front end is compiled once and the variants only
// instantiate the pixel loop.

#include <cstddef>

#include "coverage/coverage.hpp"
#include "facet/render.hpp"
#include "frontend/fetch.hpp"
#include "frontend/planes.hpp"

namespace facet::detail {

/// A clip position on screen, in double: the projection every later stage starts from.
inline glm::dvec2 screenPosition(const glm::vec4& clip) {
    return glm::dvec2(clip.x, clip.y) / static_cast<double>(clip.w);
}

/// The per-triangle rasterizer of a variant: covers `setup` and shades with `planes`; returns
/// the number of pixels covered (fragments before the depth test).
using RasterizeFn = std::size_t (*)(void* context, const CoverageSetup& setup,
                                    const Planes& planes);

/// Runs the front end over triangles [first, end) of the draw and calls `emit` for each part
/// that covers pixels, with the planes of the (whole, unclipped by the guard band) triangle.
/// Returns the sum of what `emit` returned. Coverage uses a grid of 1/2^subPixelBits px; boxes
/// reach `sampleReach` grid units past the pixel centres (multisampling, setupCoverage()).
std::size_t drawTriangles(const DrawInput& in, const VaryingLayout& layout, bool cull, int width,
                          int height, std::size_t first, std::size_t end, RasterizeFn emit,
                          void* context, RenderStats& stats, int subPixelBits = kSubPixelBits,
                          int sampleReach = 0);

}  // namespace facet::detail
