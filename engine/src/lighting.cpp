// Conventions §6 in double, written the obvious way: the reference the float path in
// lighting.hpp is tested against. The header lists the choices for the undefined cases.

#include "facet/lighting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace facet {

namespace {

/// v / |v|, or zero where |v| = 0. Dividing by the largest component first keeps |v|² from
/// overflowing for a light placed as far as 1e300.
glm::dvec3 normalizeOrZero(const glm::dvec3& v) {
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (largest == 0.0) return glm::dvec3(0.0);
    const glm::dvec3 u = v / largest;
    return u / glm::length(u);
}

/// Narrows to float, saturating at the largest float: an overflow to +inf would turn a zero
/// factor (n·h = 0, Ks = 0) into NaN.
float narrow(double x) {
    return static_cast<float>(std::min(x, static_cast<double>(std::numeric_limits<float>::max())));
}

}  // namespace

LightingParams lightingParams(const Scene& scene) {
    return LightingParams{scene.ambient, scene.light, scene.material};
}

glm::dvec3 directionToLight(const glm::dvec3& p, const glm::dvec4& lightPosition) {
    const glm::dvec3 xyz(lightPosition);
    const double w = lightPosition.w;
    if (w == 0.0) return normalizeOrZero(xyz);
    return normalizeOrZero(xyz / w - p);
}

double lightIntensity(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& eye,
                      const LightingParams& params) {
    const Material& m = params.material;
    const double ambient = params.ambient * m.ka;

    const glm::dvec3 l = directionToLight(p, params.light.position);
    const double nl = glm::dot(n, l);
    if (nl <= 0.0) return ambient;

    const glm::dvec3 v = normalizeOrZero(eye - p);
    const glm::dvec3 h = normalizeOrZero(l + v);
    const double nh = std::clamp(glm::dot(n, h), 0.0, 1.0);
    const double diffuse = m.kd * nl;
    const double specular = m.ks * std::pow(nh, m.s);
    return ambient + params.light.intensity * (diffuse + specular);
}

FastLighting prepareLighting(const LightingParams& params) {
    // (x, y, z, w) and (−x, −y, −z, −w) are the same point; w ≥ 0 keeps xyz − w·p pointing at
    // the light. Any positive scale is the same point too; the largest |component| 1 keeps the
    // numbers in float range whatever the file said.
    glm::dvec4 q = params.light.position;
    if (q.w < 0.0) q = -q;
    const double largest = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z), q.w});
    if (largest > 0.0) q /= largest;

    const Material& m = params.material;
    const double id = params.light.intensity;
    FastLighting f;
    f.light = glm::vec4(q);
    f.ambientTerm = narrow(params.ambient * m.ka);
    f.diffuse = narrow(id * m.kd);
    f.specular = narrow(id * m.ks);
    f.shininess = static_cast<float>(m.s);  // +inf is a valid exponent (see the header)
    return f;
}

}  // namespace facet
