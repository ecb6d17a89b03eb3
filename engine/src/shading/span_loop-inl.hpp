// The vector triangle loops for the affine and perspective variants, one lane per pixel:
//  - the row-span loop, for wide boxes: each row's covered pixels are found exactly from the
//    integer edge functions (coveredSpan, one division per edge and row, no per-pixel test),
//    then walked a vector at a time;
//  - the block loop, for narrow boxes (a dense mesh's small triangles): the box is walked in 2D
//    blocks of the vector's lane count (4×4 pixels on 16 lanes, 4×2 on 8, 4×1 on 4), and each
//    lane tests its own pixel against the edge functions in 32-bit integers.
// In both, depth, the depth test, the interpolation weights, the varyings and (when enough lanes
// are live) the colour are computed for all lanes at once, and only the pixels that are covered
// and pass the test are written.
//
// Written with Google Highway and compiled once per SIMD target (pipeline/span_targets.cpp);
// the best target the CPU has is picked at run time, once per draw. Every lane does the same
// float operations in the same order as the scalar loop (scalar_loop.hpp), so both give the same
// image bit for bit, on every target (fast_vs_reference, threads_test, simd_targets_test).

#include <algorithm>
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

/// The plane p at the lanes' points (dx, dy), on or off the pixel grid: the scalar
/// Planes::eval, lane by lane.
HWY_INLINE VecF evalLanes(const float (&p)[3], VecF dx, VecF dy) {
    const Df d;
    return hn::Set(d, p[0]) + hn::Set(d, p[1]) * dx + hn::Set(d, p[2]) * dy;
}

/// evalLanes() along one row (the same rounding: p[2]·dy is one product either way).
HWY_INLINE VecF evalLanes(const float (&p)[3], VecF dx, float dy) {
    return evalLanes(p, dx, hn::Set(Df(), dy));
}

/// phongTerms().intensity lane by lane, `n` the interpolated normal: the same operations in the
/// same order, the specular power by unitPowLanes() as the scalar loop's unitPow(), and each
/// inverse length (the scalar inverseLength()) by `inverseLength`, given a vector.
template <class InverseLength>
HWY_INLINE VecF phongIntensityLanes(const Vec3Lanes& p, const Vec3Lanes& n, const DrawConstants& k,
                                    InverseLength inverseLength) {
    const Df d;
    const FastLighting& f = k.lighting;
    auto all = [&](float v) HWY_ATTR { return hn::Set(d, v); };
    const VecF lw = all(f.light.w);
    const Vec3Lanes toLight{all(f.light.x) - lw * p.x, all(f.light.y) - lw * p.y,
                            all(f.light.z) - lw * p.z};
    const Vec3Lanes l = scaleLanes(toLight, inverseLength(toLight));
    const VecF nDotL = dotLanes(n, l);
    VecF intensity = all(f.ambientTerm);
    // Where no lane faces the light (n·l ≤ 0, or not a number), I is the ambient term alone
    // whatever the specular: |n|, the halfway vector and the power are skipped for the whole
    // vector. n·l·(1/|n|) > 0 needs n·l > 0, 1/|n| being 0 or positive.
    if (!hn::AllFalse(d, nDotL > hn::Zero(d))) {
        const VecF rn = inverseLength(n);
        const VecF nl = nDotL * rn;
        const MaskF lit = nl > hn::Zero(d);
        const Vec3Lanes toEye{all(k.eye.x) - p.x, all(k.eye.y) - p.y, all(k.eye.z) - p.z};
        const Vec3Lanes v = scaleLanes(toEye, inverseLength(toEye));
        const Vec3Lanes halfway{l.x + v.x, l.y + v.y, l.z + v.z};
        const VecF rh = inverseLength(halfway);
        // std::clamp(nh, 0, 1): the same for NaN too
        const VecF nh = clamp01Lanes(dotLanes(n, halfway) * (rn * rh));
        const VecF diffuse = all(f.diffuse) * nl;
        VecF diffuseAndSpecular = diffuse;
        // The power is the longest chain of dependent operations here: left out where no lit
        // lane's specular term can change I (k.specularSkip: there diffuse + specular rounds to
        // diffuse, the same float). A lane whose n·h is not a number fails n·h ≤ maxNh and keeps
        // the power (its NaN).
        const SpecularSkip& skip = k.specularSkip;
        const MaskF negligible = hn::And(nh <= all(skip.maxNh), diffuse >= all(skip.minDiffuse));
        if (!hn::AllFalse(d, hn::AndNot(negligible, lit))) {
            const VecF specular = unitPowLanes(nh, f.shininess);
            diffuseAndSpecular = diffuse + all(f.specular) * specular;
        }
        intensity = intensity + hn::IfThenElseZero(lit, diffuseAndSpecular);
    }
    return intensity;
}

/// phongIntensityLanes() with inverseLengthLanes(), which handles every length (zero, subnormal,
/// not a number) lane by lane: lightLanes()' rare slow path, out of line.
HWY_NOINLINE inline VecF phongIntensityCarefulLanes(const Vec3Lanes& p, const Vec3Lanes& n,
                                                    const DrawConstants& k) {
    return phongIntensityLanes(p, n, k,
                               [](const Vec3Lanes& v) HWY_ATTR { return inverseLengthLanes(v); });
}

/// phongTerms().intensity and shade() lane by lane, before the clamp (for packColorLanes()), `n`
/// the interpolated normal. The lengths take rsqrtNormalLanes() alone, each only compared with
/// 2^−126: where any of the vector's lengths is below (zero or subnormal: rare), the whole
/// intensity is computed again the careful way. A length that is not a number gets NaN on the
/// fast way instead of inverseLengthLanes()' 0, and the same bytes: its vector has a NaN
/// component either way (p NaN makes l NaN, light.w · p included), every use of l, v and h is a
/// dot product with n or a sum that it reaches, so n·l is NaN on the same lanes either way (an
/// unlit lane, ambient alone), and where only n·h is, the intensity is NaN either way, which
/// packColorLanes() turns to 0 whatever its bits. (The multisampled loop's dead lanes have NaN
/// positions: flagged, they took the careful way every time.) So the lanes' pixels are the
/// scalar loop's, for two compares, a blend and a branch fewer per length.
HWY_INLINE Vec3Lanes lightLanes(const Vec3Lanes& rgb, const Vec3Lanes& p, const Vec3Lanes& n,
                                const DrawConstants& k) {
    const Df d;
    const VecF minNormal = hn::Set(d, kRsqrtMinNormal);
    MaskF tiny = hn::FirstN(d, 0);
    VecF intensity = phongIntensityLanes(p, n, k, [&](const Vec3Lanes& v) HWY_ATTR {
        const VecF length2 = dotLanes(v, v);
        tiny = hn::Or(tiny, length2 < minNormal);  // zero too, not NaN
        return rsqrtNormalLanes(length2);
    });
    if (HWY_UNLIKELY(!hn::AllFalse(d, tiny))) intensity = phongIntensityCarefulLanes(p, n, k);
    // shade()'s clamp is left to packColorLanes(), whose toByteLanes() clamps the same way (NaN
    // to 0 either way): the same bytes for four lane operations fewer per channel.
    return {rgb.x * intensity, rgb.y * intensity, rgb.z * intensity};
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
        rgb = lightLanes(rgb, {a[pi], a[pi + 1], a[pi + 2]}, {a[ni], a[ni + 1], a[ni + 2]}, k);
    }
    return packColorLanes(rgb.x, rgb.y, rgb.z);
}

/// The packed colours of all lanes at once, for a variant with kVectorColor or kVectorTexture.
template <class V>
HWY_INLINE VecI vectorColorLanes(const VecF* a, const DrawConstants& k) {
    if constexpr (kVectorTexture<V>)
        return bilinearPackedLanes(k.texture->level(0), a[V::kLayout.uvAt()],
                                   a[V::kLayout.uvAt() + 1]);
    else
        return colorLanes<V>(a, k);
}

/// How many live lanes make shading all lanes at once pay off: any for a plain colour or Phong
/// lighting (a vector of Phong lanes costs fewer instructions than one scalar pixel, whose
/// phongTerms() is one long chain of dependent scalar operations, plus the lane's varyings
/// stored and reloaded to reach it); a quarter for texture lookups, whose lanes are dearer (a
/// vector of bilinear texels costs about as many instructions as two scalar ones): below that
/// the scalar code shades the live lanes cheaper.
template <class V>
inline constexpr int kMinVectorLanes = !kVectorColor<V> ? (kLanes + 3) / 4 : 1;

/// fragmentWeights() lane by lane for an affine or perspective variant: the weights (m1, m2) of
/// vertices 1 and 2 at the lanes' pixels, `depth` = 1/q there.
template <class V>
HWY_INLINE void weightLanes(const Planes& p, VecF dx, VecF dy, VecF depth, VecF& m1, VecF& m2) {
    if constexpr (V::kInterp == Interp::Affine) {
        m1 = evalLanes(p.l1, dx, dy);
        m2 = evalLanes(p.l2, dx, dy);
    } else {
        m1 = evalLanes(p.u1, dx, dy) * depth;
        m2 = evalLanes(p.u2, dx, dy) * depth;
    }
}

/// interpolateVaryings() lane by lane: V's varyings at weights (m1, m2) into a[0 … V::kCount).
template <class V>
HWY_INLINE void varyingLanes(const Planes& p, VecF m1, VecF m2, VecF* a) {
    const Df d;
    for (int j = 0; j < V::kCount; ++j)
        a[j] = hn::Set(d, p.a0[j]) + m1 * hn::Set(d, p.d1[j]) + m2 * hn::Set(d, p.d2[j]);
}

/// The packed colours of the lanes set in `live` (bit i: lane i) into colors[], from their
/// varyings a[]: all lanes at once when enough are live, else lane by lane through the scalar
/// fragmentColor(). Nothing for the depth shader, which writes no colour.
template <class V>
HWY_INLINE void shadeLanes(const VecF* a, const DrawConstants& k, unsigned live,
                           std::uint32_t* colors) {
    if constexpr (V::kShader != ShaderKind::Depth) {
        const Df d;
        if constexpr (kVectorColor<V> || kVectorTexture<V>) {
            if (std::popcount(live) >= kMinVectorLanes<V>) {
                hn::Store(hn::BitCast(Du(), vectorColorLanes<V>(a, k)), Du(), colors);
                return;
            }
        }
        constexpr int kCount = V::kCount;
        HWY_ALIGN float varyings[kCount > 0 ? kCount : 1][kLanes];
        for (int j = 0; j < kCount; ++j) hn::Store(a[j], d, varyings[j]);
        for (unsigned rest = live; rest != 0; rest &= rest - 1) {
            const int i = std::countr_zero(rest);
            float v[kCount > 0 ? kCount : 1];
            for (int j = 0; j < kCount; ++j) v[j] = varyings[j][i];
            colors[i] = packColor(fragmentColor<V>(v, k, 0.0f));
        }
    }
}

/// The triangle loop of an affine or perspective variant V without derivatives, for wide boxes:
/// row spans.
template <class V>
HWY_NOINLINE std::size_t rasterizeSpans(const RasterContext& ctx, const CoverageSetup& setup,
                                        const Planes& p, const PixelTarget& target) {
    static_assert(kHasSpanLoop<V>);
    const Df d;
    const Du du;
    const PixelTarget& fb = target;
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
        const VecF dy = hn::Set(d, static_cast<float>(y - p.baseY));
        const std::size_t rowStart = fb.index(0, y);  // modulo 2^64: + x below

        for (int x = lo; x <= hi; x += kLanes) {
            const int n = std::min(kLanes, hi - x + 1);
            unsigned pass = kAll >> (kLanes - n);
            fragments += static_cast<std::size_t>(n);
            // Exact below 2^24.
            const VecF dx = hn::Set(d, static_cast<float>(x - p.baseX)) + laneOffset;
            const VecF depth = hn::Set(d, 1.0f) / evalLanes(p.q, dx, dy);
            float* zrow = fb.depth + (rowStart + static_cast<std::size_t>(x));
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
            weightLanes<V>(p, dx, dy, depth, m1, m2);
            VecF a[kCount > 0 ? kCount : 1];
            varyingLanes<V>(p, m1, m2, a);
            std::uint32_t* crow = fb.color + (rowStart + static_cast<std::size_t>(x));
            if constexpr (kVectorColor<V> || kVectorTexture<V>) {
                if (pass == kAll) {  // the inside of a wide triangle: two plain stores
                    if constexpr (depthTested(V::kShader)) hn::StoreU(depth, d, zrow);
                    hn::StoreU(hn::BitCast(du, vectorColorLanes<V>(a, k)), du, crow);
                    continue;
                }
            }
            HWY_ALIGN std::uint32_t colors[kLanes];
            HWY_ALIGN float depths[kLanes];
            shadeLanes<V>(a, k, pass, colors);
            hn::Store(depth, d, depths);
            for (unsigned rest = pass; rest != 0; rest &= rest - 1) {
                const int i = std::countr_zero(rest);
                if constexpr (depthTested(V::kShader)) zrow[i] = depths[i];
                if constexpr (V::kShader != ShaderKind::Depth) crow[i] = colors[i];
            }
        }
    }
    return fragments;
}

/// Block width and height in pixels: the lanes of a vector as a 2D block, row-major (lane i is
/// pixel (i mod kBlockW, i div kBlockW) of the block), as square as 4-pixel rows allow.
inline constexpr int kBlockW = kLanes < kMaxBlockSide ? kLanes : kMaxBlockSide;
inline constexpr int kBlockH = kLanes / kBlockW;
/// log2(kBlockW): lane i is in the block's row i >> kBlockShift.
inline constexpr int kBlockShift = std::countr_zero(static_cast<unsigned>(kBlockW));
static_assert(kBlockH <= kMaxBlockSide && kLanes <= 16, "a block fits in laneBits()' 16 bits");

/// The depths stored at a block's pixels, from its first pixel `first` in a framebuffer `width`
/// wide; lane i's pixel is offsets[i] (its row times `width`, plus its column) past it. Only the
/// `covered` lanes' values matter (bit i: lane i; `outside` is set on the other lanes), and only
/// pixels in the box may be read: the rest may be another thread's tile, or past the frame. A
/// one-row block is a plain load; a 4×4 block on a target whose masked loads touch no masked-off
/// memory (AVX-512) is four masked row loads of the covered lanes; other blocks gather, every lane
/// outside the triangle reading the block's first pixel (in the box) instead of its own. (A copy
/// through the stack would stall on store forwarding.)
HWY_INLINE VecF blockDepths(const float* first, [[maybe_unused]] int width,
                            [[maybe_unused]] VecI offsets, [[maybe_unused]] hn::Mask<Di> outside,
                            unsigned covered) {
    const Df d;
    if constexpr (kBlockH == 1) {
        // Covered lanes lie in the box, which starts at lane 0: read up to the last of them.
        const int columns = std::bit_width(covered);
        if (columns == kBlockW) return hn::LoadU(d, first);
        HWY_ALIGN float part[kLanes] = {};
        std::memcpy(part, first, sizeof(float) * static_cast<std::size_t>(columns));
        return hn::Load(d, part);
    }
#if (HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL) && !HWY_MEM_OPS_MIGHT_FAULT
    else if constexpr (kBlockW == 4 && kBlockH == 4) {
        const hn::Full128<float> d4;
        const hn::Half<Df> d8;
        const auto row = [&](int r) HWY_ATTR {
            const std::uint8_t bits[8] = {static_cast<std::uint8_t>(covered >> (4 * r) & 0xFu)};
            return hn::MaskedLoad(
                hn::LoadMaskBits(d4, bits), d4,
                first + static_cast<std::size_t>(r) * static_cast<std::size_t>(width));
        };
        return hn::Combine(d, hn::Combine(d8, row(3), row(2)), hn::Combine(d8, row(1), row(0)));
    }
#endif
    else {
        return hn::GatherIndex(d, first, hn::IfThenZeroElse(outside, offsets));
    }
}

/// Whether 4×4 blocks are written row by row with masked stores, which on AVX-512 touch no
/// masked-off pixel (HWY_MEM_OPS_MIGHT_FAULT is 0 there); elsewhere pixel by pixel. Clang's
/// sanitizer build sees HWY_MEM_OPS_MIGHT_FAULT set on AVX-512 too, and takes the gather.
#if (HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL) && !HWY_MEM_OPS_MIGHT_FAULT
inline constexpr bool kMaskedRows = kBlockW == 4 && kBlockH == 4;
#else
inline constexpr bool kMaskedRows = false;
#endif

/// Writes the `pass` lanes of a block of variant V, depths (when tested) and packed colours, from
/// its first pixel (z, c) in a framebuffer `width` wide: one masked store per row and buffer.
/// Only where kMaskedRows.
template <class V>
HWY_INLINE void storeBlockRows([[maybe_unused]] VecF depth, [[maybe_unused]] VecI color,
                               [[maybe_unused]] unsigned pass, [[maybe_unused]] float* z,
                               [[maybe_unused]] std::uint32_t* c, [[maybe_unused]] int width) {
#if (HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL) && !HWY_MEM_OPS_MIGHT_FAULT
    const hn::Full128<float> d4;
    const hn::Full128<std::uint32_t> du4;
    const hn::Half<Df> d8;
    const hn::Half<Du> du8;
    const auto colors = hn::BitCast(Du(), color);
    const auto z01 = hn::LowerHalf(d8, depth), z23 = hn::UpperHalf(d8, depth);
    const auto c01 = hn::LowerHalf(du8, colors), c23 = hn::UpperHalf(du8, colors);
    const hn::Vec<decltype(d4)> zr[4] = {hn::LowerHalf(d4, z01), hn::UpperHalf(d4, z01),
                                         hn::LowerHalf(d4, z23), hn::UpperHalf(d4, z23)};
    const hn::Vec<decltype(du4)> cr[4] = {hn::LowerHalf(du4, c01), hn::UpperHalf(du4, c01),
                                          hn::LowerHalf(du4, c23), hn::UpperHalf(du4, c23)};
    for (int r = 0; r < 4; ++r) {
        const std::uint8_t bits[8] = {static_cast<std::uint8_t>(pass >> (4 * r) & 0xFu)};
        if (bits[0] == 0) continue;
        const auto live = hn::LoadMaskBits(d4, bits);
        const std::size_t row = static_cast<std::size_t>(r) * static_cast<std::size_t>(width);
        if constexpr (depthTested(V::kShader)) hn::BlendedStore(zr[r], live, d4, z + row);
        if constexpr (V::kShader != ShaderKind::Depth)
            hn::BlendedStore(cr[r], hn::RebindMask(du4, live), du4, c + row);
    }
#endif
}

/// The triangle loop of an affine or perspective variant V without derivatives, for narrow boxes
/// that fitsBlockLoop(): 2D blocks of pixels, one lane each. Coverage is forEachCovered()'s
/// test, E ≥ 0 on all three edges (the top-left bias is in e0), done per lane in 32 bits.
///
/// A dense mesh's triangle covers a few pixels in two or three blocks, so what is paid per
/// triangle and per block counts as much as what is paid per pixel: the lanes' edge values are
/// set up once and stepped by vector adds; the box's right and bottom limits are two more
/// "edges" stepped the same way, so that a block's covered lanes are one OR of five vectors and
/// an empty block is skipped after it; depth steps dx instead of converting it per block, and
/// reuses the row's q₂·dy.
template <class V>
HWY_NOINLINE std::size_t rasterizeBlocks(const RasterContext& ctx, const CoverageSetup& setup,
                                         const Planes& p, const PixelTarget& target) {
    static_assert(kHasSpanLoop<V>);
    const Df d;
    const Di di;
    const PixelTarget& fb = target;
    const DrawConstants& k = *ctx.constants;
    constexpr int kCount = V::kCount;
    constexpr unsigned kAll = (1u << kLanes) - 1u;

    // Each lane's pixel (ox, oy) within the block, its place in the framebuffer and its edge
    // values at the box's first block: all exact (fitsBlockLoop() bounds the integers, and small
    // integers are exact floats), so a lane's dx and dy are the scalar loop's. Computed in lanes:
    // a table written lane by lane and read back as a vector would stall on store forwarding,
    // once per triangle.
    const VecI lane = hn::Iota(di, 0);
    const VecI ox = hn::And(lane, hn::Set(di, kBlockW - 1));
    const VecI oy = hn::ShiftRight<kBlockShift>(lane);
    const VecF offsetY = hn::ConvertTo(d, oy);
    const VecI laneOffset = oy * hn::Set(di, fb.stride) + ox;
    const auto i32 = [](std::int64_t v) { return static_cast<std::int32_t>(v); };
    const auto edgeStart = [&](int i) HWY_ATTR {
        return hn::Set(di, i32(setup.e0[i])) + ox * hn::Set(di, i32(setup.stepX[i])) +
               oy * hn::Set(di, i32(setup.stepY[i]));
    };
    VecI row0 = edgeStart(0), row1 = edgeStart(1), row2 = edgeStart(2);
    const VecI blockX0 = hn::Set(di, i32(kBlockW * setup.stepX[0]));
    const VecI blockX1 = hn::Set(di, i32(kBlockW * setup.stepX[1]));
    const VecI blockX2 = hn::Set(di, i32(kBlockW * setup.stepX[2]));
    const VecI blockY0 = hn::Set(di, i32(kBlockH * setup.stepY[0]));
    const VecI blockY1 = hn::Set(di, i32(kBlockH * setup.stepY[1]));
    const VecI blockY2 = hn::Set(di, i32(kBlockH * setup.stepY[2]));
    const int width = setup.box.x1 - setup.box.x0 + 1;
    const int height = setup.box.y1 - setup.box.y0 + 1;
    // The box as two more edges, ≥ 0 on the lanes inside it: columns left of the box's last one,
    // rows above its last row. Lanes past the box (a block sticking out of it) may be in another
    // thread's tile or past the frame.
    const VecI boxStart = hn::Set(di, width - 1) - ox;
    VecI boxRow = hn::Set(di, height - 1) - oy;
    const VecI boxStepX = hn::Set(di, kBlockW);
    const VecI boxStepY = hn::Set(di, kBlockH);
    const VecF dxStart = hn::Set(d, static_cast<float>(setup.box.x0 - p.baseX)) +
                         hn::ConvertTo(d, ox);  // exact below 2^24
    const VecF dxStep = hn::Set(d, static_cast<float>(kBlockW));
    const VecF q0 = hn::Set(d, p.q[0]), q1 = hn::Set(d, p.q[1]), q2 = hn::Set(d, p.q[2]);
    const VecF one = hn::Set(d, 1.0f);
    [[maybe_unused]] HWY_ALIGN std::int32_t
        pixelAt[kLanes];  // laneOffset, for the lane-by-lane stores
    if constexpr (!kMaskedRows || !kVectorColor<V> || kMinVectorLanes<V> != 1)
        hn::Store(laneOffset, di, pixelAt);
    std::size_t fragments = 0;
    // Without varyings the colour is the same at every pixel: packed once per draw.
    const VecI flat = hn::Set(di, static_cast<std::int32_t>(k.basePacked));

    for (int by = 0; by < height; by += kBlockH) {
        const int y = setup.box.y0 + by;
        const VecF dy = hn::Set(d, static_cast<float>(y - p.baseY)) + offsetY;
        const VecF qy = q2 * dy;  // evalLanes()' last term, the same for the whole row
        VecI e0 = row0, e1 = row1, e2 = row2, boxColumn = boxStart;
        VecF dx = dxStart;
        row0 = row0 + blockY0;
        row1 = row1 + blockY1;
        row2 = row2 + blockY2;
        const VecI boxRowHere = boxRow;
        boxRow = boxRow - boxStepY;
        float* zrow = fb.depth + fb.index(setup.box.x0, y);
        std::uint32_t* crow = fb.color + fb.index(setup.box.x0, y);

        for (int bx = 0; bx < width; bx += kBlockW, dx = dx + dxStep) {
            // Negative on some edge (the sign bit of the OR): outside the triangle or the box.
            const VecI outsideBits = e0 | e1 | e2 | boxColumn | boxRowHere;
            e0 = e0 + blockX0;
            e1 = e1 + blockX1;
            e2 = e2 + blockX2;
            boxColumn = boxColumn - boxStepX;
            const hn::Mask<Di> outside = outsideBits < hn::Zero(di);
            const unsigned covered = kAll & ~laneBits(hn::RebindMask(d, outside));
            if (covered == 0) continue;
            fragments += static_cast<std::size_t>(std::popcount(covered));

            // evalLanes(p.q, dx, dy), its row term hoisted: the same operations in the same
            // order.
            const VecF depth = one / (q0 + q1 * dx + qy);
            float* zblock = zrow + bx;
            unsigned pass = covered;
            if constexpr (depthTested(V::kShader)) {
                pass &=
                    laneBits(depth < blockDepths(zblock, fb.stride, laneOffset, outside, covered));
                if (pass == 0) continue;
            }
            VecF m1, m2;
            weightLanes<V>(p, dx, dy, depth, m1, m2);
            VecF a[kCount > 0 ? kCount : 1];
            varyingLanes<V>(p, m1, m2, a);
            std::uint32_t* cblock = crow + bx;
            if constexpr (kMaskedRows && kVectorColor<V> && kMinVectorLanes<V> == 1) {
                // Every block is shaded all lanes at once: the colours stay in a vector.
                storeBlockRows<V>(depth, kCount == 0 ? flat : colorLanes<V>(a, k), pass, zblock,
                                  cblock, fb.stride);
                continue;
            }
            HWY_ALIGN std::uint32_t colors[kLanes];
            HWY_ALIGN float depths[kLanes];
            if constexpr (kCount == 0 && kVectorColor<V>)
                hn::Store(hn::BitCast(Du(), flat), Du(), colors);
            else
                shadeLanes<V>(a, k, pass, colors);
            hn::Store(depth, d, depths);
            for (unsigned rest = pass; rest != 0; rest &= rest - 1) {
                const int i = std::countr_zero(rest);
                const auto at = static_cast<std::size_t>(pixelAt[i]);
                if constexpr (depthTested(V::kShader)) zblock[at] = depths[i];
                if constexpr (V::kShader != ShaderKind::Depth) cblock[at] = colors[i];
            }
        }
    }
    return fragments;
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_SPAN_LOOP_INL_H_
