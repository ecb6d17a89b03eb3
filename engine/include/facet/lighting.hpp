#pragma once
// The Phong reflection model of spec §6 at one surface point:
//
//     I = Ia·Ka + Id · ( Kd · max(0, n·l) + Ks · max(0, n·h)^s )
//
// twice: a plain double version for the reference path (declared here), and an inline float
// version for the fast path's per-vertex (Gouraud) and per-pixel (Phong) shading (internal:
// shading/fast_lighting.hpp), fed by the FastLighting constants of
// facet/advanced/fast_lighting.hpp.
//
// Choices the formula leaves open, identical in both versions:
//  - An undefined direction is the zero vector, never NaN: l when the point is at the light (or a
//    w = 0 light has xyz = 0), v when the point is at the eye, h when l + v = 0 (the light exactly
//    behind the point as seen from the eye). A zero n (a vertex with no face, see normals.hpp) or
//    a zero l gives n·l = 0, so ambient only.
//  - Diffuse and specular are both zero where n·l ≤ 0: a light behind the surface adds no
//    highlight even where n·h > 0 (the course code lets it).
//  - n·h is clamped to [0, 1] before the power: rounding can push it to 1 + ε, and
//    (1 + ε)^s overflows to +inf for huge s. So any s ≥ 0, including 1e30 and +inf, gives a
//    finite result: 1 exactly at n = h, 0 elsewhere.
//  - 0^0 = 1 (std::pow's rule): with s = 0 the specular term is Ks everywhere n·l > 0, even
//    where n·h ≤ 0 or h is undefined; a constant "highlight" is what an exponent of 0 means.
//  - No distance attenuation; one light (the .scene format has one).

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/scene.hpp"

namespace facet {

/// Unit vector from `p` towards the light: normalize(xyz / w − p), or normalize(xyz) for w = 0;
/// zero where undefined.
glm::dvec3 directionToLight(const glm::dvec3& p, const glm::dvec4& lightPosition);

/// I at point `p` with normal `n` (unit, or zero for none), seen from `eye`. Reference version.
double lightIntensity(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& eye,
                      const LightingParams& params);

/// The lit colour clamp(rgb · I, 0, 1).
inline glm::dvec3 shade(const glm::dvec3& rgb, double intensity) {
    return glm::clamp(rgb * intensity, 0.0, 1.0);
}

}  // namespace facet
