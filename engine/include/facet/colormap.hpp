#pragma once
// Perceptual colour map for the depth shader, shared by the fast and the reference paths.

#include <cstdint>

#include <glm/vec3.hpp>

#include "facet/framebuffer.hpp"

namespace facet {

/// Matplotlib's viridis at t in [0,1] (clamped; NaN maps to 0), linear between 17 samples.
glm::dvec3 viridis(double t);

/// The Depth shader's colour of a pixel at `depth`, the frame's visible depth range being
/// [nearest, farthest]: viridis from near (dark) to far (bright), rounded in float.
inline std::uint32_t depthColor(float depth, float nearest, float farthest) {
    const double range = farthest > nearest ? static_cast<double>(farthest) - nearest : 1.0;
    const glm::vec3 c(viridis((depth - static_cast<double>(nearest)) / range));
    return packRgba(toByte(c.r), toByte(c.g), toByte(c.b));
}

}  // namespace facet
