// Rule 1 of the reference path: projection in double, straight from spec §4.

#include <glm/geometric.hpp>

#include "facet/reference.hpp"

namespace facet::reference {

glm::dvec4 projectPoint(const Camera& cam, const glm::dvec3& world) {
    const glm::dvec3 z = glm::normalize(cam.look - cam.eye);
    const glm::dvec3 x = glm::normalize(glm::cross(cam.up, z));
    const glm::dvec3 y = glm::cross(z, x);
    const glm::dvec3 d = world - cam.eye;
    const glm::dvec3 pc{glm::dot(x, d), glm::dot(y, d), glm::dot(z, d)};
    // K·p_c, with the divide by Z left to the rasterizer (and w = Z kept for depth).
    return {cam.focal * pc.x + cam.width / 2.0 * pc.z, cam.focal * pc.y + cam.height / 2.0 * pc.z,
            pc.z, pc.z};
}

std::vector<glm::dvec4> projectScene(const Scene& scene) {
    std::vector<glm::dvec4> clip;
    clip.reserve(scene.mesh->positions.size());
    for (const glm::vec3& position : scene.mesh->positions) {
        clip.push_back(projectPoint(scene.camera, glm::dvec3(position)));
    }
    return clip;
}
}  // namespace facet::reference
