#include "light_marker.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include "facet/camera.hpp"

namespace facet::view {
namespace {

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// The handle's world point, and its distance from the target as the drag keeps it.
glm::dvec3 handleOf(const glm::dvec4& light, const glm::dvec3& target, double orbitDistance) {
    const glm::dvec3 xyz(light);
    if (light.w == 0.0) {
        const double n = glm::length(xyz);
        const glm::dvec3 dir = n > 0.0 ? xyz / n : glm::dvec3(0.0, 0.0, 1.0);
        return target + dir * (kDirectionalHandle * orbitDistance);
    }
    return xyz / light.w;
}

/// The light whose handle is `handle` (w kept).
glm::dvec4 lightAt(const glm::dvec4& light, const glm::dvec3& target, const glm::dvec3& handle) {
    if (light.w == 0.0) {
        const glm::dvec3 d = handle - target;
        const double n = glm::length(d);
        const double keep = glm::length(glm::dvec3(light));
        if (!(n > 0.0)) return light;
        return {d / n * (keep > 0.0 ? keep : 1.0), 0.0};
    }
    return {handle * light.w, light.w};
}

/// Radius of the sphere the handle moves on (never 0: a light at the target still moves).
double radiusOf(const glm::dvec3& handle, const glm::dvec3& target, double orbitDistance) {
    const double r = glm::length(handle - target);
    return r > 1e-9 * std::max(1.0, orbitDistance) ? r : kDirectionalHandle * orbitDistance;
}

/// Rodrigues: v turned by `angle` radians around the unit `axis`.
glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0 - c);
}

}  // namespace

LightMarker lightMarker(const Camera& camera, const glm::dvec4& light, const glm::dvec3& target,
                        double orbitDistance) {
    LightMarker m;
    m.directional = light.w == 0.0;
    m.handle = handleOf(light, target, orbitDistance);
    if (!finite(m.handle)) return m;
    const glm::dvec4 c = cameraFromWorld(camera) * glm::dvec4(m.handle, 1.0);
    m.side = {c.x, c.y};
    const glm::dvec3 p = projectToPixel(camera, m.handle);
    m.visible = p.z > 0.0 && std::isfinite(p.x) && std::isfinite(p.y);
    m.pixel = {p.x, p.y};
    const glm::dvec3 a = projectToPixel(camera, target);
    m.aimVisible = a.z > 0.0 && std::isfinite(a.x) && std::isfinite(a.y);
    m.aim = {a.x, a.y};
    return m;
}

bool markerInFrame(const LightMarker& m, int width, int height) {
    return m.visible && m.pixel.x >= 0.0 && m.pixel.y >= 0.0 && m.pixel.x < width &&
           m.pixel.y < height;
}

glm::dvec2 markerPlace(const LightMarker& m, int width, int height, double inset) {
    if (markerInFrame(m, width, height)) return m.pixel;
    const glm::dvec2 centre(0.5 * width, 0.5 * height);
    glm::dvec2 d = m.visible ? m.pixel - centre : m.side;
    if (!(std::abs(d.x) > 0.0 || std::abs(d.y) > 0.0) || !std::isfinite(d.x) || !std::isfinite(d.y))
        d = {0.0, 1.0};  // straight behind: at the bottom
    const double hx = std::max(0.0, 0.5 * width - inset), hy = std::max(0.0, 0.5 * height - inset);
    const double tx = d.x != 0.0 ? hx / std::abs(d.x) : INFINITY;
    const double ty = d.y != 0.0 ? hy / std::abs(d.y) : INFINITY;
    return centre + d * std::min(tx, ty);
}

glm::dvec4 dragLight(const Camera& camera, const glm::dvec4& light, const glm::dvec3& target,
                     double orbitDistance, glm::dvec2 pixel) {
    const glm::dvec3 handle = handleOf(light, target, orbitDistance);
    if (!finite(handle) || !std::isfinite(pixel.x) || !std::isfinite(pixel.y)) return light;
    // The pointer's ray: camera-space direction ((x − w/2)/f, (y − h/2)/f, 1) taken to world.
    const glm::dmat4 worldFromCamera = glm::inverse(cameraFromWorld(camera));
    const glm::dvec3 eye(worldFromCamera * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    // The sphere is never larger than the camera's distance (kDragSphere of it): the eye stays
    // outside, and the near intersection, the one taken, lies on the hemisphere the camera sees,
    // so the light stays on the model's lit side (a farther light would be met only behind).
    const double r =
        std::min(radiusOf(handle, target, orbitDistance), kDragSphere * glm::length(eye - target));
    if (!(r > 0.0)) return light;
    const double f = camera.focal;
    const glm::dvec3 dirCam((pixel.x - 0.5 * camera.width) / f, (pixel.y - 0.5 * camera.height) / f,
                            1.0);
    const glm::dvec3 dir = glm::normalize(glm::dvec3(worldFromCamera * glm::dvec4(dirCam, 0.0)));
    // |eye + t·dir − target|² = r²: t² + 2bt + c = 0.
    const glm::dvec3 oc = eye - target;
    const double b = glm::dot(oc, dir);
    const double c = glm::dot(oc, oc) - r * r;
    const double disc = b * b - c;
    glm::dvec3 next;
    if (disc >= 0.0 && -b - std::sqrt(disc) > 0.0) {
        next = eye + dir * (-b - std::sqrt(disc));
    } else {
        // Past the outline (the eye is outside the sphere): the outline's point on the
        // pointer's side. The outline is the circle of tangent points, centred r²/D from the
        // target towards the eye, of radius r·sqrt(1 − r²/D²).
        const glm::dvec3 toEye = eye - target;
        const double d2 = glm::dot(toEye, toEye);
        const glm::dvec3 across = dir - toEye * (glm::dot(dir, toEye) / d2);
        const double n = glm::length(across);
        if (!(n > 0.0) || !(d2 > r * r)) return light;
        next = target + toEye * (r * r / d2) + across / n * (r * std::sqrt(1.0 - r * r / d2));
    }
    if (!finite(next)) return light;
    return lightAt(light, target, next);
}

glm::dvec4 turnLight(const Camera& camera, const glm::dvec4& light, const glm::dvec3& target,
                     double orbitDistance, double dx, double dy, double degreesPerPixel) {
    if (!std::isfinite(dx) || !std::isfinite(dy)) return light;
    const glm::dvec3 handle = handleOf(light, target, orbitDistance);
    if (!finite(handle)) return light;
    const glm::dmat4 worldFromCamera = glm::inverse(cameraFromWorld(camera));
    const glm::dvec3 right = glm::normalize(glm::dvec3(worldFromCamera[0]));  // image +x
    const glm::dvec3 down = glm::normalize(glm::dvec3(worldFromCamera[1]));   // image +y
    const glm::dvec3 towardsEye = -glm::normalize(glm::dvec3(worldFromCamera[2]));
    glm::dvec3 v = handle - target;
    if (!(glm::length(v) > 1e-9 * std::max(1.0, orbitDistance)))
        v = towardsEye * (kDirectionalHandle * orbitDistance);
    const double k = degreesPerPixel * M_PI / 180.0;
    // Turning towardsEye into `right` (axis towardsEye × right) moves the facing side right.
    v = rotate(v, glm::normalize(glm::cross(towardsEye, right)), dx * k);
    v = rotate(v, glm::normalize(glm::cross(towardsEye, down)), dy * k);
    return lightAt(light, target, target + v);
}

}  // namespace facet::view
