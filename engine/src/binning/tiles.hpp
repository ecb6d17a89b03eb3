#pragma once
// Sort-middle parallel rasterization. A vertex pass first derives what the front end needs of
// each vertex (ScreenVertex). Then the draw's triangles are taken in batches; for each batch the
// front end runs over contiguous slices of the triangles, one per thread, and bins what it
// produces (coverage setup + planes) into 64×64 pixel tiles; each tile is then rasterized by one
// thread, visiting the slices in order, while the next batch is being binned. So every pixel
// sees its fragments in submission order, exactly as one thread would draw them: the image does
// not depend on the thread count, and no lock guards the framebuffer because no two threads ever
// own the same tile.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "frontend/front_end.hpp"

namespace facet::detail {

/// Side of a tile in pixels: a 64×64 tile's colour and depth (32 KiB) stay in L1/L2 while its
/// triangles are drawn.
inline constexpr int kTileSize = 64;

/// Worker threads for a draw: `requested` when positive, else every core.
int resolveThreads(int requested);

/// Runs the triangle pipeline on several threads; keeps its bins between draws so a steady
/// frame allocates nothing.
class TileRenderer {
  public:
    /// Draws triangles like drawTriangles() over the whole draw, rasterizing with `rasterize`
    /// (whose `context` must be safe to share between threads for disjoint tiles), on a grid of
    /// 1/2^subPixelBits px, boxes reaching `sampleReach` grid units past pixel centres
    /// (multisampling). Adds the front end's counters and the fragments to `stats`.
    void draw(const DrawInput& in, const VaryingLayout& layout, bool cull, int width, int height,
              RasterizeFn rasterize, void* context, int threads, int subPixelBits,
              RenderStats& stats, int sampleReach = 0);

  private:
    /// What one thread's slice of a batch produced: packed records, and per tile their offsets.
    /// A record is a CoverageSetup, the planes up to their varyings, and only the `varyings`
    /// varyings the layout uses (a Planes holds room for all of them): 168 bytes unlit instead
    /// of 296, so a batch's records stay in the core's cache until its tiles are rasterized.
    /// Aligned to a cache line so that two threads never write to one.
    struct alignas(64) Slice {
        std::vector<std::byte> records;  // grown, never shrunk: a steady frame allocates nothing
        std::size_t used = 0;            // bytes of `records` holding this batch's records
        std::size_t recordBytes = 0;
        int varyings = 0;
        std::vector<std::vector<std::uint32_t>> bins;  // one list of record offsets per tile
        std::vector<std::uint32_t> touched;            // tiles with a non-empty list
        int tilesX = 0;
        RenderStats stats;
    };
    static std::size_t binTriangle(void* slice, const CoverageSetup& setup, const Planes& planes);
    std::size_t rasterizeTile(int tile, int tilesX, int width, int height, RasterizeFn rasterize,
                              void* context, std::size_t first, std::size_t count) const;

    std::vector<Slice> slices_;           // one set per thread, two when binning overlaps the tiles
    std::vector<ScreenVertex> screen_;    // the vertex pass's output, one per clip position
    std::vector<std::size_t> fragments_;  // per thread
};

}  // namespace facet::detail
