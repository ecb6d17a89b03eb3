// Solution of steps 8 and 9 (assignment section 6): each light's share of
// I = Ia·Ka + Id · (Kd · max(0, n·l) + Ks · max(0, n·h)^s)   (spec §6).

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "lab/steps.hpp"

namespace lab {
namespace {

// A unit vector, or zero when the direction is undefined (never NaN).
glm::dvec3 unitOrZero(const glm::dvec3& v) {
    const double len = glm::length(v);
    return len > 0.0 && std::isfinite(len) ? v / len : glm::dvec3(0.0);
}

}  // namespace

double AmbientLight::getContribution(const Material& material) const {
    return intensity * material.ka;
}

double PointLight::getContribution(const glm::dvec3& point, const glm::dvec3& normal,
                                   const glm::dvec3& eye, const Material& material) const {
    // l: from the point to the light; w = 0 is a light at infinity coming from (x, y, z).
    const glm::dvec3 l = position.w == 0.0 ? unitOrZero(glm::dvec3(position))
                                           : unitOrZero(glm::dvec3(position) / position.w - point);
    const double nl = glm::dot(normal, l);
    if (!(nl > 0.0)) return 0.0;  // the light is behind the surface: no diffuse, no highlight
    const glm::dvec3 v = unitOrZero(eye - point);
    const glm::dvec3 h = unitOrZero(l + v);  // the bisector of l and v
    // n·h may round to just above 1; clamp so a huge exponent cannot overflow.
    const double nh = std::clamp(glm::dot(normal, h), 0.0, 1.0);
    return intensity * (material.kd * nl + material.ks * std::pow(nh, material.s));
}

}  // namespace lab
