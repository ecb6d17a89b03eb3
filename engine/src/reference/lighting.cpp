// spec §6 in double, written the obvious way: the reference the float path
// (shading/fast_lighting.hpp) is tested against. facet/lighting.hpp lists the choices for the
// undefined cases.

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "facet/lighting.hpp"

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

}  // namespace

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

}  // namespace facet
