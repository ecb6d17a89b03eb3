#include "framing.hpp"

#include <algorithm>
#include <cmath>

#include "viewer_model.hpp"

namespace facet::view {

Sphere boundingSphere(const Mesh& mesh) {
    const Bounds b = computeBounds(mesh);
    if (!(b.min.x <= b.max.x)) return {};  // empty: min > max
    const glm::dvec3 lo(b.min), hi(b.max);
    return {(lo + hi) * 0.5, 0.5 * glm::length(hi - lo)};
}

double framingDistance(double radius, double focal, int width, int height) {
    const double half = 0.5 * std::max(1, std::min(width, height));
    const double halfAngle = std::atan(half / std::max(focal, 1e-9));
    // The sphere's silhouette subtends asin(r / d) from the eye: set that to a share of the
    // half angle.
    return std::max(radius, 1e-9) / std::sin(kFrameFill * halfAngle);
}

void frameSphere(Orbit& orbit, const Sphere& sphere, const Camera& frame) {
    const double d = framingDistance(sphere.radius, frame.focal, frame.width, frame.height);
    if (!std::isfinite(d) || !std::isfinite(sphere.centre.x) || !std::isfinite(sphere.centre.y) ||
        !std::isfinite(sphere.centre.z))
        return;
    orbit.target = sphere.centre;
    orbit.minDistance = std::min(orbit.minDistance, 1e-4 * d);
    orbit.maxDistance = std::max(orbit.maxDistance, 1e4 * d);
    orbit.distance = d;
    orbitClamp(orbit);
}

void frameModel(ViewerModel& model) {
    frameSphere(model.orbit, boundingSphere(*model.scene.mesh), model.scene.camera);
    model.orbitMoved = true;
}

}  // namespace facet::view
