#pragma once
// Building test geometry in pixels: the world point a camera sees at a given pixel and depth.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "facet/camera.hpp"

namespace facet::test {

/// The world point that projects to pixel position (px, py) at camera depth z (spec §4).
inline glm::vec3 worldAt(const Camera& cam, double px, double py, double z) {
    const glm::dvec3 zAxis = glm::normalize(cam.look - cam.eye);
    const glm::dvec3 xAxis = glm::normalize(glm::cross(cam.up, zAxis));
    const glm::dvec3 yAxis = glm::cross(zAxis, xAxis);
    const double x = (px - cam.width / 2.0) / cam.focal * z;
    const double y = (py - cam.height / 2.0) / cam.focal * z;
    return glm::vec3(cam.eye + x * xAxis + y * yAxis + z * zAxis);
}

}  // namespace facet::test
