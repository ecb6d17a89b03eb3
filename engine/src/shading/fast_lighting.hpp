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

/// I at point `p` with normal `n` (unit, or zero for none), seen from `eye`. Fast version: same
/// rules as the double one, agreeing to float rounding; `pow` raises n·h to the shininess.
template <class Pow = detail::LibmPow>
inline float lightIntensity(const glm::vec3& p, const glm::vec3& n, const glm::vec3& eye,
                            const FastLighting& lighting, Pow pow = {}) {
    // With w ≥ 0, xyz − w·p is w·(light point − p) for a point light and xyz for a directional
    // one: one expression, no division, no branch on the light's kind.
    const glm::vec3 l = detail::normalizeOrZero(glm::vec3(lighting.light) - lighting.light.w * p);
    const glm::vec3 v = detail::normalizeOrZero(eye - p);
    const glm::vec3 h = detail::normalizeOrZero(l + v);
    const float nl = glm::dot(n, l);
    const float nh = std::clamp(glm::dot(n, h), 0.0f, 1.0f);
    const float lit = lighting.diffuse * nl + lighting.specular * pow(nh, lighting.shininess);
    return lighting.ambientTerm + (nl > 0.0f ? lit : 0.0f);
}

/// The lit colour clamp(rgb · I, 0, 1).
inline glm::vec3 shade(const glm::vec3& rgb, float intensity) {
    return glm::clamp(rgb * intensity, 0.0f, 1.0f);
}

}  // namespace facet
