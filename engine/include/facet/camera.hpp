#pragma once
// Camera transforms (spec §4) as GLM matrices, named by what they map.
//
// Clip space here is the homogeneous pixel space of the course's K matrix: a camera-space point
// (X, Y, Z) maps to clip (f·X + w/2·Z, f·Y + h/2·Z, Z, Z), so pixel = clip.xy / clip.w and
// clip.w is the depth Z. The third row keeps Z so nothing is lost; there is no far plane.

#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "facet/error.hpp"
#include "facet/limits.hpp"  // kMaxImageSide
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet {

/// Which field of view resizedCamera() keeps.
enum class KeepFov {
    Horizontal,  ///< focal scaled with the width (`facet render --size`)
    Vertical,    ///< focal scaled with the height (the viewer following its window)
};

/// The camera for a width × height image: same pose, the focal length scaled so the framing
/// along the `keep` axis stays. No clamping: the caller validates the size.
Camera resizedCamera(const Camera& camera, int width, int height,
                     KeepFov keep = KeepFov::Horizontal);

/// Rigid transform world -> camera: rows x, y, z of the camera frame, origin at the eye.
glm::dmat4 cameraFromWorld(const Camera& camera);

/// Intrinsics: camera space -> homogeneous pixel (clip) space, depth kept in z and w.
glm::dmat4 clipFromCamera(const Camera& camera);

/// The product of the two above.
glm::dmat4 clipFromWorld(const Camera& camera);

/// Continuous pixel coordinates and depth of a world point (depth <= 0: behind the camera).
glm::dvec3 projectToPixel(const Camera& camera, const glm::dvec3& world);

/// Validates a camera as spec §1 requires; returns an explanation or empty on success.
std::string checkCamera(const Camera& camera);

/// Near distance for a draw: the setting when positive, else 1e-3 of the mesh's bounding box
/// diagonal (spec §4, "a small fraction of the scene's size"). The fast and the reference path
/// both use it.
double resolveNearPlane(const RenderSettings& settings, const Mesh& mesh);

/// resolveNearPlane() with the mesh's bounds already known (computeBounds() of it).
double resolveNearPlane(const RenderSettings& settings, const Bounds& meshBounds);

/// Why a frame from `camera` cannot be rendered with `settings`: the camera is invalid
/// (checkCamera: non-finite, eye == look, y hint parallel, focal ≤ 0), its size is outside
/// 1…kMaxImageSide, or its buffers (with supersampling and MSAA) exceed kMaxFrameBytes
/// (limits.hpp). Success otherwise. Renderer::render and reference::render check with it before
/// allocating anything.
Status checkFrame(const Camera& camera, const RenderSettings& settings);

}  // namespace facet
