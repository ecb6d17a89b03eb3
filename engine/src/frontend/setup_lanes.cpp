// The front end's setup stage in vector lanes (LaneSetupFn, front_end.hpp), compiled once per SIMD
// target: hwy/foreach_target.h compiles this file once for each target Highway enables (the span
// loop's), and HWY_DYNAMIC_DISPATCH picks the best one the CPU has, once per draw.
//
// One lane per triangle: the vertex pass's snapped positions and flags are gathered, and the
// reject (classify()), the facing and cull (snapTriangle()'s area in 32 bits, exact for boxes
// under kLaneExtent), the pixel box and the exit for an empty box run for a whole vector of
// triangles at once, the scalar stages' integer arithmetic lane by lane. The survivors are
// compressed into the chunk in submission order with the triangles the lanes leave to the
// scalar path, so the loop that follows emits exactly what the scalar front end emits.

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "frontend/setup_lanes.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

#include <hwy/highway.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "coverage/coverage.hpp"
#include "frontend/front_end.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;

using Di = hn::ScalableTag<std::int32_t>;
using Du = hn::RebindToUnsigned<Di>;
using VecI = hn::Vec<Di>;
using VecU = hn::Vec<Du>;
using MaskI = hn::Mask<Di>;

static_assert(sizeof(ScreenVertex) == 3 * sizeof(std::int32_t));

/// Lanes where flag bit `bit` of `flags` is set.
HWY_INLINE MaskI hasFlag(VecI flags, std::uint32_t bit) {
    const Di d;
    const VecI b = hn::Set(d, static_cast<std::int32_t>(bit));
    return hn::Ne(hn::And(flags, b), hn::Zero(d));
}

/// Bit i set where lane i of `m` is true.
HWY_INLINE std::uint64_t laneBits(MaskI m) {
    std::uint8_t bytes[8] = {};
    hn::StoreMaskBits(Di(), m, bytes);
    std::uint64_t bits = 0;
    for (int i = 0; i < 8; ++i) bits |= std::uint64_t{bytes[i]} << (8 * i);
    return bits;
}

/// Triangles first + [0, present) of the chunk that starts at `chunk` (present ≤ the lanes; a
/// chunk's tail has fewer).
HWY_INLINE void setupVector(const LaneInput& in, std::size_t chunk, std::size_t first,
                            std::size_t present, LaneChunk& out) {
    const Di d;
    const Du du;
    const std::size_t n = hn::Lanes(d);
    // The indices, three per triangle; a tail's missing triangles read as invalid indices.
    VecU i0, i1, i2;
    if (present == n) {
        hn::LoadInterleaved3(du, in.indices + 3 * first, i0, i1, i2);
    } else {
        HWY_ALIGN std::uint32_t tail[3 * HWY_MAX_BYTES / sizeof(std::uint32_t)];
        std::fill(tail, tail + 3 * n, 0xFFFFFFFFu);
        std::copy(in.indices + 3 * first, in.indices + 3 * (first + present), tail);
        hn::LoadInterleaved3(du, tail, i0, i1, i2);
    }
    // Indices past the clip positions: the scalar loop skips the triangle, uncounted.
    const VecU nv = hn::Set(du, static_cast<std::uint32_t>(in.vertices));
    const MaskI valid =
        hn::RebindMask(d, hn::And(hn::And(hn::Lt(i0, nv), hn::Lt(i1, nv)), hn::Lt(i2, nv)));
    // ScreenVertex i is three int32 at 3i: gathered where valid, vertex 0's elsewhere.
    const auto* base = reinterpret_cast<const std::int32_t*>(in.screen);
    const VecI three = hn::Set(d, 3);
    const VecI o0 = hn::Mul(hn::IfThenElseZero(valid, hn::BitCast(d, i0)), three);
    const VecI o1 = hn::Mul(hn::IfThenElseZero(valid, hn::BitCast(d, i1)), three);
    const VecI o2 = hn::Mul(hn::IfThenElseZero(valid, hn::BitCast(d, i2)), three);
    const VecI f0 = hn::GatherIndex(d, base + 2, o0);
    const VecI f1 = hn::GatherIndex(d, base + 2, o1);
    const VecI f2 = hn::GatherIndex(d, base + 2, o2);

    // classify(): Nowhere (settled here), CrossesNear (the scalar path) or InFront; and beyond
    // the guard band (the scalar path too).
    const VecI all = hn::And(hn::And(f0, f1), f2);
    const VecI any = hn::Or(hn::Or(f0, f1), f2);
    constexpr std::uint32_t kOutside =
        ScreenVertex::kLeft | ScreenVertex::kRight | ScreenVertex::kAbove | ScreenVertex::kBelow;
    const MaskI allFront = hasFlag(all, ScreenVertex::kFront);
    const MaskI nowhere = hn::Or(hn::Or(hn::Not(hasFlag(all, ScreenVertex::kFinite)),
                                        hn::Not(hasFlag(any, ScreenVertex::kFront))),
                                 hn::And(allFront, hasFlag(all, kOutside)));
    const MaskI reaches = hn::AndNot(nowhere, valid);
    MaskI scalar = hn::AndNot(hn::And(allFront, hasFlag(all, ScreenVertex::kInGuard)), reaches);
    MaskI lanes = hn::AndNot(scalar, reaches);
    MaskI emit = hn::FirstN(d, 0);

    if (!hn::AllFalse(d, lanes)) {
        const VecI x0 = hn::GatherIndex(d, base, o0), y0 = hn::GatherIndex(d, base + 1, o0);
        VecI x1 = hn::GatherIndex(d, base, o1), y1 = hn::GatherIndex(d, base + 1, o1);
        VecI x2 = hn::GatherIndex(d, base, o2), y2 = hn::GatherIndex(d, base + 1, o2);
        // The box on the grid; wider than the lanes' 32-bit products allow: the scalar path.
        const VecI minX = hn::Min(hn::Min(x0, x1), x2), maxX = hn::Max(hn::Max(x0, x1), x2);
        const VecI minY = hn::Min(hn::Min(y0, y1), y2), maxY = hn::Max(hn::Max(y0, y1), y2);
        const VecI extent = hn::Set(d, kLaneExtent);
        const MaskI narrow =
            hn::And(hn::Lt(hn::Sub(maxX, minX), extent), hn::Lt(hn::Sub(maxY, minY), extent));
        scalar = hn::Or(scalar, hn::AndNot(narrow, lanes));
        lanes = hn::And(lanes, narrow);

        // snapTriangle(): twice the signed area, the facing, the cull and the winding made
        // positive (vertices 1 and 2 swapped where the area is negative).
        const VecI zero = hn::Zero(d);
        VecI area = hn::Sub(hn::Mul(hn::Sub(x1, x0), hn::Sub(y2, y0)),
                            hn::Mul(hn::Sub(y1, y0), hn::Sub(x2, x0)));
        const MaskI degenerate = hn::Eq(area, zero);
        const MaskI front = hn::Lt(area, zero);
        const MaskI culled = in.cull ? hn::Gt(area, zero) : hn::FirstN(d, 0);
        const MaskI drawn = hn::AndNot(hn::Or(degenerate, culled), lanes);
        out.trianglesCulled += hn::CountTrue(d, hn::And(culled, lanes));
        out.trianglesRasterized += hn::CountTrue(d, drawn);
        const VecI sx = hn::IfThenElse(front, x2, x1), sy = hn::IfThenElse(front, y2, y1);
        x2 = hn::IfThenElse(front, x1, x2);
        y2 = hn::IfThenElse(front, y1, y2);
        x1 = sx;
        y1 = sy;
        area = hn::Abs(area);

        // The pixels whose centre (i·256 + 128), or with reach a sample, may be covered, within
        // the image; none: the triangle covers no pixel centre and ends here.
        const VecI reach = hn::Set(d, in.sampleReach);
        const VecI up = hn::Set(d, static_cast<std::int32_t>(kSubPixel - 1 - kSubPixel / 2));
        const VecI down = hn::Set(d, static_cast<std::int32_t>(kSubPixel / 2));
        const VecI bx0 =
            hn::Max(zero, hn::ShiftRight<kSubPixelBits>(hn::Add(hn::Sub(minX, reach), up)));
        const VecI by0 =
            hn::Max(zero, hn::ShiftRight<kSubPixelBits>(hn::Add(hn::Sub(minY, reach), up)));
        const VecI bx1 =
            hn::Min(hn::Set(d, in.width - 1),
                    hn::ShiftRight<kSubPixelBits>(hn::Sub(hn::Add(maxX, reach), down)));
        const VecI by1 =
            hn::Min(hn::Set(d, in.height - 1),
                    hn::ShiftRight<kSubPixelBits>(hn::Sub(hn::Add(maxY, reach), down)));
        emit = hn::AndNot(hn::Or(hn::Gt(bx0, bx1), hn::Gt(by0, by1)), drawn);

        // SnappedTriangle's coordinates: relative to the box's first pixel corner.
        const VecI cx = hn::ShiftLeft<kSubPixelBits>(bx0);
        const VecI cy = hn::ShiftLeft<kSubPixelBits>(by0);
        const VecI xs[3] = {hn::Sub(x0, cx), hn::Sub(x1, cx), hn::Sub(x2, cx)};
        const VecI ys[3] = {hn::Sub(y0, cy), hn::Sub(y1, cy), hn::Sub(y2, cy)};
        // edgesOf(): each edge at the box's first pixel centre, top-left bias included, in 32
        // bits (exact for boxes under kLaneExtent).
        const VecI one = hn::Set(d, 1);
        const VecI half = hn::Set(d, static_cast<std::int32_t>(kSubPixel / 2));
        VecI edges[3], stepX[3], stepY[3];
        for (int i = 0; i < 3; ++i) {
            const int j = (i + 1) % 3;
            const VecI dx = hn::Sub(xs[j], xs[i]), dy = hn::Sub(ys[j], ys[i]);
            const MaskI topLeft =
                hn::Or(hn::Lt(dy, zero), hn::And(hn::Eq(dy, zero), hn::Gt(dx, zero)));
            edges[i] = hn::Sub(
                hn::Sub(hn::Mul(dx, hn::Sub(half, ys[i])), hn::Mul(dy, hn::Sub(half, xs[i]))),
                hn::IfThenZeroElse(topLeft, one));
            stepX[i] = hn::Neg(hn::ShiftLeft<kSubPixelBits>(dy));
            stepY[i] = hn::ShiftLeft<kSubPixelBits>(dx);
        }
        if (in.sampleReach == 0) {
            // coversNoCentre(): boxes of at most kNoCentreSide² pixels whose centres the edge
            // functions all leave out end here. Centre (i, j) of the box is covered where the
            // OR of its three edge values and of w − i and h − j (the box's right and bottom
            // limits as two more edges) has the sign bit clear; the AND of those ORs over the
            // centres has it clear where any centre is covered.
            const VecI w = hn::Sub(bx1, bx0), h = hn::Sub(by1, by0);  // pixels − 1
            const VecI side = hn::Set(d, kNoCentreSide);
            const MaskI small = hn::And(hn::Lt(w, side), hn::Lt(h, side));
            if (!hn::AllFalse(d, hn::And(emit, small))) {
                VecI none = hn::Set(d, -1);
                VecI row[3] = {edges[0], edges[1], edges[2]};
                for (int j = 0; j < kNoCentreSide; ++j) {
                    const VecI below = hn::Sub(h, hn::Set(d, j));
                    VecI e[3] = {row[0], row[1], row[2]};
                    for (int i = 0; i < kNoCentreSide; ++i) {
                        const VecI right = hn::Sub(w, hn::Set(d, i));
                        none = hn::And(
                            none, hn::Or(hn::Or(hn::Or(e[0], e[1]), hn::Or(e[2], right)), below));
                        for (int k = 0; k < 3; ++k) e[k] = hn::Add(e[k], stepX[k]);
                    }
                    for (int k = 0; k < 3; ++k) row[k] = hn::Add(row[k], stepY[k]);
                }
                emit = hn::AndNot(hn::And(small, hn::Lt(none, zero)), emit);
            }
        }

        if (!hn::AllFalse(d, emit)) {
            // Stored at the triangle's place in the chunk, whole vectors (no compress:
            // Highway's AVX2 compress copied a 1 KiB table per call, 16 instructions per
            // triangle).
            const std::size_t at = first - chunk;
            for (int i = 0; i < 3; ++i) {
                hn::StoreU(xs[i], d, out.x[i] + at);
                hn::StoreU(ys[i], d, out.y[i] + at);
            }
            hn::StoreU(bx0, d, out.box[0] + at);
            hn::StoreU(by0, d, out.box[1] + at);
            hn::StoreU(bx1, d, out.box[2] + at);
            hn::StoreU(by1, d, out.box[3] + at);
            hn::StoreU(area, d, out.area2 + at);
            for (int i = 0; i < 3; ++i) hn::StoreU(edges[i], d, out.e0[i] + at);
        }
    }

    // The scalar path counts its own triangles.
    out.trianglesIn += hn::CountTrue(d, hn::AndNot(scalar, valid));
    // The loop's entries, in submission order: survivors and the scalar path's triangles.
    std::uint64_t visit = laneBits(hn::Or(emit, scalar));
    if (visit == 0) return;
    const std::uint64_t slow = laneBits(scalar);
    const auto offset = static_cast<std::uint32_t>(first - chunk);
    std::uint32_t count = out.count;
    do {
        const auto lane = static_cast<std::uint32_t>(__builtin_ctzll(visit));
        out.at[count++] = (offset + lane) | ((slow >> lane & 1u) != 0 ? LaneChunk::kScalar : 0u);
        visit &= visit - 1;
    } while (visit != 0);
    out.count = count;
}

using Dd = hn::ScalableTag<double>;
using Df = hn::Rebind<float, Dd>;
using Dw = hn::Rebind<std::int32_t, Dd>;
using VecD = hn::Vec<Dd>;

/// Clip positions a survivor's gather may index: vertex i's floats start at 4i in 32 bits (and
/// its varyings at 3i or 2i).
constexpr std::size_t kPlaneVertices = std::size_t{1} << 29;

using Dv = hn::ScalableTag<float>;
using Dvi = hn::RebindToSigned<Dv>;

/// setVaryingPlanes() of the survivors `which` [0, survivors) (padded to whole vectors): each
/// varying of their three vertices gathered from its stream (a missing one's fill), a0 = a0,
/// d1 = a1 − a0, d2 = a2 − a0 in float as the scalar loop rounds them, a whole vector of floats
/// of survivors at once (twice the doubles' lanes).
HWY_INLINE void varyingsOf(const LaneInput& in, const std::int32_t* indices,
                           const std::int32_t* which, std::size_t survivors, LaneChunk& out) {
    const Dv dv;
    const Dvi dvi;
    const std::size_t n = hn::Lanes(dv);
    const VaryingStreams& streams = in.varyings;
    for (std::size_t g = 0; g < survivors; g += n) {
        const auto k3 = hn::Mul(hn::LoadU(dvi, which + g), hn::Set(dvi, 3));
        hn::Vec<Dvi> vertex[3];
        for (int j = 0; j < 3; ++j)
            vertex[j] = hn::GatherIndex(dvi, indices, hn::Add(k3, hn::Set(dvi, j)));
        std::size_t row = 0;
        for (int k = 0; k < streams.count; ++k) {
            const VaryingStream& stream = streams.s[k];
            if (stream.data == nullptr) {
                for (int c = 0; c < stream.size; ++c, ++row) {
                    hn::StoreU(hn::Set(dv, stream.fill), dv, out.varying[row] + g);
                    hn::StoreU(hn::Zero(dv), dv, out.varying[kMaxVaryings + row] + g);
                    hn::StoreU(hn::Zero(dv), dv, out.varying[2 * kMaxVaryings + row] + g);
                }
                continue;
            }
            const auto size = hn::Set(dvi, stream.size);
            const hn::Vec<Dvi> at[3] = {hn::Mul(vertex[0], size), hn::Mul(vertex[1], size),
                                        hn::Mul(vertex[2], size)};
            for (int c = 0; c < stream.size; ++c, ++row) {
                const float* from = stream.data + c;
                const auto a0 = hn::GatherIndex(dv, from, at[0]);
                const auto a1 = hn::GatherIndex(dv, from, at[1]);
                const auto a2 = hn::GatherIndex(dv, from, at[2]);
                hn::StoreU(a0, dv, out.varying[row] + g);
                hn::StoreU(hn::Sub(a1, a0), dv, out.varying[kMaxVaryings + row] + g);
                hn::StoreU(hn::Sub(a2, a0), dv, out.varying[2 * kMaxVaryings + row] + g);
            }
        }
    }
}

/// The planes of the chunk's survivors (those of out.at without kScalar, in that order), a
/// vector of survivors at once: makePlanes() after screenPosition() and planeBase(), the same
/// double operations in the same order in every lane (no fused multiply-add: the engine is built
/// with -ffp-contract=off, and Highway's Mul and Add round each), so every float is the scalar
/// path's bit for bit.
HWY_INLINE void planesOf(const LaneInput& in, std::size_t chunk, LaneChunk& out) {
    const Dd dd;
    const Df df;
    const Dw dw;
    const std::size_t n = hn::Lanes(dd);
    std::int32_t which[LaneChunk::kSize + LaneChunk::kSlack];
    std::size_t survivors = 0;
    for (std::uint32_t e = 0; e < out.count; ++e)
        if ((out.at[e] & LaneChunk::kScalar) == 0)
            which[survivors++] = static_cast<std::int32_t>(out.at[e]);
    if (survivors == 0) return;
    // A tail's missing lanes take the first survivor again (valid indices), stored past the end
    // (a vector of floats: the varyings' lanes, as many as the doubles' or more).
    for (std::size_t i = survivors; i < survivors + hn::Lanes(Dv()); ++i) which[i] = which[0];

    const auto* indices = reinterpret_cast<const std::int32_t*>(in.indices + 3 * chunk);
    const float* clip = &in.clip[0].x;
    const VecD zero = hn::Zero(dd), one = hn::Set(dd, 1.0), half = hn::Set(dd, 0.5);
    const VecD hiX = hn::Set(dd, in.width - 1.0), hiY = hn::Set(dd, in.height - 1.0);
    for (std::size_t g = 0; g < survivors; g += n) {
        const auto k3 = hn::Mul(hn::LoadU(dw, which + g), hn::Set(dw, 3));
        VecD sx[3], sy[3], r[3];
        for (int j = 0; j < 3; ++j) {
            const auto v4 =
                hn::ShiftLeft<2>(hn::GatherIndex(dw, indices, hn::Add(k3, hn::Set(dw, j))));
            const VecD x = hn::PromoteTo(dd, hn::GatherIndex(df, clip, v4));
            const VecD y = hn::PromoteTo(dd, hn::GatherIndex(df, clip + 1, v4));
            const VecD w = hn::PromoteTo(dd, hn::GatherIndex(df, clip + 3, v4));
            sx[j] = hn::Div(x, w);  // screenPosition()
            sy[j] = hn::Div(y, w);
            r[j] = hn::Div(one, w);
        }
        // planeBase(): floorClamped() of the least x and y (finite here: the vertices are in
        // the guard band); truncation is the floor for values ≥ 0.
        const VecD minX = hn::Min(hn::Min(sx[0], sx[1]), sx[2]);
        const VecD minY = hn::Min(hn::Min(sy[0], sy[1]), sy[2]);
        const VecD baseX = hn::Min(hn::Max(minX, zero), hiX);
        const VecD baseY = hn::Min(hn::Max(minY, zero), hiY);
        const auto bxi = hn::DemoteTo(dw, baseX), byi = hn::DemoteTo(dw, baseY);
        const VecD bx = hn::Add(hn::PromoteTo(dd, bxi), half);
        const VecD by = hn::Add(hn::PromoteTo(dd, byi), half);

        // makePlanes().
        const VecD area = hn::Sub(hn::Mul(hn::Sub(sx[1], sx[0]), hn::Sub(sy[2], sy[0])),
                                  hn::Mul(hn::Sub(sy[1], sy[0]), hn::Sub(sx[2], sx[0])));
        const auto usable = hn::And(hn::Ne(area, zero), hn::IsFinite(area));
        const VecD l1 = hn::Div(hn::Sub(hn::Mul(hn::Sub(sx[0], sx[2]), hn::Sub(by, sy[2])),
                                        hn::Mul(hn::Sub(sy[0], sy[2]), hn::Sub(bx, sx[2]))),
                                area);
        const VecD l2 = hn::Div(hn::Sub(hn::Mul(hn::Sub(sx[1], sx[0]), hn::Sub(by, sy[0])),
                                        hn::Mul(hn::Sub(sy[1], sy[0]), hn::Sub(bx, sx[0]))),
                                area);
        const VecD l1x = hn::Div(hn::Neg(hn::Sub(sy[0], sy[2])), area);
        const VecD l1y = hn::Div(hn::Sub(sx[0], sx[2]), area);
        const VecD l2x = hn::Div(hn::Neg(hn::Sub(sy[1], sy[0])), area);
        const VecD l2y = hn::Div(hn::Sub(sx[1], sx[0]), area);
        const VecD d1 = hn::Sub(r[1], r[0]), d2 = hn::Sub(r[2], r[0]);
        const VecD planes[15] = {l1,
                                 l1x,
                                 l1y,
                                 l2,
                                 l2x,
                                 l2y,
                                 hn::Mul(l1, r[1]),
                                 hn::Mul(l1x, r[1]),
                                 hn::Mul(l1y, r[1]),
                                 hn::Mul(l2, r[2]),
                                 hn::Mul(l2x, r[2]),
                                 hn::Mul(l2y, r[2]),
                                 hn::Add(hn::Add(r[0], hn::Mul(l1, d1)), hn::Mul(l2, d2)),
                                 hn::Add(hn::Mul(l1x, d1), hn::Mul(l2x, d2)),
                                 hn::Add(hn::Mul(l1y, d1), hn::Mul(l2y, d2))};
        for (int i = 0; i < 15; ++i) hn::StoreU(hn::DemoteTo(df, planes[i]), df, out.plane[i] + g);
        hn::StoreU(hn::DemoteTo(dw, hn::IfThenElse(usable, baseX, hn::Set(dd, -1.0))), dw,
                   out.base[0] + g);
        hn::StoreU(byi, dw, out.base[1] + g);
    }
    varyingsOf(in, indices, which, survivors, out);
}

/// LaneSetupFn for this target.
void setupLanes(const LaneInput& in, std::size_t first, std::size_t end, LaneChunk& out) {
    const std::size_t n = hn::Lanes(Di());
    out.count = 0;
    out.trianglesIn = out.trianglesCulled = out.trianglesRasterized = 0;
    out.planes = false;
    // No clip positions: every index is invalid, and the gathers (of vertex 0 where invalid)
    // would read outside the vertex pass's output.
    if (in.vertices == 0) return;
    for (std::size_t t = first; t < end; t += n)
        setupVector(in, first, t, std::min(n, end - t), out);
    if (in.clip != nullptr && in.vertices <= kPlaneVertices) {
        planesOf(in, first, out);
        out.planes = true;
    }
}

}  // namespace

LaneSetupFn laneSetupOf() {
    return &setupLanes;
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <atomic>

namespace facet::detail {
namespace {
std::atomic<bool> gLaneSetup{true};
}  // namespace

HWY_EXPORT(laneSetupOf);

LaneSetupFn laneSetup() {
    if (!gLaneSetup.load(std::memory_order_relaxed)) return nullptr;
    return HWY_DYNAMIC_DISPATCH(laneSetupOf)();
}

void enableLaneSetup(bool enabled) {
    gLaneSetup.store(enabled, std::memory_order_relaxed);
}

}  // namespace facet::detail
#endif  // HWY_ONCE
