#include "orbit.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace facet::view {
namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Any unit vector perpendicular to unit `n`: crossed with the world axis least aligned with it.
glm::dvec3 perpendicular(const glm::dvec3& n) {
    const glm::dvec3 a = std::abs(n.x) < 0.6   ? glm::dvec3(1, 0, 0)
                         : std::abs(n.y) < 0.6 ? glm::dvec3(0, 1, 0)
                                               : glm::dvec3(0, 0, 1);
    return glm::normalize(glm::cross(n, a));
}

/// Unit horizontal direction at `yaw` degrees: reference turned towards vertical × reference
/// (the camera's right at yaw 0, so a positive yaw moves the eye to the right).
glm::dvec3 horizontal(const Orbit& o, double yaw) {
    const double y = glm::radians(yaw);
    return std::cos(y) * o.reference + std::sin(y) * glm::cross(o.vertical, o.reference);
}

}  // namespace

void orbitClamp(Orbit& o) {
    if (!std::isfinite(o.yaw)) o.yaw = 0.0;
    if (!std::isfinite(o.pitch)) o.pitch = 0.0;
    o.yaw = std::remainder(o.yaw, 360.0);  // (−180, 180]; remainder is exact
    if (o.yaw == -180.0) o.yaw = 180.0;
    o.pitch = std::clamp(o.pitch, -kMaxPitch, kMaxPitch);
    if (!(o.minDistance > 0.0)) o.minDistance = 1e-6;
    if (!(o.maxDistance >= o.minDistance)) o.maxDistance = o.minDistance;
    if (!std::isfinite(o.distance)) o.distance = o.minDistance;
    o.distance = std::clamp(o.distance, o.minDistance, o.maxDistance);
}

Orbit orbitMeasure(const Orbit& basis, const glm::dvec3& eye, const glm::dvec3& look) {
    Orbit o = basis;
    const glm::dvec3 offset = eye - look;
    const double dist = glm::length(offset);
    if (!finite(eye) || !finite(look) || !(dist > 0.0) || !std::isfinite(dist)) return o;
    o.target = look;
    o.distance = dist;
    const glm::dvec3 d = offset / dist;
    o.pitch = glm::degrees(std::asin(std::clamp(glm::dot(d, o.vertical), -1.0, 1.0)));
    const glm::dvec3 side = glm::cross(o.vertical, o.reference);
    o.yaw = glm::degrees(std::atan2(glm::dot(d, side), glm::dot(d, o.reference)));
    orbitClamp(o);
    return o;
}

Orbit orbitFromCamera(const Camera& camera) {
    Orbit o;
    const glm::dvec3 offset = camera.eye - camera.look;
    const double dist = glm::length(offset);
    const double upLength = glm::length(camera.up);
    if (finite(camera.up) && upLength > 0.0) o.vertical = -camera.up / upLength;
    // The horizontal part of the eye offset is yaw 0; a view straight along the vertical (which
    // a valid scene camera never has exactly) falls back to any horizontal direction.
    const glm::dvec3 flat = offset - glm::dot(offset, o.vertical) * o.vertical;
    const double flatLength = glm::length(flat);
    o.reference = flatLength > 1e-12 * dist && std::isfinite(flatLength)
                      ? flat / flatLength
                      : perpendicular(o.vertical);
    if (dist > 0.0 && std::isfinite(dist)) {
        o.minDistance = 1e-4 * dist;
        o.maxDistance = 1e4 * dist;
    }
    return orbitMeasure(o, camera.eye, camera.look);
}

void orbitAxes(const Orbit& o, glm::dvec3& right, glm::dvec3& screenUp) {
    const double p = glm::radians(o.pitch);
    const glm::dvec3 h = horizontal(o, o.yaw);
    // d(eye direction)/d(pitch): perpendicular to the view, leaning towards `vertical`.
    screenUp = -std::sin(p) * h + std::cos(p) * o.vertical;
    // d(eye direction)/d(yaw), normalised: the camera's right (spec §4: x = up × z).
    right = glm::cross(o.vertical, h);
}

Pose orbitPose(const Orbit& o) {
    const double p = glm::radians(o.pitch);
    const glm::dvec3 dir = std::cos(p) * horizontal(o, o.yaw) + std::sin(p) * o.vertical;
    glm::dvec3 right, screenUp;
    orbitAxes(o, right, screenUp);
    return {o.target + o.distance * dir, o.target, -screenUp};
}

void applyPose(const Orbit& orbit, Camera& camera) {
    const Pose pose = orbitPose(orbit);
    camera.eye = pose.eye;
    camera.look = pose.look;
    // The world's vertical as the y hint, not the screen's up: the same camera (spec §4
    // takes x = up × z), and a saved scene carries its up axis (§3b).
    camera.up = -orbit.vertical;
}

void orbitRotate(Orbit& o, double dx, double dy, double degreesPerPixel) {
    if (!std::isfinite(dx) || !std::isfinite(dy) || !std::isfinite(degreesPerPixel)) return;
    // The object follows the mouse: the eye moves the other way.
    o.yaw -= dx * degreesPerPixel;
    o.pitch += dy * degreesPerPixel;
    orbitClamp(o);
}

void orbitPan(Orbit& o, double dx, double dy, double focal) {
    if (!std::isfinite(dx) || !std::isfinite(dy) || !(focal > 0.0) || !std::isfinite(focal)) return;
    glm::dvec3 right, screenUp;
    orbitAxes(o, right, screenUp);
    // One pixel at the target's depth is distance / focal world units; the scene follows the
    // mouse, so the camera moves against it (image y grows downwards).
    const double perPixel = o.distance / focal;
    const glm::dvec3 move = (-dx * right + dy * screenUp) * perPixel;
    if (finite(move)) o.target += move;
}

void orbitZoom(Orbit& o, double steps) {
    if (!std::isfinite(steps)) return;
    o.distance *= std::pow(0.85, std::clamp(steps, -50.0, 50.0));
    orbitClamp(o);
}

}  // namespace facet::view
