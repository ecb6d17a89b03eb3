#pragma once
// Perceptual colour map for the depth shader, shared by the fast and the reference paths.

#include <glm/vec3.hpp>

namespace facet {

/// Matplotlib's viridis at t in [0,1] (clamped; NaN maps to 0), linear between 17 samples.
glm::dvec3 viridis(double t);

}  // namespace facet
