#include "facet/camera.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "facet/limits.hpp"
#include "passes/supersample.hpp"  // kMaxSupersample

namespace facet {

glm::dmat4 cameraFromWorld(const Camera& camera) {
    const glm::dvec3 z = glm::normalize(camera.look - camera.eye);
    const glm::dvec3 x = glm::normalize(glm::cross(camera.up, z));
    const glm::dvec3 y = glm::cross(z, x);
    // GLM is column-major: m[column][row]. Rows of the rotation are the camera axes.
    glm::dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = x[c];
        m[c][1] = y[c];
        m[c][2] = z[c];
    }
    m[3][0] = -glm::dot(x, camera.eye);
    m[3][1] = -glm::dot(y, camera.eye);
    m[3][2] = -glm::dot(z, camera.eye);
    return m;
}

glm::dmat4 clipFromCamera(const Camera& camera) {
    // Rows: (f, 0, w/2, 0), (0, f, h/2, 0), (0, 0, 1, 0), (0, 0, 1, 0).
    glm::dmat4 m(0.0);
    m[0][0] = camera.focal;
    m[1][1] = camera.focal;
    m[2][0] = 0.5 * camera.width;
    m[2][1] = 0.5 * camera.height;
    m[2][2] = 1.0;
    m[2][3] = 1.0;
    return m;
}

glm::dmat4 clipFromWorld(const Camera& camera) {
    return clipFromCamera(camera) * cameraFromWorld(camera);
}

glm::dvec3 projectToPixel(const Camera& camera, const glm::dvec3& world) {
    const glm::dvec4 clip = clipFromWorld(camera) * glm::dvec4(world, 1.0);
    return {clip.x / clip.w, clip.y / clip.w, clip.w};
}

std::string checkCamera(const Camera& camera) {
    auto finite3 = [](const glm::dvec3& v) {
        return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
    };
    if (!finite3(camera.eye) || !finite3(camera.look) || !finite3(camera.up))
        return "camera vectors must be finite";
    const glm::dvec3 forward = camera.look - camera.eye;
    const double len = glm::length(forward);
    if (!(len > 0.0)) return "look-at point equals the camera position";
    const double upLen = glm::length(camera.up);
    if (!(glm::length(glm::cross(camera.up, forward)) > 1e-12 * len * upLen))
        return "y hint is zero or parallel to the viewing direction";
    if (!(camera.focal > 0.0) || !std::isfinite(camera.focal))
        return "focal length must be a positive number of pixels";
    if (camera.width < 1 || camera.width > kMaxImageSide || camera.height < 1 ||
        camera.height > kMaxImageSide)
        return "image size must be 1.." + std::to_string(kMaxImageSide) +
               " pixels in each direction";
    return {};
}

Camera resizedCamera(const Camera& camera, int width, int height, KeepFov keep) {
    Camera c = camera;
    // Each rule keeps the order of operations its callers always used, so their images stay
    // bit for bit what they were (f·(w/W) is exactly f·n for an n-times supersampled image).
    if (keep == KeepFov::Horizontal)
        c.focal = camera.focal * (static_cast<double>(width) / camera.width);
    else
        c.focal = camera.focal * static_cast<double>(height) / static_cast<double>(camera.height);
    c.width = width;
    c.height = height;
    return c;
}

double resolveNearPlane(const RenderSettings& settings, const Mesh& mesh) {
    if (settings.nearPlane > 0.0) return settings.nearPlane;
    return resolveNearPlane(settings, computeBounds(mesh));
}

double resolveNearPlane(const RenderSettings& settings, const Bounds& meshBounds) {
    if (settings.nearPlane > 0.0) return settings.nearPlane;
    const double diagonal = meshBounds.diagonal();
    return diagonal > 0.0 ? 1e-3 * diagonal : 1e-3;
}

Status checkFrame(const Camera& camera, const RenderSettings& settings) {
    if (std::string problem = checkCamera(camera); !problem.empty()) {
        // The size has its own message with the numbers; the rest are the camera's.
        if (camera.width < 1 || camera.width > kMaxImageSide || camera.height < 1 ||
            camera.height > kMaxImageSide)
            return checkImageSize(camera.width, camera.height, 1, 1);
        return Error{{}, "camera: " + problem};
    }
    const int supersample = settings.mode == DrawMode::Solid
                                ? std::clamp(settings.supersample, 1, detail::kMaxSupersample)
                                : 1;
    const int msaa = settings.mode == DrawMode::Solid ? settings.msaa : 1;
    return checkImageSize(camera.width, camera.height, supersample, msaa);
}

}  // namespace facet
