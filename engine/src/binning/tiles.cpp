// Sort-middle rasterization on OpenMP threads (see tile_renderer.hpp).

#include "binning/tiles.hpp"

#include <algorithm>

#include <omp.h>

namespace facet::detail {
namespace {

/// Triangles each thread's front end takes per batch: big enough that the two barriers per
/// batch cost little, small enough that a batch's records (about 300 bytes each) stay in cache.
constexpr std::size_t kBatchPerThread = 8192;

/// The setup restricted to `rect`; the edge values move to the new first pixel exactly, in
/// integers, so coverage inside the rectangle is unchanged.
CoverageSetup clipSetup(const CoverageSetup& s, const PixelRect& rect) {
    CoverageSetup out = s;
    out.box = {std::max(s.box.x0, rect.x0), std::max(s.box.y0, rect.y0),
               std::min(s.box.x1, rect.x1), std::min(s.box.y1, rect.y1)};
    if (out.box.empty()) return out;
    const std::int64_t dx = out.box.x0 - s.box.x0, dy = out.box.y0 - s.box.y0;
    for (int i = 0; i < 3; ++i) out.e0[i] = s.e0[i] + dx * s.stepX[i] + dy * s.stepY[i];
    return out;
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
    const auto index = static_cast<std::uint32_t>(slice.records.size());
    slice.records.push_back({setup, planes});
    const PixelRect& b = setup.box;
    for (int ty = b.y0 / kTileSize; ty <= b.y1 / kTileSize; ++ty)
        for (int tx = b.x0 / kTileSize; tx <= b.x1 / kTileSize; ++tx) {
            const auto tile = static_cast<std::size_t>(ty * slice.tilesX + tx);
            std::vector<std::uint32_t>& bin = slice.bins[tile];
            if (bin.empty()) slice.touched.push_back(static_cast<std::uint32_t>(tile));
            bin.push_back(index);
        }
    return 0;  // fragments are counted when the tiles are rasterized
}

std::size_t TileRenderer::rasterizeTile(int tile, int tilesX, int width, int height,
                                        RasterizeFn rasterize, void* context,
                                        std::size_t slices) const {
    const int x0 = tile % tilesX * kTileSize, y0 = tile / tilesX * kTileSize;
    const PixelRect rect{x0, y0, std::min(x0 + kTileSize, width) - 1,
                         std::min(y0 + kTileSize, height) - 1};
    std::size_t fragments = 0;
    for (std::size_t s = 0; s < slices; ++s) {  // in submission order
        const Slice& slice = slices_[s];
        for (const std::uint32_t r : slice.bins[static_cast<std::size_t>(tile)]) {
            const Record& record = slice.records[r];
            const CoverageSetup part = clipSetup(record.setup, rect);
            if (!part.box.empty()) fragments += rasterize(context, part, record.planes);
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
    if (slices_.size() < n) slices_.resize(n);
    fragments_.assign(n, 0);
    for (std::size_t s = 0; s < n; ++s) {
        Slice& slice = slices_[s];
        slice.tilesX = tilesX;
        if (slice.bins.size() != static_cast<std::size_t>(tiles)) {
            slice.bins.assign(static_cast<std::size_t>(tiles), {});
            slice.touched.clear();
        }
        slice.stats = {};
    }
    const std::size_t batch = kBatchPerThread * n;
    const int slices = static_cast<int>(n);

#pragma omp parallel num_threads(slices)
    {
        std::size_t fragments = 0;
        for (std::size_t b0 = 0; b0 < triangles; b0 += batch) {
            const std::size_t b1 = std::min(triangles, b0 + batch);
#pragma omp for schedule(static)
            for (int s = 0; s < slices; ++s) {
                Slice& slice = slices_[static_cast<std::size_t>(s)];
                for (const std::uint32_t tile : slice.touched) slice.bins[tile].clear();
                slice.touched.clear();
                slice.records.clear();
                const std::size_t first = b0 + (b1 - b0) * static_cast<std::size_t>(s) / n;
                const std::size_t end = b0 + (b1 - b0) * static_cast<std::size_t>(s + 1) / n;
                drawTriangles(in, layout, cull, width, height, first, end, &binTriangle, &slice,
                              slice.stats, subPixelBits, sampleReach);
            }
#pragma omp for schedule(dynamic, 1)
            for (int tile = 0; tile < tiles; ++tile)
                fragments += rasterizeTile(tile, tilesX, width, height, rasterize, context, n);
        }
        fragments_[static_cast<std::size_t>(omp_get_thread_num())] = fragments;
    }
    for (std::size_t s = 0; s < n; ++s) {
        addCounters(stats, slices_[s].stats);
        stats.fragments += fragments_[s];
    }
}

}  // namespace facet::detail
