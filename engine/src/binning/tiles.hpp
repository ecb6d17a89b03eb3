#pragma once
// Sort-middle parallel rasterization. A vertex pass first derives what the front end needs of
// each vertex (ScreenVertex). Then the draw's triangles are taken in batches; for each batch the
// front end runs over contiguous slices of the triangles, one per thread, and bins what it
// produces (snapped triangle + planes, a compact record) into 64×64 pixel tiles; each tile is then
// rasterized by one thread, visiting the slices in order, while the next batch is being binned. So
// every pixel sees its fragments in submission order, exactly as one thread would draw them: the
// image does not depend on the thread count, and no lock guards the framebuffer because no two
// threads ever own the same tile.

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
    /// Draws the triangles of `job` like drawTriangles() over the whole draw, rasterizing with
    /// `rasterize` (whose `context` must be safe to share between threads for disjoint tiles).
    /// Adds the front end's counters, its and binning's times and the fragments to `stats`.
    void draw(const DrawJob& job, RasterizeFn rasterize, void* context, int threads,
              RenderStats& stats);
    /// draw() of the job these name (job.screen is the tile renderer's own vertex pass).
    void draw(const DrawInput& in, const VaryingLayout& layout, bool cull, int width, int height,
              RasterizeFn rasterize, void* context, int threads, int subPixelBits,
              RenderStats& stats, int sampleReach = 0) {
        draw({&in, layout, cull, width, height, subPixelBits, sampleReach, nullptr}, rasterize,
             context, threads, stats);
    }

    /// A record's storage: cache-line aligned, records packed at multiples of 8 bytes (80
    /// bytes for a triangle without varyings).
    struct alignas(64) Line {
        std::byte bytes[64];
    };
    /// A record's place in a tile's bin: the tile and the record's byte offset in its slice.
    struct BinEntry {
        std::uint32_t tile;
        std::uint32_t offset;
    };
    /// What one thread's slice of a batch produced: packed records (tiles.cpp's RecordHead,
    /// then the planes the layout needs), the (tile, record) pairs in submission order, and
    /// after the batch the same sorted by tile: tile t's records are order[start[t] …
    /// start[t + 1]). Aligned to a cache line so that two threads never write to one.
    struct alignas(64) Slice {
        std::vector<Line> records;  // grown, never shrunk: a steady frame allocates nothing
        std::size_t used = 0;       // bytes of `records` holding this batch's records
        std::size_t recordBytes = 0;
        int varyings = 0;
        std::vector<BinEntry> entries;      // grown, never shrunk
        std::size_t entryCount = 0;         // entries of this batch
        std::vector<std::uint32_t> start;   // per tile, and one past the last
        std::vector<std::uint32_t> cursor;  // per tile, the sort's scratch
        std::vector<std::uint32_t> order;   // record offsets, tile by tile
        int tilesX = 0;
        RenderStats stats;
    };

  private:
    std::size_t rasterizeTile(int tile, int tilesX, int width, int height, RasterizeFn rasterize,
                              void* context, std::size_t first, std::size_t count) const;

    std::vector<Slice> slices_;           // one set per thread, two when binning overlaps the tiles
    std::vector<ScreenVertex> screen_;    // the vertex pass's output, one per clip position
    std::vector<std::size_t> fragments_;  // per thread
};

}  // namespace facet::detail
