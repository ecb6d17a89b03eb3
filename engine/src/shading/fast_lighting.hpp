#pragma once
// The fast path's float version of the lighting formula (facet/lighting.hpp states it and its
// rules for undefined directions), inline for the per-vertex (Gouraud) and per-pixel (Phong)
// loops.

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "facet/advanced/fast_lighting.hpp"

namespace facet {

namespace detail {
/// v / |v|, or zero where |v| = 0: an undefined direction must contribute nothing, not NaN.
inline glm::vec3 normalizeOrZero(const glm::vec3& v) {
    const float length2 = glm::dot(v, v);
    return length2 > 0.0f ? v * (1.0f / std::sqrt(length2)) : glm::vec3(0.0f);
}

/// The first guess of fastRsqrt(): the exponent halved and negated in the integer bits (Chris
/// Lomont's constant), within 3.5 % of 1/√x for every normal x.
inline constexpr std::int32_t kRsqrtGuess = 0x5F375A86;
inline constexpr float kRsqrtMinNormal = 1.17549435e-38f;  ///< 2^−126: below it, scale first
inline constexpr float kRsqrtScaleUp = 16777216.0f;        ///< 2^24, which scales 1/√x by 2^−12
inline constexpr float kRsqrtScaleBack = 4096.0f;          ///< 2^12

/// 1/√x for finite x > 0 without sqrt or division, which share one slow unit (a vector sqrt and
/// division cost about as much as twenty multiplies each): the bit guess and two Newton steps,
/// relative error under 5e-6 (unit_pow_test measures it), far below an 8-bit step even after
/// the specular power. Only integer ops and + − × in a fixed order (the engine is built without
/// contraction), so rsqrtLanes() in lanes-inl.hpp gives the same float on every SIMD target and
/// the scalar and vector loops the same image. A subnormal x is scaled into normal range first,
/// where the guess holds.
[[gnu::always_inline]] inline float fastRsqrt(float x) {
    const bool tiny = x < kRsqrtMinNormal;
    const float xs = tiny ? x * kRsqrtScaleUp : x;
    const float half = 0.5f * xs;
    float y = std::bit_cast<float>(kRsqrtGuess - (std::bit_cast<std::int32_t>(xs) >> 1));
    y = y * (1.5f - half * y * y);
    y = y * (1.5f - half * y * y);
    return tiny ? y * kRsqrtScaleBack : y;
}

/// 1/|v| by fastRsqrt(), or 0 where |v| = 0 (or is not a number): what makes an undefined
/// direction contribute nothing.
[[gnu::always_inline]] inline float inverseLength(const glm::vec3& v) {
    const float length2 = glm::dot(v, v);
    return length2 > 0.0f ? fastRsqrt(length2) : 0.0f;
}
}  // namespace detail

namespace detail {
/// std::pow as a function object: the specular power of per-vertex (Gouraud) lighting.
struct LibmPow {
    float operator()(float x, float s) const { return std::pow(x, s); }
};
}  // namespace detail

/// The formula's terms at one point: what lightIntensity() sums, for the pixel inspector.
struct LightTerms {
    glm::vec3 l{0.0f}, v{0.0f}, h{0.0f};  ///< to the light, to the eye, halfway (unit or zero)
    float nl = 0.0f, nh = 0.0f;           ///< n·l, and n·h clamped to [0, 1]
    float diffuse = 0.0f, specular = 0.0f;  ///< Id·Kd·n·l and Id·Ks·(n·h)^s, before the n·l test
    float intensity = 0.0f;                 ///< I
};

/// The terms of I at point `p` with normal `n` (unit, or zero for none), seen from `eye`.
template <class Pow = detail::LibmPow>
inline LightTerms lightTerms(const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye,
                             const FastLighting& lighting, Pow pow = {}) {
    LightTerms t;
    // With w ≥ 0, xyz − w·p is w·(light point − p) for a point light and xyz for a directional
    // one: one expression, no division, no branch on the light's kind.
    t.l = detail::normalizeOrZero(glm::vec3(lighting.light) - lighting.light.w * p);
    t.v = detail::normalizeOrZero(eye - p);
    t.h = detail::normalizeOrZero(t.l + t.v);
    t.nl = glm::dot(n, t.l);
    t.nh = std::clamp(glm::dot(n, t.h), 0.0f, 1.0f);
    t.diffuse = lighting.diffuse * t.nl;
    t.specular = lighting.specular * pow(t.nh, lighting.shininess);
    t.intensity = lighting.ambientTerm + (t.nl > 0.0f ? t.diffuse + t.specular : 0.0f);
    return t;
}

/// I at point `p` with normal `n` (unit, or zero for none), seen from `eye`. Fast version: same
/// rules as the double one, agreeing to float rounding; `pow` raises n·h to the shininess.
template <class Pow = detail::LibmPow>
inline float lightIntensity(const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye,
                            const FastLighting& lighting, Pow pow = {}) {
    return lightTerms(p, n, eye, lighting, pow).intensity;
}

/// lightTerms() per pixel, for Phong, at point `p` with the interpolated normal `n` (not unit,
/// or zero for none): the specular power by `pow`, the lengths by fastRsqrt(), and only the
/// vectors the formula adds normalised: l and v (h is their sum). n and h are never scaled:
/// n·l and n·h are the dot products with the raw vectors times 1/|n| and 1/|n|·1/|h|, the
/// same values to float rounding for three multiplies fewer per normalisation. lightLanes()
/// in the vector loops does the same operations in the same order.
// Always inlined, like the samplers (samplers.hpp): the vector loops' textured fallback calls it
// per pixel, and out of line it was compiled for the baseline target, whose legacy SSE code
// called from AVX code pays a state transition per call.
template <class Pow>
[[gnu::always_inline]] inline LightTerms phongTerms(const glm::vec3& p, const glm::vec3& n,
                                                    const glm::vec3& eye,
                                                    const FastLighting& lighting, Pow pow) {
    LightTerms t;
    const float rn = detail::inverseLength(n);
    const glm::vec3 toLight = glm::vec3(lighting.light) - lighting.light.w * p;  // as lightTerms()
    t.l = toLight * detail::inverseLength(toLight);
    const glm::vec3 toEye = eye - p;
    t.v = toEye * detail::inverseLength(toEye);
    const glm::vec3 halfway = t.l + t.v;
    const float rh = detail::inverseLength(halfway);
    t.h = halfway * rh;  // for the inspector: n·h below uses the raw sum
    t.nl = glm::dot(n, t.l) * rn;
    t.nh = std::clamp(glm::dot(n, halfway) * (rn * rh), 0.0f, 1.0f);
    t.diffuse = lighting.diffuse * t.nl;
    t.specular = lighting.specular * pow(t.nh, lighting.shininess);
    t.intensity = lighting.ambientTerm + (t.nl > 0.0f ? t.diffuse + t.specular : 0.0f);
    return t;
}

/// The lit colour clamp(rgb · I, 0, 1).
[[gnu::always_inline]] inline glm::vec3 shade(const glm::vec3& rgb, float intensity) {
    return glm::clamp(rgb * intensity, 0.0f, 1.0f);
}

}  // namespace facet
