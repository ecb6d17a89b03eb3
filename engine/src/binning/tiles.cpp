// Sort-middle rasterization on OpenMP threads (see tiles.hpp).

#include "binning/tiles.hpp"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <new>
#include <type_traits>
#include <utility>

#include <omp.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "facet/limits.hpp"
#include "frontend/front_end_loop.hpp"
#include "passes/frame_passes.hpp"
#include "passes/supersample.hpp"

namespace facet::detail {
namespace {

/// Triangles each thread's front end takes per batch. One thread: few enough that the batch's
/// records (64 to 248 bytes each) and bins are still in the core's L2 when its tiles read them
/// (with 8192 the tile loop waited on memory for every record). Several threads: every batch
/// costs two barriers, and on a loaded machine a barrier waits for a descheduled thread's next
/// time slice; the bunny at 2 threads took twice as long with 2048 as with 8192 (load 17 on 2
/// cores), so there the batch stays large.
constexpr std::size_t kBatchPerThread = 2048;
constexpr std::size_t kBatchPerThreadShared = 8192;

/// How many times a one-batch draw's triangle boxes must cover the frame for its tiles to be
/// drawn in the tile buffer (see run()).
constexpr std::uint64_t kResidentOverdraw = 2;

/// Bytes of a record with `varyings` varyings, a multiple of 8 so that the edges stay aligned.
constexpr std::size_t recordBytes(int varyings) {
    const std::size_t planes =
        varyings == 0 ? 0 : kWeightBytes + 3 * sizeof(float) * static_cast<std::size_t>(varyings);
    return (sizeof(RecordHead) + planes + 7) / 8 * 8;
}
static_assert(recordBytes(0) == sizeof(TileRenderer::Line), "a painter triangle is one line");
// Every frame the engine draws has its sides within RecordHead's 16-bit coordinates.
static_assert(std::int64_t{kMaxImageSide} * kMaxSupersample <= kMaxRecordSide);

/// Writes the head of a record in place (records start at multiples of 8 bytes in cache-line
/// aligned storage): a head built on the stack and copied cost a spill and a reload per field.
void writeHead(std::byte* record, const CoverageSetup& setup, const Planes& planes) {
    auto* head = new (record) RecordHead;
    for (int i = 0; i < 3; ++i) head->e0[i] = setup.e0[i];
    for (int i = 0; i < 2; ++i) {  // the vertex differences: the steps are ∓256 times them
        head->dx[i] = static_cast<std::int32_t>(setup.stepY[i] >> kSubPixelBits);
        head->dy[i] = static_cast<std::int32_t>(-(setup.stepX[i] >> kSubPixelBits));
    }
    for (int i = 0; i < 3; ++i) head->q[i] = planes.q[i];
    // Boxes and bases lie in the image (kMaxRecordSide).
    const auto u16 = [](int v) { return static_cast<std::uint16_t>(v); };
#if defined(__SSE2__)
    // The box's low halves gathered by three shuffles (GCC packed them by shifts and ORs, ten
    // instructions more per record).
    static_assert(offsetof(RecordHead, y1) == offsetof(RecordHead, x0) + 6);
    __m128i box = _mm_loadu_si128(reinterpret_cast<const __m128i*>(&setup.box));
    box = _mm_shufflelo_epi16(box, _MM_SHUFFLE(3, 3, 2, 0));  // x0, y0 in the first 32 bits
    box = _mm_shufflehi_epi16(box, _MM_SHUFFLE(3, 3, 2, 0));  // x1, y1 in the third
    box = _mm_shuffle_epi32(box, _MM_SHUFFLE(3, 3, 2, 0));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(&head->x0), box);
#else
    head->x0 = u16(setup.box.x0);
    head->y0 = u16(setup.box.y0);
    head->x1 = u16(setup.box.x1);
    head->y1 = u16(setup.box.y1);
#endif
    head->baseX = u16(planes.baseX);
    head->baseY = u16(planes.baseY);
}

void addCounters(RenderStats& to, const RenderStats& from) {
    to.trianglesIn += from.trianglesIn;
    to.trianglesCulled += from.trianglesCulled;
    to.trianglesClipped += from.trianglesClipped;
    to.trianglesRasterized += from.trianglesRasterized;
    to.frontEndMs += from.frontEndMs;
    to.binningMs += from.binningMs;
}

/// The front end's receiver in the tile renderer: appends each triangle's record to the slice
/// and one entry per tile its box touches. A type the front end's loop is instantiated with, so
/// this is a direct call, not one through a pointer and a void*. (GCC 12 keeps it out of line;
/// forcing it inline made it outline the loop's per-triangle lambda instead, 12 % more
/// instructions in the front end on the bunny.)
struct Binner {
    TileRenderer::Slice& slice;

    std::size_t operator()(const CoverageSetup& setup, const Planes& planes) const {
        TileRenderer::Slice& s = slice;
        const std::size_t at = s.used;
        if (at + s.recordBytes > s.records.size() * sizeof(TileRenderer::Line))
            s.records.resize(std::max(2 * s.records.size(),
                                      (at + s.recordBytes) / sizeof(TileRenderer::Line) + 1));
        std::byte* record = reinterpret_cast<std::byte*>(s.records.data()) + at;
        s.used = at + s.recordBytes;
        writeHead(record, setup, planes);
        if (s.varyings > 0) {
            std::byte* rest = record + sizeof(RecordHead);
            std::memcpy(rest, planes.l1, kWeightBytes);
            rest += kWeightBytes;
            withVaryingCount(s.varyings, [&](auto count) {
                constexpr std::size_t n = sizeof(float) * decltype(count)::value;
                std::memcpy(rest, planes.a0, n);
                std::memcpy(rest + n, planes.d1, n);
                std::memcpy(rest + 2 * n, planes.d2, n);
            });
        }

        const auto offset = static_cast<std::uint32_t>(at);
        // Boxes lie in the image (coordinates ≥ 0): unsigned division is a shift.
        const PixelRect& b = setup.box;
        const auto tile = [](int v) {
            return static_cast<int>(static_cast<unsigned>(v) / unsigned{kTileSize});
        };
        const int tx0 = tile(b.x0), tx1 = tile(b.x1);
        const int ty0 = tile(b.y0), ty1 = tile(b.y1);
        const auto tiles = static_cast<std::size_t>((tx1 - tx0 + 1) * (ty1 - ty0 + 1));
        if (s.entryCount + tiles > s.entries.size())
            s.entries.resize(std::max(2 * s.entries.size(), s.entryCount + tiles));
        TileRenderer::BinEntry* entry = s.entries.data() + s.entryCount;
        s.entryCount += tiles;
        s.boxPixels += static_cast<std::uint64_t>(b.x1 - b.x0 + 1) *
                       static_cast<std::uint64_t>(b.y1 - b.y0 + 1);
        if (tiles == 1) {  // most triangles of a dense mesh lie in one tile
            *entry = {static_cast<std::uint32_t>(ty0 * s.tilesX + tx0), offset};
            return 0;
        }
        for (int ty = ty0; ty <= ty1; ++ty)
            for (int tx = tx0; tx <= tx1; ++tx)
                *entry++ = {static_cast<std::uint32_t>(ty * s.tilesX + tx), offset};
        return 0;  // fragments are counted when the tiles are rasterized
    }
};

/// Sorts the slice's entries by tile (a counting sort, stable: each tile's records stay in
/// submission order) into order[start[t] … start[t + 1]).
void sortByTile(TileRenderer::Slice& s) {
    std::fill(s.start.begin(), s.start.end(), 0u);
    const TileRenderer::BinEntry* entries = s.entries.data();
    for (std::size_t i = 0; i < s.entryCount; ++i) ++s.start[entries[i].tile + 1];
    const std::size_t tiles = s.cursor.size();
    for (std::size_t t = 0; t < tiles; ++t) {
        s.start[t + 1] += s.start[t];
        s.cursor[t] = s.start[t];
    }
    // kPrefetchAhead entries more, for the tile loop's prefetch past the last record: offsets
    // of records in the slice's storage (zero when new, else a batch's before).
    const std::size_t needed = s.entryCount + kPrefetchAhead;
    if (s.order.size() < needed) s.order.resize(std::max(2 * s.order.size(), needed));
    std::uint32_t* order = s.order.data();
    for (std::size_t i = 0; i < s.entryCount; ++i)
        order[s.cursor[entries[i].tile]++] = entries[i].offset;
}

using Clock = std::chrono::steady_clock;

std::atomic<TileBufferUse> gTileBuffer{TileBufferUse::Overdrawn};
std::atomic<bool> gHiZ{true};
std::atomic<bool> gBlockHiZ{false};

/// Frames of more bytes (colour and depth) than this are written back with streaming stores.
/// A plain copy reads each line of the frame into the cache before overwriting it; on a frame
/// far larger than the caches that doubled the write-back's traffic (8 full-screen layers at 4K,
/// 1 thread: 111 ms with plain copies, 90 with streaming stores; at 1080p 25 against 22). A frame
/// that stays in the caches is better copied plainly: streaming stores send every line to
/// memory (the course's example0, 512×512: 0.41 ms a frame plainly, 0.92 streamed; 720p: equal).
constexpr std::size_t kStreamFrameBytes = std::size_t{8} << 20;

/// Whether a frame of `pixels` (colour and depth) is larger than the caches: kStreamFrameBytes.
constexpr bool largerThanCaches(std::size_t pixels) {
    return pixels * (sizeof(std::uint32_t) + sizeof(float)) > kStreamFrameBytes;
}

/// Copies `bytes` (a multiple of 4) from `from` to `to`: with streaming stores when `stream` and
/// `to` is 16-byte aligned, else plainly.
void copyRow(void* to, const void* from, std::size_t bytes, [[maybe_unused]] bool stream) {
#if defined(__SSE2__)
    if (stream && (reinterpret_cast<std::uintptr_t>(to) & 15u) == 0) {
        auto* d = static_cast<__m128i*>(to);
        const auto* s = static_cast<const __m128i*>(from);
        const std::size_t vectors = bytes / 16;
        for (std::size_t i = 0; i < vectors; ++i) _mm_stream_si128(d + i, _mm_loadu_si128(s + i));
        std::memcpy(d + vectors, s + vectors, bytes % 16);
        return;
    }
#endif
    std::memcpy(to, from, bytes);
}

/// Writes the tile `rect` of `buffer` (rows kTileSize apart) into the frame, a row at a time.
void writeTile(const TileRenderer::TileBuffer& buffer, const PixelRect& rect, Framebuffer& fb) {
    const auto w = static_cast<std::size_t>(rect.x1 - rect.x0 + 1);
    const bool stream = largerThanCaches(fb.color.size());
    for (int y = rect.y0; y <= rect.y1; ++y) {
        const std::size_t from = static_cast<std::size_t>(y - rect.y0) * kTileSize;
        const std::size_t to = fb.index(rect.x0, y);
        copyRow(fb.color.data() + to, buffer.color + from, w * sizeof(std::uint32_t), stream);
        copyRow(fb.depth.data() + to, buffer.depth + from, w * sizeof(float), stream);
    }
#if defined(__SSE2__)
    if (stream) _mm_sfence();  // the streamed lines are visible before the frame is read
#endif
}

/// Clears the tile `rect` of the frame: a tile no triangle touched.
void clearTile(const PixelRect& rect, std::uint32_t background, Framebuffer& fb) {
    const auto w = static_cast<std::size_t>(rect.x1 - rect.x0 + 1);
    for (int y = rect.y0; y <= rect.y1; ++y) {
        const std::size_t at = fb.index(rect.x0, y);
        clearPixels(fb, background, at, at + w);
    }
}

double msBetween(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

}  // namespace

void useTileBuffer(TileBufferUse use) {
    gTileBuffer.store(use, std::memory_order_relaxed);
}

void enableHiZ(bool enabled) {
    gHiZ.store(enabled, std::memory_order_relaxed);
}

void enableBlockHiZ(bool enabled) {
    gBlockHiZ.store(enabled, std::memory_order_relaxed);
}

int resolveThreads(int requested) {
    if (requested > 0) return requested;
    return std::max(1, omp_get_num_procs());
}

void TileRenderer::run(const DrawJob& job, int threads, RenderStats& stats, TileDrawer drawer,
                       const TileFrame& frame) {
    const DrawInput& in = *job.in;
    const int width = job.width, height = job.height;
    const std::size_t triangles = in.indices.size() / 3;
    if (width <= 0 || height <= 0) return;
    assert(width <= kMaxRecordSide && height <= kMaxRecordSide);  // see kMaxRecordSide
    const auto n = static_cast<std::size_t>(std::max(1, threads));
    const std::size_t batch = (n == 1 ? kBatchPerThread : kBatchPerThreadShared) * n;
    const std::size_t batches = (triangles + batch - 1) / batch;
    // Tile-resident: each tile's pixels are cleared in a thread's tile buffer, drawn there and
    // written to the frame once. Only when the draw is one batch, so that each tile is visited
    // once: with several, a tile would be read back and written once per batch that touches it
    // (the bunny's 34 batches at 1 thread), more memory traffic than drawing in the frame. And
    // only when the batch's boxes cover the frame kResidentOverdraw times or more (decided once
    // it is binned): writing every tile back costs about what the clear pass does, so it pays
    // where triangles overdraw (8 full-screen layers at 4K: 75 -> 46 ms at 2 threads), not on a
    // model covering part of the frame once (Spot at 1080p, 2 threads: 3.1 -> 3.7 ms). And only
    // on a frame larger than the caches (kStreamFrameBytes): one that stays in them gains nothing
    // from fewer trips to memory and pays the buffer's fill and copy (the course's example0,
    // 512×512, a cube: 0.34 ms a frame drawn in the frame, 0.41 in the tile buffer).
    const TileBufferUse use = gTileBuffer.load(std::memory_order_relaxed);
    const bool mayReside =
        frame.fb != nullptr && frame.clear && batches == 1 && triangles > 0 &&
        (use == TileBufferUse::Always ||
         (use == TileBufferUse::Overdrawn &&
          largerThanCaches(static_cast<std::size_t>(width) * static_cast<std::size_t>(height))));
    if (frame.fb != nullptr && frame.clear && !mayReside) {
        const Clock::time_point t0 = Clock::now();
        clearFrame(*frame.fb, frame.background, threads);
        stats.clearMs += msBetween(t0, Clock::now());
    }
    if (triangles == 0) return;
    const int tilesX = (width + kTileSize - 1) / kTileSize;
    const int tilesY = (height + kTileSize - 1) / kTileSize;
    const int tiles = tilesX * tilesY;
    width_ = width;
    height_ = height;
    tilesX_ = tilesX;
    const bool hiZ = frame.fb != nullptr && frame.hiZ && gHiZ.load(std::memory_order_relaxed);
    // Without a clear, the frame's depths are unknown: every block stale, so that the first
    // test a block's bound would fail reads them.
    if (hiZ)
        depths_.assign(static_cast<std::size_t>(tiles),
                       TileDepth{!frame.clear, gBlockHiZ.load(std::memory_order_relaxed)});
    if (mayReside && buffers_.size() < n) buffers_.resize(n);
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
        slice.start.assign(static_cast<std::size_t>(tiles) + 1, 0u);  // no allocation when equal
        slice.cursor.resize(static_cast<std::size_t>(tiles));
        slice.entryCount = 0;
        slice.boxPixels = 0;
        slice.used = 0;
        slice.stats = {};
        slice.varyings = job.layout.count();
        slice.recordBytes = recordBytes(slice.varyings);
    }
    const int slices = static_cast<int>(n);
    const ScreenSpace space = ScreenSpace::of(width, height, in.nearPlane, job.subPixelBits);
    const auto vertices = static_cast<std::ptrdiff_t>(in.clip.size());
    screen_.resize(in.clip.size());  // grown, never shrunk: a steady frame allocates nothing
    ScreenVertex* screen = screen_.data();
    DrawJob binned = job;
    binned.screen = screen;
    binned.lanes = laneSetup();  // the SIMD target, chosen once per draw

    // Thread i's share of the frame: tiles [tileShareBegin(i), tileShareBegin(i + 1)), rows of
    // tiles from the top, as the in-draw clear below splits the frame's pixels. The shares of
    // step k are set during step k − 1 (below), so none is set here.
    const auto tileShareBegin = [&](std::size_t i) {
        return static_cast<int>(static_cast<std::size_t>(tiles) * i / n);
    };
    if (shares_.size() < 2 * n) shares_ = std::vector<TileShare>(2 * n);
    double clearMs = 0;  // the in-draw clear pass when the batch does not reside
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
        bool resident = false;
        for (std::size_t k = 0; k <= batches; ++k) {
            if (mayReside && k == 1) {  // the one batch is binned (the barrier): reside or clear
                std::uint64_t boxPixels = 0;
                for (std::size_t s = 0; s < n; ++s) boxPixels += slices_[s].boxPixels;
                resident = use == TileBufferUse::Always ||
                           boxPixels >= kResidentOverdraw * static_cast<std::uint64_t>(width) *
                                            static_cast<std::uint64_t>(height);
                if (!resident) {  // every thread takes the same branch: the loop is shared
                    const Clock::time_point t0 = Clock::now();
                    const std::size_t pixels = frame.fb->color.size();
                    const auto parts = static_cast<std::ptrdiff_t>(n);
#pragma omp for schedule(static)
                    for (std::ptrdiff_t p = 0; p < parts; ++p) {
                        const auto i = static_cast<std::size_t>(p);
                        clearPixels(*frame.fb, frame.background, pixels * i / n,
                                    pixels * (i + 1) / n);
                    }
                    if (omp_get_thread_num() == 0) clearMs = msBetween(t0, Clock::now());
                }
            }
            Slice* produce = slices_.data() + (k % sets) * n;
            const std::size_t consume = ((k + 1) % sets) * n;
            const std::size_t b0 = k * batch, b1 = std::min(triangles, b0 + batch);
            const auto bin = [&](std::size_t s) {  // the front end of slice s of batch k
                Slice& slice = produce[s];
                slice.entryCount = 0;
                slice.boxPixels = 0;
                slice.used = 0;
                const std::size_t first = b0 + (b1 - b0) * s / n;
                const std::size_t end = b0 + (b1 - b0) * (s + 1) / n;
                // Clocked per batch, not per triangle: the front end with the records'
                // writes inlined, then the sort of its records into the tiles' bins.
                const Clock::time_point t0 = Clock::now();
                front::frontEnd(binned, first, end, Binner{slice}, slice.stats);
                const Clock::time_point t1 = Clock::now();
                sortByTile(slice);
                const Clock::time_point t2 = Clock::now();
                slice.stats.frontEndMs += msBetween(t0, t1);
                slice.stats.binningMs += msBetween(t1, t2);
            };
            if (n == 1) {  // the tiles first: they read the set that the slice then overwrites
                if (k > 0)
                    for (int tile = 0; tile < tiles; ++tile)
                        fragments += drawTile(tile, consume, n, drawer, frame, resident, hiZ);
                if (k < batches) bin(0);
                continue;
            }
            // Several threads: each bins its own slice (the vertices its vertex pass wrote),
            // then draws the tiles of batch k − 1 from its own share of the frame, then helps
            // with the others' (see TileShare). Tile t is drawn by the same thread in every
            // batch unless another ran out of work first, so its colour and depth stay in that
            // core's cache between batches instead of moving to whichever thread took it.
            // The team may be smaller than asked (a thread limit): thread i then does the
            // slices and shares i, i + team, ...
            const auto me = static_cast<std::size_t>(omp_get_thread_num());
            const auto team = static_cast<std::size_t>(omp_get_num_threads());
            for (std::size_t s = me; s < n; s += team) {
                shares_[((k + 1) % 2) * n + s].next.store(  // for step k + 1, after the barrier
                    tileShareBegin(s), std::memory_order_relaxed);
                if (k < batches) bin(s);
            }
            if (k > 0)
                for (std::size_t r = 0; r < n; ++r) {
                    const std::size_t owner = (me + r) % n;
                    TileShare& share = shares_[(k % 2) * n + owner];
                    const int end = tileShareBegin(owner + 1);
                    for (int tile = share.next.fetch_add(1, std::memory_order_relaxed); tile < end;
                         tile = share.next.fetch_add(1, std::memory_order_relaxed))
                        fragments += drawTile(tile, consume, n, drawer, frame, resident, hiZ);
                }
#pragma omp barrier
        }
        fragments_[static_cast<std::size_t>(omp_get_thread_num())] = fragments;
    }
    stats.clearMs += clearMs;
    for (std::size_t s = 0; s < sets * n; ++s) addCounters(stats, slices_[s].stats);
    for (std::size_t s = 0; s < n; ++s) stats.fragments += fragments_[s];
    if (hiZ)
        for (const TileDepth& d : depths_) stats.hiZTriangles += d.rejected;
}

std::size_t TileRenderer::drawTile(int tile, std::size_t first, std::size_t count,
                                   TileDrawer drawer, const TileFrame& frame, bool resident,
                                   bool hiZ) {
    const int x0 = tile % tilesX_ * kTileSize, y0 = tile / tilesX_ * kTileSize;
    const PixelRect rect{x0, y0, std::min(x0 + kTileSize, width_) - 1,
                         std::min(y0 + kTileSize, height_) - 1};
    const auto at = static_cast<std::size_t>(tile);
    bool any = false;
    for (std::size_t s = first; s < first + count; ++s)
        any = any || slices_[s].start[at] != slices_[s].start[at + 1];
    if (!any) {  // no triangle here in this batch: when resident, the clear value straight away
        if (resident) clearTile(rect, frame.background, *frame.fb);
        return 0;
    }
    TileDepth* bound = hiZ ? &depths_[at] : nullptr;
    if (!resident) {
        PixelTarget target;  // unused by a raster that writes elsewhere (frame.fb null)
        if (frame.fb != nullptr) {
            target = PixelTarget::frame(*frame.fb);
            target.tile = rect;
            target.bound = bound;
        }
        return drawer.draw(*this, drawer.raster, {tile, first, count, &target});
    }
    Framebuffer& fb = *frame.fb;
    TileBuffer& buffer = buffers_[static_cast<std::size_t>(omp_get_thread_num())];
    std::fill(std::begin(buffer.color), std::end(buffer.color), frame.background);
    std::fill(std::begin(buffer.depth), std::end(buffer.depth), kEmptyDepth);
    const PixelTarget target{
        buffer.color, buffer.depth,
        kTileSize,    static_cast<std::size_t>(y0) * kTileSize + static_cast<std::size_t>(x0),
        rect,         bound};
    const std::size_t fragments = drawer.draw(*this, drawer.raster, {tile, first, count, &target});
    writeTile(buffer, rect, fb);
    return fragments;
}

}  // namespace facet::detail
