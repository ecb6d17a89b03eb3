// A vector of pixels for the span loop, one lane per pixel: the lane operations the loop shares
// (colour rounding and packing, clamps, dot products, normalisation), written with Google
// Highway. Every operation is the scalar one lane by lane, in the same order, so a lane equals
// the scalar loop bit for bit (the engine is built with -ffp-contract=off: no fused multiply-add
// may merge two roundings into one on the targets that have FMA).
//
// Compiled once per SIMD target (hwy/foreach_target.h re-includes the file that includes this
// one), hence the toggle guard instead of #pragma once.

#include <cstdint>

#include "shading/fast_lighting.hpp"

#if defined(FACET_SHADING_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_LANES_INL_H_
#undef FACET_SHADING_LANES_INL_H_
#else
#define FACET_SHADING_LANES_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {

namespace hn = hwy::HWY_NAMESPACE;

/// One float per pixel, as many lanes as the target has (4 with SSE4, 8 with AVX2, 16 with
/// AVX-512).
using Df = hn::ScalableTag<float>;
using Di = hn::RebindToSigned<Df>;
using Du = hn::RebindToUnsigned<Df>;
using VecF = hn::Vec<Df>;
using VecI = hn::Vec<Di>;
using MaskF = hn::Mask<Df>;

/// Lanes per vector, a compile-time constant on every target the engine compiles.
inline constexpr int kLanes = static_cast<int>(HWY_LANES(float));

/// Bit i set where lane i of `m` is true.
HWY_INLINE unsigned laneBits(MaskF m) {
    std::uint8_t bytes[8] = {};
    hn::StoreMaskBits(Df(), m, bytes);
    return static_cast<unsigned>(bytes[0]) | static_cast<unsigned>(bytes[1]) << 8;
}

/// hn::ConvertTo(Di(), v), truncating, for lanes whose v is a number within int32's range (the
/// others are left unspecified): the plain conversion instruction, without the four operations
/// Highway adds on x86 to saturate lanes out of range, which would lengthen the lighting's chain
/// of dependent operations for lanes that never need them.
HWY_INLINE VecI truncateInRangeLanes(VecF v) {
#if HWY_TARGET == HWY_AVX3 || HWY_TARGET == HWY_AVX3_DL
    return VecI{_mm512_cvttps_epi32(v.raw)};
#elif HWY_TARGET == HWY_AVX2
    return VecI{_mm256_cvttps_epi32(v.raw)};
#elif HWY_TARGET == HWY_SSE4 || HWY_TARGET == HWY_SSSE3
    return VecI{_mm_cvttps_epi32(v.raw)};
#else
    return hn::ConvertTo(Di(), v);
#endif
}

/// toByte() lane by lane for c already in [0, 1] (no clamp needed): scale, round half up.
HWY_INLINE VecI unitToByteLanes(VecF c) {
    const Df d;
    return truncateInRangeLanes(c * hn::Set(d, 255.0f) + hn::Set(d, 0.5f));  // in [0.5, 255.5]
}

/// toByte() lane by lane: clamp to [0, 1] (NaN to 0), scale, round half up.
HWY_INLINE VecI toByteLanes(VecF c) {
    const Df d;
    const VecF zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    return unitToByteLanes(hn::IfThenElse(c > zero, hn::IfThenElse(c < one, c, one), zero));
}

/// Opaque RGBA8 from the lanes' three channel bytes, R in the low byte.
HWY_INLINE VecI packBytesLanes(VecI r, VecI g, VecI b) {
    const VecI opaque = hn::Set(Di(), static_cast<std::int32_t>(0xFF000000u));
    return r | hn::ShiftLeft<8>(g) | hn::ShiftLeft<16>(b) | opaque;
}

/// packColor() lane by lane: opaque RGBA8, R in the low byte.
HWY_INLINE VecI packColorLanes(VecF r, VecF g, VecF b) {
    return packBytesLanes(toByteLanes(r), toByteLanes(g), toByteLanes(b));
}

/// glm::clamp(c, 0, 1) lane by lane (NaN stays NaN, as there).
HWY_INLINE VecF clamp01Lanes(VecF c) {
    const Df d;
    const VecF zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    return hn::IfThenElse(c < zero, zero, hn::IfThenElse(c > one, one, c));
}

/// Colours or vectors of the lanes' pixels.
struct Vec3Lanes {
    VecF x, y, z;
};

HWY_INLINE VecF dotLanes(const Vec3Lanes& a, const Vec3Lanes& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;  // glm::dot's order: (x + y) + z
}

/// fastRsqrt()'s bit guess and two Newton steps lane by lane, right for the lanes whose x is a
/// normal float (x ≥ 2^−126 and finite); the others are left unspecified, for the caller to
/// find (rsqrtLanes() scales subnormal lanes first; lightLanes() tests all its lengths at once).
HWY_INLINE VecF rsqrtNormalLanes(VecF x) {
    const Df d;
    const VecF threeHalves = hn::Set(d, 1.5f);
    const VecF half = hn::Set(d, 0.5f) * x;
    VecF y = hn::BitCast(d, hn::Set(Di(), kRsqrtGuess) - hn::ShiftRight<1>(hn::BitCast(Di(), x)));
    y = y * (threeHalves - half * y * y);
    return y * (threeHalves - half * y * y);
}

/// fastRsqrt() lane by lane for the lanes where x > 0 (the others are left unspecified, for
/// inverseLengthLanes() to zero): the same integer guess and Newton steps in the same order, so
/// the same float on every target (not hn::ApproximateReciprocalSqrt, whose guess differs between
/// targets: 12 bits with SSE4 and AVX2, 14 with AVX-512).
HWY_INLINE VecF rsqrtLanes(VecF x) {
    const Df d;
    // Zero lanes are not scaled: inverseLengthLanes() sets them to 0 whatever they hold.
    const MaskF tiny = hn::And(x<hn::Set(d, kRsqrtMinNormal), x> hn::Zero(d));
    // Subnormal lengths are rare: one test for the whole vector instead of two blends per
    // call; the lanes' values are the same either way.
    if (HWY_LIKELY(hn::AllFalse(d, tiny))) return rsqrtNormalLanes(x);
    const VecF y = rsqrtNormalLanes(hn::IfThenElse(tiny, x * hn::Set(d, kRsqrtScaleUp), x));
    return hn::IfThenElse(tiny, y * hn::Set(d, kRsqrtScaleBack), y);
}

/// inverseLength() lane by lane.
HWY_INLINE VecF inverseLengthLanes(const Vec3Lanes& v) {
    const VecF length2 = dotLanes(v, v);
    return hn::IfThenElseZero(length2 > hn::Zero(Df()), rsqrtLanes(length2));
}

/// v · s lane by lane.
HWY_INLINE Vec3Lanes scaleLanes(const Vec3Lanes& v, VecF s) {
    return {v.x * s, v.y * s, v.z * s};
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_LANES_INL_H_
