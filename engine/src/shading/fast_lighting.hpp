#pragma once
// The fast path's float version of the lighting formula (facet/lighting.hpp states it and its
// rules for undefined directions), inline for the per-vertex (Gouraud) and per-pixel (Phong)
// loops.

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "facet/lighting.hpp"

namespace facet {

namespace detail {
/// v / |v|, or zero where |v| = 0: an undefined direction must contribute nothing, not NaN.
inline glm::vec3 normalizeOrZero(const glm::vec3& v) {
    const float length2 = glm::dot(v, v);
    return length2 > 0.0f ? v * (1.0f / std::sqrt(length2)) : glm::vec3(0.0f);
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

/// The lit colour clamp(rgb · I, 0, 1).
inline glm::vec3 shade(const glm::vec3& rgb, float intensity) {
    return glm::clamp(rgb * intensity, 0.0f, 1.0f);
}

}  // namespace facet
