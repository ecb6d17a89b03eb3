// Sort-middle rasterization on OpenMP threads (see tiles.hpp).

#include "binning/tiles.hpp"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <type_traits>

#include <omp.h>

namespace facet::detail {
namespace {

/// Triangles each thread's front end takes per batch. One thread: few enough that the batch's
/// records (168 to 300 bytes each) and bins are still in the core's L2 when its tiles read them
/// (with 8192 the tile loop waited on memory for every record). Several threads: every batch
/// costs two barriers, and on a loaded machine a barrier waits for a descheduled thread's next
/// time slice; the bunny at 2 threads took twice as long with 2048 as with 8192 (load 17 on 2
/// cores), so there the batch stays large.
constexpr std::size_t kBatchPerThread = 2048;
constexpr std::size_t kBatchPerThreadShared = 8192;

/// A packed record: the setup, then the planes' fields before the varyings, then a0, d1 and d2
/// of the layout's varyings only.
constexpr std::size_t kSetupBytes = sizeof(CoverageSetup);
constexpr std::size_t kPlaneHeadBytes = offsetof(Planes, a0);
static_assert(std::is_trivially_copyable_v<CoverageSetup> && std::is_trivially_copyable_v<Planes> &&
              std::is_standard_layout_v<Planes>);

/// Bytes of a record with `varyings` varyings, rounded up so every record stays 8-byte aligned.
constexpr std::size_t recordBytes(int varyings) {
    const std::size_t bytes =
        kSetupBytes + kPlaneHeadBytes + 3 * sizeof(float) * static_cast<std::size_t>(varyings);
    return (bytes + 7) / 8 * 8;
}

/// Whether `inner` lies within `outer`.
bool contains(const PixelRect& outer, const PixelRect& inner) {
    return inner.x0 >= outer.x0 && inner.y0 >= outer.y0 && inner.x1 <= outer.x1 &&
           inner.y1 <= outer.y1;
}

void addCounters(RenderStats& to, const RenderStats& from) {
    to.trianglesIn += from.trianglesIn;
    to.trianglesCulled += from.trianglesCulled;
    to.trianglesClipped += from.trianglesClipped;
    to.trianglesRasterized += from.trianglesRasterized;
}

}  // namespace

int resolveThreads(int requested) {
    if (requested > 0) return requested;
    return std::max(1, omp_get_num_procs());
}

std::size_t TileRenderer::binTriangle(void* context, const CoverageSetup& setup,
                                      const Planes& planes) {
    Slice& slice = *static_cast<Slice*>(context);
    const std::size_t at = slice.used;
    if (at + slice.recordBytes > slice.records.size())
        slice.records.resize(std::max(2 * slice.records.size(), at + slice.recordBytes));
    std::byte* record = slice.records.data() + at;
    slice.used = at + slice.recordBytes;
    std::memcpy(record, &setup, kSetupBytes);
    std::memcpy(record + kSetupBytes, &planes, kPlaneHeadBytes);
    const std::size_t n = sizeof(float) * static_cast<std::size_t>(slice.varyings);
    std::byte* varyings = record + kSetupBytes + kPlaneHeadBytes;
    std::memcpy(varyings, planes.a0, n);
    std::memcpy(varyings + n, planes.d1, n);
    std::memcpy(varyings + 2 * n, planes.d2, n);

    const auto offset = static_cast<std::uint32_t>(at);
    const PixelRect& b = setup.box;
    for (int ty = b.y0 / kTileSize; ty <= b.y1 / kTileSize; ++ty)
        for (int tx = b.x0 / kTileSize; tx <= b.x1 / kTileSize; ++tx) {
            const auto tile = static_cast<std::size_t>(ty * slice.tilesX + tx);
            std::vector<std::uint32_t>& bin = slice.bins[tile];
            if (bin.empty()) slice.touched.push_back(static_cast<std::uint32_t>(tile));
            bin.push_back(offset);
        }
    return 0;  // fragments are counted when the tiles are rasterized
}

std::size_t TileRenderer::rasterizeTile(int tile, int tilesX, int width, int height,
                                        RasterizeFn rasterize, void* context, std::size_t first,
                                        std::size_t count) const {
    const int x0 = tile % tilesX * kTileSize, y0 = tile / tilesX * kTileSize;
    const PixelRect rect{x0, y0, std::min(x0 + kTileSize, width) - 1,
                         std::min(y0 + kTileSize, height) - 1};
    std::size_t fragments = 0;
    CoverageSetup setup;
    Planes planes{};  // the varyings past the layout's are never read
    for (std::size_t s = first; s < first + count; ++s) {  // in submission order
        const Slice& slice = slices_[s];
        const std::size_t n = sizeof(float) * static_cast<std::size_t>(slice.varyings);
        for (const std::uint32_t r : slice.bins[static_cast<std::size_t>(tile)]) {
            const std::byte* record = slice.records.data() + r;
            std::memcpy(&setup, record, kSetupBytes);
            // Most triangles of a dense mesh lie in one tile: their setup needs no clipping.
            if (!contains(rect, setup.box)) {
                setup = restrictSetup(setup, rect);
                if (setup.box.empty()) continue;
            }
            // Planes is trivially copyable; its head is a prefix of its layout.
            std::memcpy(static_cast<void*>(&planes), record + kSetupBytes, kPlaneHeadBytes);
            const std::byte* varyings = record + kSetupBytes + kPlaneHeadBytes;
            std::memcpy(planes.a0, varyings, n);
            std::memcpy(planes.d1, varyings + n, n);
            std::memcpy(planes.d2, varyings + 2 * n, n);
            fragments += rasterize(context, setup, planes);
        }
    }
    return fragments;
}

void TileRenderer::draw(const DrawInput& in, const VaryingLayout& layout, bool cull, int width,
                        int height, RasterizeFn rasterize, void* context, int threads,
                        int subPixelBits, RenderStats& stats, int sampleReach) {
    const std::size_t triangles = in.indices.size() / 3;
    if (width <= 0 || height <= 0 || triangles == 0) return;
    const int tilesX = (width + kTileSize - 1) / kTileSize;
    const int tilesY = (height + kTileSize - 1) / kTileSize;
    const int tiles = tilesX * tilesY;
    const auto n = static_cast<std::size_t>(std::max(1, threads));
    // Several threads: two sets of n slices, the batch being binned and the batch being
    // rasterized (see below). One thread draws the previous batch's tiles before it bins the
    // next batch, so one set serves both and stays in cache (with two, the bunny took 15 % more
    // time at 1 thread).
    const std::size_t sets = n == 1 ? 1 : 2;
    if (slices_.size() < sets * n) slices_.resize(sets * n);
    fragments_.assign(n, 0);
    for (std::size_t s = 0; s < sets * n; ++s) {
        Slice& slice = slices_[s];
        slice.tilesX = tilesX;
        if (slice.bins.size() != static_cast<std::size_t>(tiles)) {
            slice.bins.assign(static_cast<std::size_t>(tiles), {});
            slice.touched.clear();
        }
        slice.stats = {};
        slice.varyings = layout.count();
        slice.recordBytes = recordBytes(slice.varyings);
    }
    const std::size_t batch = (n == 1 ? kBatchPerThread : kBatchPerThreadShared) * n;
    const std::size_t batches = (triangles + batch - 1) / batch;
    const int slices = static_cast<int>(n);
    const int tasks = slices + tiles;  // per step: the front end's slices, then the tiles
    const ScreenSpace space = ScreenSpace::of(width, height, in.nearPlane, subPixelBits);
    const auto vertices = static_cast<std::ptrdiff_t>(in.clip.size());
    screen_.resize(in.clip.size());  // grown, never shrunk: a steady frame allocates nothing
    ScreenVertex* screen = screen_.data();

#pragma omp parallel num_threads(slices)
    {
        // The vertex pass: what each vertex gives every triangle around it, computed once.
#pragma omp for schedule(static)
        for (std::ptrdiff_t i = 0; i < vertices; ++i)
            screen[i] = space.vertex(in.clip[static_cast<std::size_t>(i)]);

        // Step k bins batch k into slice set k % sets and rasterizes the tiles of batch k − 1
        // from the other set, as one work list: one barrier per batch instead of two (a
        // barrier waits for the slowest thread, on a loaded machine one that was descheduled),
        // and a thread done with its slice draws tiles instead of waiting. All tiles of batch
        // k − 1 are done (the barrier) before any tile of batch k starts, so every pixel still
        // sees its fragments in submission order, whatever the thread count.
        std::size_t fragments = 0;
        for (std::size_t k = 0; k <= batches; ++k) {
            Slice* produce = slices_.data() + (k % sets) * n;
            const std::size_t consume = ((k + 1) % sets) * n;
            const std::size_t b0 = k * batch, b1 = std::min(triangles, b0 + batch);
#pragma omp for schedule(dynamic, 1)
            for (int task = 0; task < tasks; ++task) {
                // Several threads: the slices first, being the longest tasks. One thread: the
                // tiles first, since they read the set that its slice then overwrites.
                const int t = n == 1 ? (task + slices) % tasks : task;
                if (t < slices) {
                    if (k == batches) continue;
                    Slice& slice = produce[t];
                    for (const std::uint32_t tile : slice.touched) slice.bins[tile].clear();
                    slice.touched.clear();
                    slice.used = 0;
                    const auto s = static_cast<std::size_t>(t);
                    const std::size_t first = b0 + (b1 - b0) * s / n;
                    const std::size_t end = b0 + (b1 - b0) * (s + 1) / n;
                    drawTriangles(in, layout, cull, width, height, first, end, &binTriangle, &slice,
                                  slice.stats, subPixelBits, sampleReach, screen);
                } else if (k > 0) {
                    fragments += rasterizeTile(t - slices, tilesX, width, height, rasterize,
                                               context, consume, n);
                }
            }
        }
        fragments_[static_cast<std::size_t>(omp_get_thread_num())] = fragments;
    }
    for (std::size_t s = 0; s < sets * n; ++s) addCounters(stats, slices_[s].stats);
    for (std::size_t s = 0; s < n; ++s) stats.fragments += fragments_[s];
}

}  // namespace facet::detail
