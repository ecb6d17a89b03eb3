#pragma once
// x^s for x in [0, 1] and s ≥ 0, Phong's specular term (n·h)^s, without libm: log2 of x by a
// series in t = (m − 1)/(m + 1) of its mantissa m ∈ [√½, √2), times s, then exp2 by a Taylor
// polynomial of the fraction and the integer part put in the exponent bits. Plain multiplies and
// adds in a fixed order, so the vector version (unit_pow-inl.hpp) gives the same float on every
// SIMD target, and the scalar and span loops the same image. Relative error about 1e-6 where
// the result is above 2^-9, far below the 8-bit step (unit_pow_test measures it).

#include <bit>
#include <cmath>
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

/// Where Phong's specular term cannot change a pixel's intensity (per draw, for the vector
/// loops; specularSkip() computes it): on a lit lane whose n·h ≤ maxNh and whose diffuse term
/// a = Id·Kd·n·l ≥ minDiffuse, b = Id·Ks·unitPow(n·h, s) rounds to at most a·2^−25, less than
/// half a float step of a, so the float sum a + b is a itself and I the same bits without b.
/// The defaults skip nothing (n·h is never below 0).
struct SpecularSkip {
    float maxNh = -1.0f;
    float minDiffuse = 0.0f;
};

/// The SpecularSkip of a draw with Id·Kd = `diffuse`, Id·Ks = `specular` and shininess `s`;
/// nothing skipped unless all three are positive and finite (s ≤ 10⁴).
///
/// Why it holds: with a ≥ A = diffuse/16 and b ≥ 0, a + b rounds to a when b ≤ A·2^−25 (half
/// the float step above a is more than a·2^−25). b = fl(specular·P) ≤ specular·P·(1 + 2^−22)
/// while specular·P stays normal (A ≥ 2^−90 is required for that), and P = unitPow(x, s) ≤
/// x^s·2^(δ) for x in [0, 1]: δ bounds the error of unitPow's exponent y = s·log2 x (the log2
/// series' truncation under 1e-9, its float roundings about 1e-7 and e + p·t's rounding under
/// 2^−17, all times s; y's own rounding under 2^−17) and of the exp2 polynomial (relative 1e-6):
/// δ = 0.01 + s/1024 is a hundred times that. So maxNh = (A·2^−25 / (specular·(1 + 2^−22)) ·
/// 2^−δ)^(1/s), rounded down to a float: x ≤ maxNh gives b ≤ A·2^−25. (unitPow gives 0 below
/// y = −125 and 1 at x = 1, both within the bound.) lighting_lanes_test checks the claim on
/// dense grids.
inline SpecularSkip specularSkip(float diffuse, float specular, float s) {
    SpecularSkip skip;
    const bool finite = std::isfinite(diffuse) && std::isfinite(specular) && std::isfinite(s);
    if (!finite || !(diffuse > 0.0f) || !(specular > 0.0f) || !(s > 0.0f) || s > 1e4f) return skip;
    const float minDiffuse = diffuse / 16.0f;  // exact unless it underflows: then nothing skips
    if (!(minDiffuse >= 0x1p-90f)) return skip;
    const double slack = 0.01 + static_cast<double>(s) / 1024.0;
    const double log2Bound = std::log2(static_cast<double>(minDiffuse)) - 25.0 -
                             std::log2(static_cast<double>(specular) * (1.0 + 0x1p-22));
    const double maxNh = std::exp2((log2Bound - slack) / static_cast<double>(s));
    float t = static_cast<float>(maxNh);
    if (static_cast<double>(t) > maxNh) t = std::nextafter(t, 0.0f);
    skip.maxNh = t;
    skip.minDiffuse = minDiffuse;
    return skip;
}

}  // namespace facet::detail
