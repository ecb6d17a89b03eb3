// unitPow() (unit_pow.hpp) lane by lane: the same operations in the same order, so every lane
// equals the scalar function bit for bit on every SIMD target (no fused multiply-add: Highway's
// MulAdd would be one rounding on AVX2 and two on SSE4).
//
// Compiled once per SIMD target (see lanes-inl.hpp).

#include <bit>
#include <cstdint>

#include "shading/lanes-inl.hpp"
#include "shading/unit_pow.hpp"

#if defined(FACET_SHADING_UNIT_POW_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_UNIT_POW_INL_H_
#undef FACET_SHADING_UNIT_POW_INL_H_
#else
#define FACET_SHADING_UNIT_POW_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {

/// unitPow(x[i], s) for every lane.
HWY_INLINE VecF unitPowLanes(VecF x, float s) {
    const Df d;
    const Di di;
    auto all = [&](float v) HWY_ATTR { return hn::Set(d, v); };
    if (s == 0.0f) return all(1.0f);  // the same per draw: tested once, not per lane
    // Only lanes with x > 0 use the logarithm (the others return x), so only they are scaled
    // when subnormal; that is rare, and one test for the whole vector keeps the scaling's
    // multiply and blends off the chain of dependent operations the power is. The lanes' values
    // are the same either way.
    const MaskF belowNormal = x < all(kMinNormal);
    const MaskF positive = x > hn::Zero(d);
    const MaskF tiny = hn::And(belowNormal, positive);
    VecF xs = x;
    VecF bias = all(127.0f);
    if (HWY_UNLIKELY(!hn::AllFalse(d, tiny))) {
        xs = hn::IfThenElse(tiny, x * all(kTwo24), x);
        bias = hn::IfThenElse(tiny, all(127.0f + 24.0f), all(127.0f));
    }
    const VecI bits = hn::BitCast(di, xs);
    // The exponent e is kept as a float: a small integer, so every step is exact and e is
    // unitPow()'s integer e, converted. Integer constants cost the compiler three instructions
    // each here, float ones one: the integer ones are floats' bit patterns (127 << 23 is 1.0f's,
    // 126 << 23 0.5f's, 0x7FFFFF the largest subnormal's).
    const VecI oneBits = hn::BitCast(di, all(1.0f));
    VecF e = hn::ConvertTo(d, hn::ShiftRight<23>(bits)) - bias;
    // m = 1.mantissa, halved where above √2: the same floats as unitPow()'s compare and
    // multiply by ½ (exact), from the integer bits (m > √2 is the mantissas' integer order; m·½
    // is m with 0.5f's exponent), a few cycles shorter.
    const VecI mantissa = hn::And(bits, hn::BitCast(di, all(std::bit_cast<float>(0x7FFFFF))));
    const VecI sqrt2Mantissa = hn::BitCast(
        di, all(std::bit_cast<float>(std::bit_cast<std::int32_t>(kSqrtHalf2) & 0x7FFFFF)));
    const hn::Mask<Di> bigI = mantissa > sqrt2Mantissa;
    const VecI exponentBits = hn::IfThenElse(bigI, hn::BitCast(di, all(0.5f)), oneBits);
    const VecF m = hn::BitCast(d, hn::Or(mantissa, exponentBits));
    e = e + hn::IfThenElseZero(hn::RebindMask(d, bigI), all(1.0f));
    const VecF t = (m - all(1.0f)) / (m + all(1.0f));
    const VecF t2 = t * t;
    VecF p = all(kLog2Series[4]);
    for (int k = 3; k >= 0; --k) p = p * t2 + all(kLog2Series[k]);
    const VecF y = all(s) * (e + p * t);
    const MaskF inRange = y >= all(kMinExponent);
    const VecF ySafe = hn::IfThenElseZero(inRange, y);
    // ySafe ∈ [−125, 0] where x ∈ (0, 1]; where x ≤ 0 or is not a number the last blend returns
    // x whatever n is (x above 1 is outside the domain: the loops clamp n·h first).
    const VecI n = truncateInRangeLanes(ySafe - all(0.5f));
    const VecF f = ySafe - hn::ConvertTo(d, n);
    VecF q = all(kExp2Series[6]);
    for (int k = 5; k >= 0; --k) q = q * f + all(kExp2Series[k]);
    const VecF scale = hn::BitCast(d, hn::ShiftLeft<23>(n) + oneBits);  // (n + 127) << 23
    const VecF r = hn::IfThenElseZero(inRange, q * scale);
    const VecF one = all(1.0f);
    return hn::IfThenElse(x == one, one, hn::IfThenElse(x > hn::Zero(d), r, x));
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_UNIT_POW_INL_H_
