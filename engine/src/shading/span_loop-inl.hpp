// The row-span vector triangle loop for the affine and perspective variants. Each row's covered
// pixels are found exactly from the integer edge functions (coveredSpan, one division per edge
// and row, no per-pixel test), then walked a vector at a time: depth, the depth test and the
// interpolation weights are computed for all lanes at once, and only the pixels that pass the
// test are shaded.
//
// Written with Google Highway and compiled once per SIMD target (pipeline/span_targets.cpp);
// the best target the CPU has is picked at run time, once per draw. Every lane does the same
// float operations in the same order as the scalar loop (scalar_loop.hpp), so both give the same
// image bit for bit, on every target (fast_vs_reference, threads_test, simd_targets_test).

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "frontend/front_end.hpp"
#include "shading/fragment.hpp"
#include "shading/lanes-inl.hpp"
#include "shading/span_loop.hpp"
#include "shading/texture_lanes-inl.hpp"
#include "shading/unit_pow-inl.hpp"

#if defined(FACET_SHADING_SPAN_LOOP_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_SPAN_LOOP_INL_H_
#undef FACET_SHADING_SPAN_LOOP_INL_H_
#else
#define FACET_SHADING_SPAN_LOOP_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {

/// The plane p at the lanes' pixels: the scalar Planes::eval, lane by lane.
HWY_INLINE VecF evalLanes(const float (&p)[3], VecF dx, float dy) {
    const Df d;
    return hn::Set(d, p[0]) + hn::Set(d, p[1]) * dx + hn::Set(d, p[2] * dy);
}

/// The plane p at points (dx, dy) off the pixel grid, one per lane: Planes::eval lane by lane.
HWY_INLINE VecF evalLanes(const float (&p)[3], VecF dx, VecF dy) {
    const Df d;
    return hn::Set(d, p[0]) + hn::Set(d, p[1]) * dx + hn::Set(d, p[2]) * dy;
}

/// lightIntensity() and shade() lane by lane: the same operations in the same order, the
/// specular power by unitPowLanes(), as the scalar loop's unitPow().
HWY_INLINE Vec3Lanes lightLanes(const Vec3Lanes& rgb, const Vec3Lanes& p, const Vec3Lanes& n,
                                const DrawConstants& k) {
    const Df d;
    const FastLighting& f = k.lighting;
    auto all = [&](float v) HWY_ATTR { return hn::Set(d, v); };
    const VecF lw = all(f.light.w);
    const Vec3Lanes toLight{all(f.light.x) - lw * p.x, all(f.light.y) - lw * p.y,
                            all(f.light.z) - lw * p.z};
    const Vec3Lanes l = normalizeLanes(toLight);
    const Vec3Lanes v =
        normalizeLanes({all(k.eye.x) - p.x, all(k.eye.y) - p.y, all(k.eye.z) - p.z});
    const Vec3Lanes h = normalizeLanes({l.x + v.x, l.y + v.y, l.z + v.z});
    const VecF nl = dotLanes(n, l);
    const VecF nh = clamp01Lanes(dotLanes(n, h));  // std::clamp(nh, 0, 1): the same for NaN too
    const VecF specular = unitPowLanes(nh, f.shininess);
    const VecF lit = all(f.diffuse) * nl + all(f.specular) * specular;
    const VecF intensity = all(f.ambientTerm) + hn::IfThenElseZero(nl > hn::Zero(d), lit);
    return {clamp01Lanes(rgb.x * intensity), clamp01Lanes(rgb.y * intensity),
            clamp01Lanes(rgb.z * intensity)};
}

/// Whether V's colour can be computed for all lanes at once (no texture lookups).
template <class V>
inline constexpr bool kVectorColor =
    V::kShader == ShaderKind::Simple || V::kShader == ShaderKind::Painter;

/// Whether V is a bare bilinear texel, sampled for all lanes at once.
template <class V>
inline constexpr bool kVectorTexture =
    V::kShader == ShaderKind::Texture&& V::kFilter == TextureFilter::Bilinear && !V::kCombine;

/// The packed colours of the lanes' pixels for an untextured variant, from their varyings.
template <class V>
HWY_INLINE VecI colorLanes(const VecF* a, const DrawConstants& k) {
    constexpr VaryingLayout L = V::kLayout;
    const Df d;
    Vec3Lanes rgb{hn::Set(d, k.baseColor.r), hn::Set(d, k.baseColor.g), hn::Set(d, k.baseColor.b)};
    if constexpr (L.color) rgb = {a[L.colorAt()], a[L.colorAt() + 1], a[L.colorAt() + 2]};
    if constexpr (L.phong) {
        const int ni = L.normalAt(), pi = L.positionAt();
        const Vec3Lanes n = normalizeLanes({a[ni], a[ni + 1], a[ni + 2]});
        rgb = lightLanes(rgb, {a[pi], a[pi + 1], a[pi + 2]}, n, k);
    }
    return packColorLanes(rgb.x, rgb.y, rgb.z);
}

/// The triangle loop of an affine or perspective variant V without derivatives.
template <class V>
HWY_NOINLINE std::size_t rasterizeSpans(void* context, const CoverageSetup& setup,
                                        const Planes& p) {
    static_assert(kHasSpanLoop<V>);
    const Df d;
    const Du du;
    const RasterContext& ctx = *static_cast<const RasterContext*>(context);
    Framebuffer& fb = *ctx.fb;
    const DrawConstants& k = *ctx.constants;
    constexpr int kCount = V::kCount;
    constexpr unsigned kAll = (1u << kLanes) - 1u;
    const VecF laneOffset = hn::Iota(d, 0.0f);
    std::size_t fragments = 0;

    std::int64_t row[3] = {setup.e0[0], setup.e0[1], setup.e0[2]};
    for (int y = setup.box.y0; y <= setup.box.y1; ++y) {
        int lo = 0, hi = -1;
        const bool any = coveredSpan(row, setup.stepX, setup.box.x0, setup.box.x1, lo, hi);
        for (int i = 0; i < 3; ++i) row[i] += setup.stepY[i];
        if (!any) continue;
        const auto dy = static_cast<float>(y - p.baseY);
        const std::size_t rowStart = fb.index(0, y);

        for (int x = lo; x <= hi; x += kLanes) {
            const int n = std::min(kLanes, hi - x + 1);
            unsigned pass = kAll >> (kLanes - n);
            fragments += static_cast<std::size_t>(n);
            // Exact below 2^24.
            const VecF dx = hn::Set(d, static_cast<float>(x - p.baseX)) + laneOffset;
            const VecF depth = hn::Set(d, 1.0f) / evalLanes(p.q, dx, dy);
            float* zrow = fb.depth.data() + rowStart + static_cast<std::size_t>(x);
            if constexpr (depthTested(V::kShader)) {
                VecF z;
                if (n == kLanes) {
                    z = hn::LoadU(d, zrow);
                } else {  // the row's last pixels: no load past them
                    HWY_ALIGN float part[kLanes] = {};
                    std::memcpy(part, zrow, sizeof(float) * static_cast<std::size_t>(n));
                    z = hn::Load(d, part);
                }
                pass &= laneBits(depth < z);
                if (pass == 0) continue;
            }
            VecF m1, m2;
            if constexpr (V::kInterp == Interp::Affine) {
                m1 = evalLanes(p.l1, dx, dy);
                m2 = evalLanes(p.l2, dx, dy);
            } else {
                m1 = evalLanes(p.u1, dx, dy) * depth;
                m2 = evalLanes(p.u2, dx, dy) * depth;
            }
            VecF a[kCount > 0 ? kCount : 1];
            for (int j = 0; j < kCount; ++j)
                a[j] = hn::Set(d, p.a0[j]) + m1 * hn::Set(d, p.d1[j]) + m2 * hn::Set(d, p.d2[j]);
            std::uint32_t* crow = fb.color.data() + rowStart + static_cast<std::size_t>(x);
            HWY_ALIGN float depths[kLanes];
            // All lanes at once pay off only when most are live: a dense mesh's small
            // triangles leave one to three, which the scalar code below shades cheaper.
            if constexpr (kVectorColor<V> || kVectorTexture<V>) {
                if (std::popcount(pass) >= kLanes / 2) {
                    VecI c;
                    if constexpr (kVectorTexture<V>)
                        c = bilinearPackedLanes(k.texture->level(0), a[V::kLayout.uvAt()],
                                                a[V::kLayout.uvAt() + 1]);
                    else
                        c = colorLanes<V>(a, k);
                    if (pass == kAll) {  // the inside of a wide triangle: two plain stores
                        if constexpr (depthTested(V::kShader)) hn::StoreU(depth, d, zrow);
                        hn::StoreU(hn::BitCast(du, c), du, crow);
                        continue;
                    }
                    HWY_ALIGN std::uint32_t colors[kLanes];
                    hn::Store(hn::BitCast(du, c), du, colors);
                    hn::Store(depth, d, depths);
                    for (int i = 0; i < n; ++i) {
                        if (!(pass >> i & 1u)) continue;
                        if constexpr (depthTested(V::kShader)) zrow[i] = depths[i];
                        crow[i] = colors[i];
                    }
                    continue;
                }
            }
            HWY_ALIGN float varyings[kCount > 0 ? kCount : 1][kLanes];
            for (int j = 0; j < kCount; ++j) hn::Store(a[j], d, varyings[j]);
            hn::Store(depth, d, depths);
            for (int i = 0; i < n; ++i) {
                if (!(pass >> i & 1u)) continue;
                float v[kCount > 0 ? kCount : 1];
                for (int j = 0; j < kCount; ++j) v[j] = varyings[j][i];
                if constexpr (depthTested(V::kShader)) zrow[i] = depths[i];
                if constexpr (V::kShader != ShaderKind::Depth)
                    crow[i] = packColor(fragmentColor<V>(v, k, 0.0f));
            }
        }
    }
    return fragments;
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_SPAN_LOOP_INL_H_
