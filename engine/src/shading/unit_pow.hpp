#pragma once
// x^s for x in [0, 1] and s ≥ 0, Phong's specular term (n·h)^s, without libm: log2 of x by a
// series in t = (m − 1)/(m + 1) of its mantissa m ∈ [√½, √2), times s, then exp2 by a Taylor
// polynomial of the fraction and the integer part put in the exponent bits. Plain multiplies and
// adds in a fixed order, so the vector version (unit_pow-inl.hpp) gives the same float on every
// SIMD target, and the scalar and span loops the same image. Relative error about 1e-6 where
// the result is above 2^-9, far below the 8-bit step (unit_pow_test measures it).

#include <bit>
#include <cstdint>

namespace facet::detail {

/// Coefficients of log2(m) = t·(c0 + c1·t² + c2·t⁴ + c3·t⁶ + c4·t⁸), ck = 2 / ((2k + 1)·ln 2).
inline constexpr float kLog2Series[5] = {2.8853900817779268f, 0.96179669392597560f,
                                         0.57707801635558536f, 0.41219858311113240f,
                                         0.32059889797532520f};
/// Coefficients of 2^f = Σ ck·f^k, ck = (ln 2)^k / k!, for f ∈ [−½, ½].
inline constexpr float kExp2Series[7] = {1.0f,
                                         0.69314718055994531f,
                                         0.24022650695910071f,
                                         0.055504108664821580f,
                                         0.0096181291076284772f,
                                         0.0013333558146428443f,
                                         0.00015403530393381610f};
inline constexpr float kSqrtHalf2 = 1.41421356237309505f;  ///< √2
inline constexpr float kMinNormal = 1.17549435e-38f;       ///< 2^−126
inline constexpr float kTwo24 = 16777216.0f;               ///< 2^24
/// Below 2^−125 the result is 0: no colour channel can tell.
inline constexpr float kMinExponent = -125.0f;

/// x^s for x in [0, 1] and s ≥ 0 (+inf included): 1 when x = 1 or s = 0, x itself when x is not
/// positive (0 stays 0, NaN stays NaN), else 2^(s·log2 x).
[[gnu::always_inline]] inline float unitPow(float x, float s) {
    if (x == 1.0f || s == 0.0f) return 1.0f;
    if (!(x > 0.0f)) return x;
    // log2 x = e + log2 m, m ∈ [√½, √2); a subnormal x is scaled up into normal range first.
    const bool tiny = x < kMinNormal;
    const float xs = tiny ? x * kTwo24 : x;
    const auto bits = std::bit_cast<std::int32_t>(xs);
    std::int32_t e = (bits >> 23) - 127 - (tiny ? 24 : 0);
    float m = std::bit_cast<float>((bits & 0x7FFFFF) | 0x3F800000);
    if (m > kSqrtHalf2) {
        m = m * 0.5f;
        e = e + 1;
    }
    const float t = (m - 1.0f) / (m + 1.0f);
    const float t2 = t * t;
    float p = kLog2Series[4];
    for (int k = 3; k >= 0; --k) p = p * t2 + kLog2Series[k];
    const float y = s * (static_cast<float>(e) + p * t);
    if (!(y >= kMinExponent)) return 0.0f;
    // 2^y = 2^f · 2^n, n = y rounded (y ≤ 0: truncating y − ½ rounds), f ∈ [−½, ½].
    const auto n = static_cast<std::int32_t>(y - 0.5f);
    const float f = y - static_cast<float>(n);
    float q = kExp2Series[6];
    for (int k = 5; k >= 0; --k) q = q * f + kExp2Series[k];
    return q * std::bit_cast<float>((n + 127) << 23);
}

}  // namespace facet::detail
