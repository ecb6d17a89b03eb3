#pragma once
// Cameras, scenes and frames the tests build in code: one place that spells a camera's fields,
// so a test states only its numbers.

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/mesh.hpp"
#include "facet/scene.hpp"

namespace facet::test {

/// The course's up hint: image-down leans towards −y, so +y shows up (spec §4).
inline constexpr glm::dvec3 kUpMinusY{0.0, -1.0, 0.0};

/// A camera at `eye` looking at `look`, `width`×`height` pixels, focal length `focal` in pixels.
inline Camera lookAt(const glm::dvec3& eye, const glm::dvec3& look, double focal, int width,
                     int height, const glm::dvec3& up = kUpMinusY) {
    return Camera{
        .eye = eye, .look = look, .up = up, .focal = focal, .width = width, .height = height};
}

/// A scene of `mesh` alone (default lighting, no texture) seen by `camera`.
inline Scene sceneOf(Mesh mesh, const Camera& camera) {
    Scene scene;
    scene.mesh = std::make_shared<const Mesh>(std::move(mesh));
    scene.camera = camera;
    return scene;
}

/// `positions` in clip space through `camera`, by its matrix rounded to float (the input these
/// tests hand Renderer::countCoverage).
inline std::vector<glm::vec4> clipPositions(const Camera& camera,
                                            const std::vector<glm::vec3>& positions) {
    const glm::mat4 m(clipFromWorld(camera));
    std::vector<glm::vec4> clip;
    clip.reserve(positions.size());
    for (const glm::vec3& p : positions) clip.push_back(m * glm::vec4(p, 1.0f));
    return clip;
}

/// A `width`×`height` frame filled with the packed colour `rgba` (depth cleared).
inline Framebuffer filledFrame(int width, int height, std::uint32_t rgba) {
    Framebuffer f;
    f.resize(width, height);
    f.clear(rgba);
    return f;
}

}  // namespace facet::test
