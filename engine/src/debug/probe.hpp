#pragma once
// The instrumented draws behind the debug views. They count what the real draw does by running
// its own stages: the front end (drawTriangles), the tile binning (TileRenderer), the coverage
// (forEachCovered, the same edge functions) and the depth rule (passesDepth, storeFragment) of
// the draw's shader, and the mip level its trilinear filter would pick (uvLevelOfDetail). Only
// the shading is replaced by counters, so the normal frame path has no counter to pay for.

#include <cstdint>
#include <vector>

#include "binning/tiles.hpp"
#include "facet/advanced/draw.hpp"
#include "facet/framebuffer.hpp"
#include "facet/settings.hpp"

namespace facet::detail {

/// Per-pixel and per-triangle counts of one instrumented draw; keeps its buffers between draws.
struct DrawProbe {
    static constexpr std::uint32_t kNoTriangle = 0xFFFFFFFFu;

    Framebuffer depth;                          ///< the probe's own depth buffer (colour unused)
    std::vector<std::uint32_t> fragments;       ///< per pixel: fragments that reached depth test
    std::vector<std::uint32_t> failures;        ///< per pixel: fragments that failed it
    std::vector<std::uint32_t> winner;          ///< per pixel: triangle that wrote it last
    std::vector<float> lod;                     ///< per pixel: the winner's mip level (withLod)
    std::vector<std::uint32_t> trianglePixels;  ///< per triangle: fragments it produced

    /// Draws `in`'s triangles in submission order, one at a time so that each fragment is known
    /// by its triangle, with the settings' culling, sub-pixel grid, shader (its depth rule) and
    /// interpolation (the mip level's derivatives). `withLod`: also the mip level `in.texture`
    /// (white when null) would be sampled at, from `in.uvs`.
    void run(const DrawInput& in, const RenderSettings& settings, int width, int height,
             bool withLod, RenderStats& stats);
};

/// Counts, per 64×64 tile of a width × height frame, the triangles (guard-band parts counted
/// apart) the tile renderer bins there, by running `tiles` on `in` with a counter for a
/// rasterizer. `perTile` is row-major, (width + 63) / 64 tiles a row.
void countBinLoad(TileRenderer& tiles, const DrawInput& in, const RenderSettings& settings,
                  int width, int height, std::vector<std::uint32_t>& perTile);

}  // namespace facet::detail
