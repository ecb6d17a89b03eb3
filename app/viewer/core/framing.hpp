#pragma once
// Framing the model (the F key): the orbit's look-at point moves to the centre of the mesh's
// bounding sphere and the distance becomes the one at which that sphere just fits the frame's
// narrower field of view, with a margin. The view direction is kept.

#include <glm/vec3.hpp>

#include "facet/mesh.hpp"
#include "facet/scene.hpp"
#include "orbit.hpp"

namespace facet::view {

struct ViewerModel;

/// Share of the narrower half field of view the framed sphere fills (a margin around it).
inline constexpr double kFrameFill = 0.9;

/// A sphere around every vertex: the bounding box's centre and half diagonal (radius 0 for an
/// empty mesh, centred at the origin).
struct Sphere {
    glm::dvec3 centre{0.0};
    double radius = 0.0;
};

/// The bounding sphere of a mesh's positions.
Sphere boundingSphere(const Mesh& mesh);

/// The eye distance at which a sphere of `radius` fills kFrameFill of the narrower half field of
/// view of a camera with `focal` pixels over a width × height frame.
double framingDistance(double radius, double focal, int width, int height);

/// Moves the orbit's target to the sphere's centre and sets the distance that frames it for the
/// camera `frame` (its focal length and size), widening the zoom limits when needed. Yaw and
/// pitch stay.
void frameSphere(Orbit& orbit, const Sphere& sphere, const Camera& frame);

/// frameSphere() for the model's mesh and the camera of its last frame; marks the view moved.
void frameModel(ViewerModel& model);

}  // namespace facet::view
