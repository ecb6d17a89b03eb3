// The row-span vector loop of multisampling (RenderSettings::msaa > 1) for the affine and
// perspective variants: the vector twin of rasterizeMsaa (msaa_loop.hpp), which stays the rule.
//
// Per row, each sample's covered pixels are found exactly from the integer edge functions
// (coveredSpan at the sample's offset: one division per edge, sample and row), and so is the
// run of pixels whose centre is inside. The row is then walked a vector of pixels at a time:
// coverage, depth and the depth test per sample for all lanes at once, reading and writing the
// per-sample buffer with interleaved loads and stores (a pixel's samples sit side by side in a
// SampleBlock's rows); then one shading per pixel, at the centre or at the covered samples'
// centroid, for all lanes at once, written to the samples that passed.
//
// Every lane does the same float operations in the same order as the scalar loop, so both give
// the same per-sample buffer bit for bit on every target (simd_targets_test, msaa_test).
// Compiled once per SIMD target with the span loop (pipeline/span_targets.cpp).

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "shading/msaa_loop.hpp"
#include "shading/span_loop-inl.hpp"

#if defined(FACET_SHADING_MSAA_LOOP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_MSAA_LOOP_INL_H_
#undef FACET_SHADING_MSAA_LOOP_INL_H_
#else
#define FACET_SHADING_MSAA_LOOP_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {

/// One row of a SampleBlock for a vector of pixels: `bx` interleaved samples per pixel, the
/// whole vector's worth at `at`, or only the first `live` pixels' when the row ends sooner (the
/// pixels past them may belong to another thread's tile: never read or written).
template <class D, class T>
struct SampleRow {
    T* at = nullptr;
    int bx = 2;
    int live = kLanes;

    /// The samples c = 0 … bx−1 of the lanes' pixels into v[c].
    HWY_INLINE void load(D d, hn::Vec<D> (&v)[4]) const {
        HWY_ALIGN T part[4 * kLanes];
        const T* from = at;
        if (live < kLanes) {
            std::memset(part, 0, sizeof(part));
            std::memcpy(part, at, sizeof(T) * static_cast<std::size_t>(live * bx));
            from = part;
        }
        if (bx == 2)
            hn::LoadInterleaved2(d, from, v[0], v[1]);
        else
            hn::LoadInterleaved4(d, from, v[0], v[1], v[2], v[3]);
    }

    /// v[c] to the samples c = 0 … bx−1 of the lanes' pixels.
    HWY_INLINE void store(D d, const hn::Vec<D> (&v)[4]) const {
        HWY_ALIGN T part[4 * kLanes];
        T* to = live < kLanes ? part : at;
        if (bx == 2)
            hn::StoreInterleaved2(v[0], v[1], d, to);
        else
            hn::StoreInterleaved4(v[0], v[1], v[2], v[3], d, to);
        if (live < kLanes) std::memcpy(at, part, sizeof(T) * static_cast<std::size_t>(live * bx));
    }
};

/// The multisampled loop of an affine or perspective variant V without derivatives; returns
/// the pixels with a covered sample, as rasterizeMsaa does.
template <class V>
HWY_NOINLINE std::size_t rasterizeMsaaSpans(const MsaaContext& ctx, const CoverageSetup& setup,
                                            const Planes& p) {
    static_assert(kHasSpanLoop<V>);
    const Df d;
    const Du du;
    const SamplePattern& sp = ctx.pattern;
    Framebuffer& fb = *ctx.samples;
    const DrawConstants& k = *ctx.constants;
    constexpr int kCount = V::kCount;
    constexpr bool kColor = V::kShader != ShaderKind::Depth;
    constexpr bool kTested = depthTested(V::kShader);
    const int n = sp.count, bx = sp.block.x, by = sp.block.y;
    const VecF laneOffset = hn::Iota(d, 0.0f);
    const MaskF none = hn::FirstN(d, 0);
    std::size_t fragments = 0;

    std::int64_t off[3][kMaxMsaa];
    sampleEdgeOffsets(setup, sp, off);
    std::int64_t row[3] = {setup.e0[0], setup.e0[1], setup.e0[2]};
    for (int y = setup.box.y0; y <= setup.box.y1; ++y) {
        // Each sample's covered run [lo, hi] (empty as x1 + 1 > x1), their union [first, last]
        // and the run of inside centres [clo, chi].
        const int x0 = setup.box.x0, x1 = setup.box.x1;
        int lo[kMaxMsaa], hi[kMaxMsaa];
        int first = x1 + 1, last = x0 - 1;
        for (int j = 0; j < n; ++j) {
            const std::int64_t e[3] = {row[0] + off[0][j], row[1] + off[1][j], row[2] + off[2][j]};
            if (coveredSpan(e, setup.stepX, x0, x1, lo[j], hi[j])) {
                first = std::min(first, lo[j]);
                last = std::max(last, hi[j]);
            } else {
                lo[j] = x1 + 1;
                hi[j] = x1;
            }
        }
        int clo = x1 + 1, chi = x1;
        if (!coveredSpan(row, setup.stepX, x0, x1, clo, chi)) clo = x1 + 1, chi = x1;
        for (int i = 0; i < 3; ++i) row[i] += setup.stepY[i];
        if (first > last) continue;
        const auto dy = static_cast<float>(y - p.baseY);

        for (int x = first; x <= last; x += kLanes) {
            const int live = std::min(kLanes, last - x + 1);
            // Pixel numbers and offsets from the planes' base, exact below 2^24.
            const VecF px = hn::Set(d, static_cast<float>(x)) + laneOffset;
            const VecF dx = hn::Set(d, static_cast<float>(x - p.baseX)) + laneOffset;
            auto within = [&](int a, int b) HWY_ATTR {
                return hn::And(px >= hn::Set(d, static_cast<float>(a)),
                               px <= hn::Set(d, static_cast<float>(b)));
            };

            // Coverage, depth and the depth test per sample, block row by block row.
            MaskF covered[kMaxMsaa], passed[kMaxMsaa];
            VecF depth[kMaxMsaa], z[kMaxMsaa];
            MaskF anyCovered = none, anyPassed = none;
            for (int r = 0; r < by; ++r) {
                VecF zr[4];
                const SampleRow<Df, float> zrow{fb.depth.data() + fb.index(x * bx, y * by + r), bx,
                                                live};
                if constexpr (kTested) zrow.load(d, zr);
                for (int c = 0; c < bx; ++c) {
                    const int j = r * bx + c;
                    covered[j] = within(lo[j], hi[j]);
                    anyCovered = hn::Or(anyCovered, covered[j]);
                    depth[j] =
                        hn::Set(d, 1.0f) / evalLanes(p.q, dx + hn::Set(d, sp.fx[j]), dy + sp.fy[j]);
                    passed[j] = covered[j];
                    if constexpr (kTested) {
                        z[j] = zr[c];
                        passed[j] = hn::And(passed[j], depth[j] < z[j]);
                    }
                    anyPassed = hn::Or(anyPassed, passed[j]);
                }
            }
            fragments += static_cast<std::size_t>(std::popcount(laneBits(anyCovered)));
            const unsigned shaded = laneBits(anyPassed);
            if (shaded == 0) continue;

            // Where each pixel is shaded: its centre when inside, else its covered samples'
            // centroid (summed in sample order, as the scalar loop does).
            VecF cx = hn::Zero(d), cy = hn::Zero(d), m = hn::Zero(d);
            for (int j = 0; j < n; ++j) {
                cx = hn::IfThenElse(covered[j], cx + hn::Set(d, sp.fx[j]), cx);
                cy = hn::IfThenElse(covered[j], cy + hn::Set(d, sp.fy[j]), cy);
                m = hn::IfThenElse(covered[j], m + hn::Set(d, 1.0f), m);
            }
            const MaskF centre = within(clo, chi);
            const VecF sx = hn::IfThenElse(centre, dx, dx + cx / m);
            const VecF sy = hn::IfThenElse(centre, hn::Set(d, dy), hn::Set(d, dy) + cy / m);
            const VecF at = hn::Set(d, 1.0f) / evalLanes(p.q, sx, sy);
            VecF m1, m2;
            if constexpr (V::kInterp == Interp::Affine) {
                m1 = evalLanes(p.l1, sx, sy);
                m2 = evalLanes(p.l2, sx, sy);
            } else {
                m1 = evalLanes(p.u1, sx, sy) * at;
                m2 = evalLanes(p.u2, sx, sy) * at;
            }
            VecF a[kCount > 0 ? kCount : 1];
            for (int j = 0; j < kCount; ++j)
                a[j] = hn::Set(d, p.a0[j]) + m1 * hn::Set(d, p.d1[j]) + m2 * hn::Set(d, p.d2[j]);

            // The packed colour per pixel: all lanes at once when enough are live (as in the
            // span loop: any for plain colours and Phong, half for texture lookups), else lane
            // by lane through the scalar shading.
            hn::Vec<Du> color = hn::Zero(du);
            if constexpr (kColor) {
                bool done = false;
                if constexpr (kVectorColor<V> || kVectorTexture<V>) {
                    if (std::popcount(shaded) >= kMinVectorLanes<V>) {
                        if constexpr (kVectorTexture<V>)
                            color = hn::BitCast(
                                du, bilinearPackedLanes(k.texture->level(0), a[V::kLayout.uvAt()],
                                                        a[V::kLayout.uvAt() + 1]));
                        else
                            color = hn::BitCast(du, colorLanes<V>(a, k));
                        done = true;
                    }
                }
                if (!done) {
                    HWY_ALIGN float varyings[kCount > 0 ? kCount : 1][kLanes];
                    for (int j = 0; j < kCount; ++j) hn::Store(a[j], d, varyings[j]);
                    HWY_ALIGN std::uint32_t colors[kLanes] = {};
                    for (int i = 0; i < kLanes; ++i) {
                        if (!(shaded >> i & 1u)) continue;
                        float v[kCount > 0 ? kCount : 1];
                        for (int j = 0; j < kCount; ++j) v[j] = varyings[j][i];
                        colors[i] = packColor(fragmentColor<V>(v, k, 0.0f));
                    }
                    color = hn::Load(du, colors);
                }
            }

            // Every sample that passed takes the pixel's colour and its own depth; the others
            // keep theirs (read above, or read now for the colours when some sample failed).
            for (int r = 0; r < by; ++r) {
                const std::size_t start = fb.index(x * bx, y * by + r);
                const SampleRow<Df, float> zrow{fb.depth.data() + start, bx, live};
                const SampleRow<Du, std::uint32_t> crow{fb.color.data() + start, bx, live};
                // A full vector whose samples all passed: the colours need no read.
                bool all = live == kLanes;
                for (int c = 0; c < bx && all; ++c) all = hn::AllTrue(d, passed[r * bx + c]);
                if constexpr (kTested) {
                    VecF zs[4];
                    for (int c = 0; c < bx; ++c)
                        zs[c] =
                            hn::IfThenElse(passed[r * bx + c], depth[r * bx + c], z[r * bx + c]);
                    zrow.store(d, zs);
                }
                if constexpr (kColor) {
                    hn::Vec<Du> cs[4];
                    if (!all) crow.load(du, cs);
                    for (int c = 0; c < bx; ++c)
                        cs[c] = all ? color
                                    : hn::IfThenElse(hn::RebindMask(du, passed[r * bx + c]), color,
                                                     cs[c]);
                    crow.store(du, cs);
                }
            }
        }
    }
    return fragments;
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_MSAA_LOOP_INL_H_
