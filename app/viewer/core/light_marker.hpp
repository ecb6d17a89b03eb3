#pragma once
// The light in the picture: where its marker goes and how dragging it moves the light. A point
// light's marker is the light itself, projected; a directional light (w = 0) gets a handle at
// kDirectionalHandle × the orbit distance from the look-at point, towards the light, with an
// arrow to the look-at point (the way the light travels). Dragging the marker puts it under the
// pointer on a sphere around the look-at point (its distance, at most 0.9 of the camera's), on
// the side the camera sees; Ctrl + drag turns it around the look-at point like the orbit.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/scene.hpp"

namespace facet::view {

/// A directional light's handle sits this share of the orbit distance from the look-at point.
inline constexpr double kDirectionalHandle = 0.35;

/// A dragged light moves on a sphere around the look-at point no larger than this share of the
/// camera's distance from it.
inline constexpr double kDragSphere = 0.9;

/// Where the light's marker is.
struct LightMarker {
    bool directional = false;
    bool visible = false;     ///< in front of the camera (its pixel means something)
    glm::dvec3 handle{0.0};   ///< the world point the marker stands for
    glm::dvec2 pixel{0.0};    ///< the handle in frame pixels
    glm::dvec2 aim{0.0};      ///< directional: the look-at point in frame pixels (arrow head)
    bool aimVisible = false;  ///< the look-at point is in front of the camera
    glm::dvec2 side{0.0};     ///< camera-space x, y of the handle: its side of the view, even
                              ///< behind the camera
};

/// Where the marker is drawn in a width × height frame: its projection when that lies inside
/// the frame, else on the frame's border inset by `inset` pixels, in the light's direction from
/// the centre (so a light off-screen or behind the camera can still be seen and grabbed).
glm::dvec2 markerPlace(const LightMarker& marker, int width, int height, double inset);

/// True when the marker's projection lies inside a width × height frame.
bool markerInFrame(const LightMarker& marker, int width, int height);

/// The marker of `light` seen by `camera` (the frame's), around the orbit's look-at point.
LightMarker lightMarker(const Camera& camera, const glm::dvec4& light, const glm::dvec3& target,
                        double orbitDistance);

/// The light moved so that its marker sits under frame pixel `pixel`: the handle stays at its
/// distance from `target` (a light at the target itself is taken at kDirectionalHandle × the
/// orbit distance), but no farther than kDragSphere × the camera's, at the sphere's near point
/// under the pointer, so always on the side the camera sees; a pointer beyond the sphere's
/// outline puts it on the outline, on the pointer's side. w is kept: a point light stays a point, a
/// directional one keeps |xyz|.
glm::dvec4 dragLight(const Camera& camera, const glm::dvec4& light, const glm::dvec3& target,
                     double orbitDistance, glm::dvec2 pixel);

/// The light turned around `target` by a mouse move of (dx, dy) pixels: dragging right moves
/// the side facing the camera right, dragging down moves it down. Its distance is kept.
glm::dvec4 turnLight(const Camera& camera, const glm::dvec4& light, const glm::dvec3& target,
                     double orbitDistance, double dx, double dy, double degreesPerPixel = 0.4);

}  // namespace facet::view
