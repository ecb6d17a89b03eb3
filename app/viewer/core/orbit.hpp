#pragma once
// Orbit camera maths for the viewer: yaw, pitch and distance around a look-at point. Pure
// functions on plain data (no window, no OpenGL), so the unit tests cover them fully.
//
// The basis is taken from the scene's camera: `vertical` is the world direction shown upwards
// (the negated y hint, spec §4) and `reference` the horizontal direction from the
// look-at point towards the scene's eye, so the scene's own view is yaw 0. The camera's up is
// built from yaw and pitch (perpendicular to the view, never parallel to it), and pitch stops
// short of ±90°: no flip and no NaN at the poles.

#include <glm/vec3.hpp>

#include "facet/scene.hpp"

namespace facet::view {

/// Largest |pitch| in degrees; at 90° the view would be parallel to `vertical`.
inline constexpr double kMaxPitch = 89.0;

/// An orbit pose. Angles are in degrees.
struct Orbit {
    glm::dvec3 target{0.0};               ///< look-at point the camera turns around
    glm::dvec3 vertical{0.0, 1.0, 0.0};   ///< unit world direction shown upwards on screen
    glm::dvec3 reference{0.0, 0.0, 1.0};  ///< unit, ⟂ vertical: where the eye sits at yaw 0
    double yaw = 0.0;       ///< around `vertical`, in (−180, 180]; positive moves the eye right
    double pitch = 0.0;     ///< elevation above the horizontal plane, within ±kMaxPitch
    double distance = 1.0;  ///< eye to target, within [minDistance, maxDistance]
    double minDistance = 1e-3;  ///< zoom limit: the eye never reaches (or crosses) the target
    double maxDistance = 1e6;   ///< zoom limit outwards
};

/// Camera position, look-at point and y hint (camera +y = image down) of an orbit.
struct Pose {
    glm::dvec3 eye{0.0};
    glm::dvec3 look{0.0};
    glm::dvec3 up{0.0, -1.0, 0.0};
};

/// The orbit that reproduces a camera's view: its basis, yaw 0, its pitch (clamped), its distance.
/// Distance limits are set to 1e-4 and 1e4 times that distance.
Orbit orbitFromCamera(const Camera& camera);

/// Yaw, pitch and distance of the pose eye → look measured in `basis`'s frame (its target moves
/// to `look`); the inverse of orbitPose() up to rounding and the pitch clamp.
Orbit orbitMeasure(const Orbit& basis, const glm::dvec3& eye, const glm::dvec3& look);

/// The pose an orbit describes; always finite for a finite orbit.
Pose orbitPose(const Orbit& orbit);

/// Writes an orbit's pose into a camera (eye, look, and −vertical as the y hint: the same
/// picture as the pose's up, and it carries the up axis), leaving focal and size alone.
void applyPose(const Orbit& orbit, Camera& camera);

/// Camera axes of an orbit in world space: right (image +x) and screen up (image −y).
void orbitAxes(const Orbit& orbit, glm::dvec3& right, glm::dvec3& screenUp);

/// Turns by a mouse drag of (dx, dy) pixels, image axes: dragging right turns the object right,
/// dragging down tips its top towards the viewer. Non-finite input changes nothing.
void orbitRotate(Orbit& orbit, double dx, double dy, double degreesPerPixel = 0.3);

/// Moves target and eye together so the target-depth plane follows a drag of (dx, dy) pixels
/// at focal length `focal` (pixels). Non-finite input changes nothing.
void orbitPan(Orbit& orbit, double dx, double dy, double focal);

/// Zooms by wheel steps (positive: closer), multiplying the distance by 0.85 per step and
/// clamping it to the limits, so the eye never crosses the target.
void orbitZoom(Orbit& orbit, double steps);

/// Brings angles and distance back into range (used after slider edits).
void orbitClamp(Orbit& orbit);

}  // namespace facet::view
