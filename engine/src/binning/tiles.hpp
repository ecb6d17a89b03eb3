#pragma once
// Sort-middle parallel rasterization. A vertex pass first derives what the front end needs of
// each vertex (ScreenVertex). Then the draw's triangles are taken in batches; for each batch the
// front end runs over contiguous slices of the triangles, one per thread, and bins what it
// produces (snapped triangle + planes, a compact record) into 64×64 pixel tiles; each tile is then
// rasterized by one thread, visiting the slices in order, while the next batch is being binned. So
// every pixel sees its fragments in submission order, exactly as one thread would draw them: the
// image does not depend on the thread count, and no lock guards the framebuffer because no two
// threads ever own the same tile.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>
#include <vector>

#include "binning/tile_buffer.hpp"
#include "facet/framebuffer.hpp"
#include "facet/settings.hpp"
#include "frontend/front_end.hpp"

namespace facet::detail {

/// Side of a tile in pixels: a 64×64 tile's colour and depth (32 KiB) stay in L1/L2 while its
/// triangles are drawn.
inline constexpr int kTileSize = 64;
static_assert(kTileSize == kDepthBlock * kDepthBlocksPerSide, "hierarchical depth's blocks");

/// Worker threads for a draw: `requested` when positive, else every core.
int resolveThreads(int requested);

/// The DrawJob of `in` drawn with `settings` into a width × height image with varyings `layout`:
/// back-face culling and the sub-pixel grid (clamped to what the engine supports) from the
/// settings, one sample per pixel.
inline DrawJob drawJob(const DrawInput& in, const VaryingLayout& layout,
                       const RenderSettings& settings, int width, int height) {
    DrawJob job;
    job.in = &in;
    job.layout = layout;
    job.cull = settings.cullBackFaces;
    job.width = width;
    job.height = height;
    job.subPixelBits = clampedSubPixelBits(settings);
    return job;
}

/// A record's head: the triangle's edges as the tile side reads them (the edge values at the
/// box's first pixel centre in 64 bits; the steps from two edges' vertex differences, in 32 bits
/// since the guard band bounds them, the third edge's being minus their sum) and the planes'
/// depth plane, then the box and the planes' base in 16 bits (both lie in the image, whose sides
/// are at most kMaxRecordSide): 64 bytes, so a triangle without varyings is one aligned
/// cache line (at 80 bytes most records straddled two, and the tile loop, reading them in tile
/// order, missed on both). Keeping the edges, not the snapped vertices, spares every tile the
/// triangle touches their rebuild (edgesOf, ~90 instructions: on the 1M-triangle sphere that
/// cost more than the smaller record saved). A draw without varyings needs nothing more (the
/// weights of vertices 1 and 2 only interpolate varyings); with varyings the weights' planes
/// (l1, l2, u1, u2) and a0, d1 and d2 of the layout's varyings follow.
struct RecordHead {
    std::int64_t e0[3];
    std::int32_t dx[2], dy[2];
    float q[3];
    std::uint16_t x0, y0, x1, y1;  ///< the box
    std::uint16_t baseX, baseY;

    /// The box.
    PixelRect box() const { return {x0, y0, x1, y1}; }
};
/// Largest image side whose pixel coordinates RecordHead holds (16 bits unsigned); the engine's
/// frames are at most kMaxImageSide × kMaxSupersample = 65536 (tiles.cpp checks).
inline constexpr int kMaxRecordSide = 65536;
static_assert(sizeof(RecordHead) == 64 && alignof(RecordHead) == 8);

static_assert(std::is_trivially_copyable_v<RecordHead> && std::is_trivially_copyable_v<Planes>);

/// How many records ahead of the one being drawn the tile loop prefetches.
inline constexpr std::uint32_t kPrefetchAhead = 4;

/// Bytes of the weights' planes: l1, l2, u1 and u2, adjacent in Planes.
inline constexpr std::size_t kWeightBytes = 12 * sizeof(float);
static_assert(offsetof(Planes, u2) + 3 * sizeof(float) - offsetof(Planes, l1) == kWeightBytes);

/// Calls f(std::integral_constant<int, N>{}) for the N == n of N…: code that copies n
/// varyings then copies a size known at compile time, inline moves instead of three calls to
/// memcpy (with 3 varyings those calls were half of the tile loop's cost per triangle).
template <class F, int... N>
void withVaryingCount(int n, F&& f, std::integer_sequence<int, N...>) {
    (void)((n == N ? (f(std::integral_constant<int, N>{}), true) : false) || ...);
}
/// withVaryingCount() over 0 … kMaxVaryings.
template <class F>
void withVaryingCount(int n, F&& f) {
    withVaryingCount(n, f, std::make_integer_sequence<int, kMaxVaryings + 1>{});
}

/// The frame a one-sample solid draw writes (TileRenderer::draw): where each tile's PixelTarget
/// points, whether the frame is cleared first, and whether tiles keep a hierarchical depth.
struct TileFrame {
    Framebuffer* fb = nullptr;  ///< null: the raster writes elsewhere and ignores its target
    /// Clear the frame to `background` (depth kEmptyDepth) before drawing: in each tile's buffer
    /// where the draw is tile-resident (see run()), else in a pass over the frame.
    bool clear = false;
    std::uint32_t background = 0;
    bool hiZ = false;  ///< the draw tests depth (LESS): keep a far bound per tile
};

/// When a one-batch solid draw uses the per-thread tile buffer: never, when the frame is larger
/// than the caches and its triangles' boxes cover it at least twice (the default; see run()), or
/// always.
enum class TileBufferUse { Never, Overdrawn, Always };
/// Sets when the tile buffer is used, for tests that compare the image drawn with and without
/// it; not thread-safe against draws in progress.
void useTileBuffer(TileBufferUse use);
/// Switches hierarchical depth (on by default) off or on, for the same kind of tests.
void enableHiZ(bool enabled);
/// Switches the per-block depth bounds (TileDepth::blockFar) on or off. Off by default: timed
/// on the idle machine, the test they add per triangle cost more than the triangles they reject
/// saved on every bench case (the bunny at 720p, 1 thread: 9.4 ms without, 10.4 with, though
/// 38 % of its triangles were rejected); the tests switch them on to keep them exact.
void enableBlockHiZ(bool enabled);

/// Runs the triangle pipeline on several threads; keeps its bins between draws so a steady
/// frame allocates nothing.
class TileRenderer {
  public:
    /// Draws the triangles of `job` like drawTriangles() over the whole draw, calling
    /// `raster(setup, planes)` (returning the pixels covered) for each triangle and tile it
    /// touches, the setup clipped to the tile. `raster` is the draw's typed rasterizer (a
    /// struct of the per-draw state with a call operator): the tile loop is instantiated with
    /// it, so the per-triangle call is a direct one the compiler may inline. It must be safe to
    /// call from several threads for disjoint tiles. Adds the front end's counters, its and
    /// binning's times and the fragments to `stats`. `raster` is called as
    /// raster(setup, planes, target): `target` is where the tile's pixels go (`frame`'s pixels,
    /// or a per-thread tile buffer written to the frame after the tile), with the tile's
    /// hierarchical depth when frame.hiZ.
    template <class Raster>
    void draw(const DrawJob& job, const Raster& raster, int threads, RenderStats& stats,
              const TileFrame& frame = {}) {
        run(job, threads, stats, {&drawTileWith<Raster>, &raster}, frame);
    }

    /// A record's storage: cache-line aligned, records packed at multiples of 8 bytes (64
    /// bytes, one line, for a triangle without varyings).
    struct alignas(64) Line {
        std::byte bytes[64];
    };
    /// A record's place in a tile's bin: the tile and the record's byte offset in its slice.
    struct BinEntry {
        std::uint32_t tile;
        std::uint32_t offset;
    };
    /// What one thread's slice of a batch produced: packed records (RecordHead, then the planes
    /// the layout needs), the (tile, record) pairs in submission order, and after the batch the
    /// same sorted by tile: tile t's records are order[start[t] … start[t + 1]). Aligned to a
    /// cache line so that two threads never write to one.
    struct alignas(64) Slice {
        std::vector<Line> records;  // grown, never shrunk: a steady frame allocates nothing
        std::size_t used = 0;       // bytes of `records` holding this batch's records
        std::size_t recordBytes = 0;
        int varyings = 0;
        std::vector<BinEntry> entries;      // grown, never shrunk
        std::size_t entryCount = 0;         // entries of this batch
        std::uint64_t boxPixels = 0;        // the batch's boxes' pixels: how much it may draw
        std::vector<std::uint32_t> start;   // per tile, and one past the last
        std::vector<std::uint32_t> cursor;  // per tile, the sort's scratch
        std::vector<std::uint32_t> order;   // record offsets, tile by tile, kPrefetchAhead more
        int tilesX = 0;
        RenderStats stats;
    };

    /// Which tile a thread draws and from which slices: the tile's records are in slices
    /// [first, first + count), visited in that order (submission order).
    struct TileTask {
        int tile = 0;
        std::size_t first = 0, count = 0;
        const PixelTarget* target = nullptr;  ///< where the tile's pixels go (never null)
    };
    /// A thread's tile buffer: a 64×64 tile's colour and depth, rows kTileSize apart.
    struct alignas(64) TileBuffer {
        std::uint32_t color[kTileSize * kTileSize];
        float depth[kTileSize * kTileSize];
    };
    /// The tile loop of one rasterizer type, and that rasterizer: called once per tile and
    /// batch (not per triangle), so the type is erased here and nowhere below.
    struct TileDrawer {
        std::size_t (*draw)(const TileRenderer& self, const void* raster, const TileTask& task);
        const void* raster;
    };

  private:
    /// The draw, its threads and batches (tiles.cpp); `drawer` rasterizes one tile.
    void run(const DrawJob& job, int threads, RenderStats& stats, TileDrawer drawer,
             const TileFrame& frame);

    /// One tile of a step: its records from slices [first, first + count) drawn into the frame,
    /// or when `resident` in the thread's tile buffer, cleared first and written to the frame
    /// after; with the tile's far bound when `hiZ`. Returns the pixels covered.
    std::size_t drawTile(int tile, std::size_t first, std::size_t count, TileDrawer drawer,
                         const TileFrame& frame, bool resident, bool hiZ);

    template <class Raster>
    static std::size_t drawTileWith(const TileRenderer& self, const void* raster,
                                    const TileTask& task) {
        return self.rasterizeTile(*static_cast<const Raster*>(raster), task);
    }

    /// Rasterizes the task's tile with `raster`, every record of its slices in order; returns
    /// the pixels covered.
    template <class Raster>
    std::size_t rasterizeTile(const Raster& raster, const TileTask& task) const;

    /// rasterizeTile() for one slice's records.
    template <class Raster>
    std::size_t rasterizeSlice(const Raster& raster, const Slice& slice, std::size_t tile,
                               const PixelRect& rect, const PixelTarget& target) const;

    std::vector<Slice> slices_;           // one set per thread, two when binning overlaps the tiles
    std::vector<ScreenVertex> screen_;    // the vertex pass's output, one per clip position
    std::vector<std::size_t> fragments_;  // per thread
    std::vector<TileBuffer> buffers_;     // per thread, when the draw is tile-resident
    std::vector<TileDepth> depths_;       // per tile, the hierarchical depth
    /// A thread's share of a step's tiles: the next one not yet taken, by it or by a thread
    /// that finished its own; its own cache line, as every thread takes from it.
    struct alignas(64) TileShare {
        std::atomic<int> next{0};
    };
    std::vector<TileShare> shares_;  // per thread, two steps (one in use, one being reset)
    int width_ = 0, height_ = 0, tilesX_ = 0;  // the draw being run
};

template <class Raster>
std::size_t TileRenderer::rasterizeTile(const Raster& raster, const TileTask& task) const {
    const int x0 = task.tile % tilesX_ * kTileSize, y0 = task.tile / tilesX_ * kTileSize;
    const PixelRect rect{x0, y0, std::min(x0 + kTileSize, width_) - 1,
                         std::min(y0 + kTileSize, height_) - 1};
    std::size_t fragments = 0;
    const auto at = static_cast<std::size_t>(task.tile);
    for (std::size_t s = task.first; s < task.first + task.count; ++s) {  // submission order
        fragments += rasterizeSlice(raster, slices_[s], at, rect, *task.target);
    }
    return fragments;
}

template <class Raster>
std::size_t TileRenderer::rasterizeSlice(const Raster& raster, const Slice& slice, std::size_t tile,
                                         const PixelRect& rect, const PixelTarget& target) const {
    std::size_t fragments = 0;
    CoverageSetup setup{};  // area2 is never read by the pixel loops
    Planes planes{};        // what the record does not hold is never read (RecordHead)
    const auto* records = reinterpret_cast<const std::byte*>(slice.records.data());
    const std::uint32_t* order = slice.order.data();
    const std::uint32_t first = slice.start[tile], end = slice.start[tile + 1];
    const std::size_t bytes = slice.recordBytes;
    withVaryingCount(slice.varyings, [&](auto varyings) {
        constexpr std::size_t n = sizeof(float) * decltype(varyings)::value;
        for (std::uint32_t k = first; k < end; ++k) {
            // The records of a tile are scattered through the slice (and with several threads
            // written by another core): fetch a few ahead while this one is drawn.
            // order[] has kPrefetchAhead entries past the batch's last (sortByTile), so no
            // test: past the tile's last record this fetches the next tile's first ones.
            const std::byte* next = records + order[k + kPrefetchAhead];
            __builtin_prefetch(next);
            if constexpr (n > 0) {  // the planes: up to two more lines
                __builtin_prefetch(next + sizeof(Line));
                if (bytes > 2 * sizeof(Line)) __builtin_prefetch(next + 2 * sizeof(Line));
            }
            const std::byte* record = records + order[k];
            RecordHead head;
            std::memcpy(&head, record, sizeof head);
            const std::int64_t dx[3] = {head.dx[0], head.dx[1], -(head.dx[0] + head.dx[1])};
            const std::int64_t dy[3] = {head.dy[0], head.dy[1], -(head.dy[0] + head.dy[1])};
            for (int i = 0; i < 3; ++i) {  // as edgesOf() derives them
                setup.e0[i] = head.e0[i];
                setup.stepX[i] = -dy[i] * kSubPixel;
                setup.stepY[i] = dx[i] * kSubPixel;
            }
            setup.box = head.box();
            // Most triangles of a dense mesh lie in one tile: their setup needs no clipping.
            const PixelRect& b = setup.box;
            if (b.x0 < rect.x0 || b.y0 < rect.y0 || b.x1 > rect.x1 || b.y1 > rect.y1) {
                setup = restrictSetup(setup, rect);
                if (setup.box.empty()) continue;
            }
            planes.baseX = head.baseX;
            planes.baseY = head.baseY;
            std::memcpy(planes.q, head.q, sizeof head.q);
            if constexpr (n > 0) {
                const std::byte* rest = record + sizeof head;
                std::memcpy(planes.l1, rest, kWeightBytes);
                rest += kWeightBytes;
                std::memcpy(planes.a0, rest, n);
                std::memcpy(planes.d1, rest + n, n);
                std::memcpy(planes.d2, rest + 2 * n, n);
            }
            fragments += raster(setup, planes, target);
        }
    });
    return fragments;
}

}  // namespace facet::detail
