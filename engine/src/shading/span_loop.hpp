#pragma once
// The row-span, 8-lane triangle loop for the affine and perspective variants. Each row's covered
// pixels are found exactly from the integer edge functions (one division per edge and row, no
// per-pixel test), then walked eight at a time: depth, the depth test and the interpolation
// weights are computed for eight pixels at once with GCC vector types, and only the pixels that
// pass the test are shaded. The loop is compiled twice (target_clones): for AVX2, where a vector
// is one register, and for the x86-64 baseline, where it is two SSE registers; the loader picks
// one when the program starts (measured on the 4K overdraw case: 297 ms baseline, 90 ms AVX2).
//
// Every lane does the same float operations in the same order as the scalar loop in
// primitives.hpp, so both give the same image bit for bit (fast_vs_reference and threads_test).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "frontend/front_end.hpp"
#include "shading/fragment.hpp"
#include "shading/lanes.hpp"
#include "shading/texture_lanes.hpp"

namespace facet::detail {

/// Boxes narrower than this take the scalar loop: a dense mesh's small triangles cover one to
/// three pixels per row, too few to fill eight lanes or to pay for the span's divisions.
inline constexpr int kNarrowBox = 16;

/// The covered pixels [lo, hi] of a row whose edge values at pixel x0 are e[i] (steps stepX[i]
/// per pixel), within [x0, x1]; false when none. Exact: E(x) ≥ 0 solved in integers per edge.
inline bool coveredSpan(const std::int64_t (&e)[3], const std::int64_t (&stepX)[3], int x0, int x1,
                        int& lo, int& hi) {
    const std::int64_t width = x1 - x0;
    std::int64_t first = 0, last = width;
    for (int i = 0; i < 3; ++i) {
        const std::int64_t v = e[i], s = stepX[i];
        if (s == 0) {
            if (v < 0) return false;
        } else if (s > 0) {  // rising: inside from k ≥ ceil(−v / s)
            if (v < 0) first = std::max(first, (-v + s - 1) / s);
        } else {  // falling: inside up to k ≤ floor(v / −s)
            if (v < 0) return false;
            last = std::min(last, v / -s);
        }
    }
    if (first > last) return false;
    lo = x0 + static_cast<int>(first);
    hi = x0 + static_cast<int>(last);
    return true;
}

/// The plane p at eight pixels: the scalar Planes::eval, lane by lane.
[[gnu::always_inline]] inline Float8 eval8(const float (&p)[3], Float8 dx, float dy) {
    return p[0] + p[1] * dx + p[2] * dy;
}

/// Eight colours or vectors, one lane per pixel.
struct Vec3x8 {
    Float8 x, y, z;
};

[[gnu::always_inline]] inline Float8 dot8(const Vec3x8& a, const Vec3x8& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;  // glm::dot's order: (x + y) + z
}

/// normalizeOrZero() lane by lane.
[[gnu::always_inline]] inline Vec3x8 normalize8(const Vec3x8& v) {
    const Float8 length2 = dot8(v, v);
    const Float8 inv = 1.0f / sqrt8(length2);
    const Float8 zero = {};
    const Float8 scale = length2 > 0.0f ? inv : zero;
    return {v.x * scale, v.y * scale, v.z * scale};
}

/// glm::clamp(c, 0, 1) lane by lane (NaN stays NaN, as there).
[[gnu::always_inline]] inline Float8 clamp01x8(Float8 c) {
    const Float8 zero = {}, one = zero + 1.0f;
    return c < 0.0f ? zero : (c > 1.0f ? one : c);
}

/// lightIntensity() and shade() for eight pixels: the same operations in the same order; only
/// pow runs lane by lane, and only for the lanes in `live` (it is most of the cost).
[[gnu::always_inline]] inline Vec3x8 light8(const Vec3x8& rgb, const Vec3x8& p, const Vec3x8& n,
                                            const DrawConstants& k, unsigned live) {
    const FastLighting& f = k.lighting;
    const Vec3x8 toLight{f.light.x - f.light.w * p.x, f.light.y - f.light.w * p.y,
                         f.light.z - f.light.w * p.z};
    const Vec3x8 l = normalize8(toLight);
    const Vec3x8 v = normalize8({k.eye.x - p.x, k.eye.y - p.y, k.eye.z - p.z});
    const Vec3x8 h = normalize8({l.x + v.x, l.y + v.y, l.z + v.z});
    const Float8 nl = dot8(n, l);
    const Float8 zero = {};
    const Float8 nh = clamp01x8(dot8(n, h));  // std::clamp(nh, 0, 1): the same for NaN too
    Float8 specular = {};
    for (int i = 0; i < kLanes; ++i)
        if (live >> i & 1u) specular[i] = std::pow(nh[i], f.shininess);
    const Float8 lit = f.diffuse * nl + f.specular * specular;
    const Float8 intensity = f.ambientTerm + (nl > 0.0f ? lit : zero);
    return {clamp01x8(rgb.x * intensity), clamp01x8(rgb.y * intensity),
            clamp01x8(rgb.z * intensity)};
}

/// Whether V's colour can be computed for eight lanes at once (no texture lookups).
template <class V>
inline constexpr bool kVectorColor =
    V::kShader == ShaderKind::Simple || V::kShader == ShaderKind::Painter;

/// Whether V is a bare bilinear texel, sampled for eight lanes at once.
template <class V>
inline constexpr bool kVectorTexture =
    V::kShader == ShaderKind::Texture&& V::kFilter == TextureFilter::Bilinear && !V::kCombine;

/// The packed colours of eight pixels of an untextured variant from their varyings.
template <class V>
[[gnu::always_inline]] inline Int8 colors8(const Float8* a, const DrawConstants& k, unsigned live) {
    constexpr VaryingLayout L = V::kLayout;
    const Float8 zero = {};
    Vec3x8 rgb{zero + k.baseColor.r, zero + k.baseColor.g, zero + k.baseColor.b};
    if constexpr (L.color) rgb = {a[L.colorAt()], a[L.colorAt() + 1], a[L.colorAt() + 2]};
    if constexpr (L.phong) {
        const int ni = L.normalAt(), pi = L.positionAt();
        const Vec3x8 n = normalize8({a[ni], a[ni + 1], a[ni + 2]});
        rgb = light8(rgb, {a[pi], a[pi + 1], a[pi + 2]}, n, k, live);
    }
    return packColor8(rgb.x, rgb.y, rgb.z);
}

/// The triangle loop of an affine or perspective variant V without derivatives.
template <class V>
[[gnu::noinline, FACET_SPAN_CLONES]] std::size_t rasterizeSpans(void* context,
                                                                const CoverageSetup& setup,
                                                                const Planes& p) {
    static_assert(V::kInterp != Interp::Subdivided && !V::kDerivatives);
    const RasterContext& ctx = *static_cast<const RasterContext*>(context);
    Framebuffer& fb = *ctx.fb;
    const DrawConstants& k = *ctx.constants;
    constexpr int kCount = V::kCount;
    Float8 laneOffset;
    for (int i = 0; i < kLanes; ++i) laneOffset[i] = static_cast<float>(i);
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
            unsigned pass = (1u << n) - 1u;
            fragments += static_cast<std::size_t>(__builtin_popcount(pass));
            const Float8 dx = static_cast<float>(x - p.baseX) + laneOffset;  // exact below 2^24
            const Float8 depth = 1.0f / eval8(p.q, dx, dy);
            float* zrow = fb.depth.data() + rowStart + static_cast<std::size_t>(x);
            if constexpr (depthTested(V::kShader)) {
                Float8 z = {};
                if (n == kLanes)
                    std::memcpy(&z, zrow, sizeof z);
                else
                    std::memcpy(&z, zrow, sizeof(float) * static_cast<std::size_t>(n));
                pass &= laneMask(depth < z);
                if (pass == 0) continue;
            }
            Float8 m1, m2;
            if constexpr (V::kInterp == Interp::Affine) {
                m1 = eval8(p.l1, dx, dy);
                m2 = eval8(p.l2, dx, dy);
            } else {
                m1 = eval8(p.u1, dx, dy) * depth;
                m2 = eval8(p.u2, dx, dy) * depth;
            }
            Float8 a[kCount > 0 ? kCount : 1];
            for (int j = 0; j < kCount; ++j) a[j] = p.a0[j] + m1 * p.d1[j] + m2 * p.d2[j];
            std::uint32_t* crow = fb.color.data() + rowStart + static_cast<std::size_t>(x);
            // Eight lanes at once pay off only when most are live: a dense mesh's small
            // triangles leave one to three, which the scalar loop below shades cheaper.
            if constexpr (kVectorColor<V> || kVectorTexture<V>) {
                if (__builtin_popcount(pass) >= kLanes / 2) {
                    Int8 c;
                    if constexpr (kVectorTexture<V>)
                        c = bilinearPacked8(k.texture->level(0), a[V::kLayout.uvAt()],
                                            a[V::kLayout.uvAt() + 1]);
                    else
                        c = colors8<V>(a, k, pass);
                    if (pass == 0xFFu) {  // the inside of a wide triangle: two plain stores
                        if constexpr (depthTested(V::kShader))
                            std::memcpy(zrow, &depth, sizeof depth);
                        std::memcpy(crow, &c, sizeof c);
                        continue;
                    }
                    for (int i = 0; i < n; ++i) {
                        if (!(pass >> i & 1u)) continue;
                        if constexpr (depthTested(V::kShader)) zrow[i] = depth[i];
                        crow[i] = static_cast<std::uint32_t>(c[i]);
                    }
                    continue;
                }
            }
            for (int i = 0; i < n; ++i) {
                if (!(pass >> i & 1u)) continue;
                float v[kCount > 0 ? kCount : 1];
                for (int j = 0; j < kCount; ++j) v[j] = a[j][i];
                if constexpr (depthTested(V::kShader)) zrow[i] = depth[i];
                if constexpr (V::kShader != ShaderKind::Depth)
                    crow[i] = packColor(fragmentColor<V>(v, k, 0.0f));
            }
        }
    }
    return fragments;
}

}  // namespace facet::detail
