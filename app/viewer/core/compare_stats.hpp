#pragma once
// The Compare view's heat map and its colour bar: what each colour means. (Its numbers are
// diffImages over the pixels either side covers, DiffPixels::covered: averaged over the whole
// frame, a small object on a wide background reads as nearly equal; the brick wall's mean error
// was 9.18 over the frame against 48.7 over the wall.)

#include <glm/vec3.hpp>

#include "facet/evaluation/image_diff.hpp"
#include "facet/framebuffer.hpp"

namespace facet::view {

/// The automatic heat scale is never below this: differences of one or two 8-bit steps (the
/// CPU engine against the OpenGL twin) show dark, not glaring yellow.
inline constexpr int kMinAutoHeat = 16;

/// The error the heat map shows brightest: the scale when set (> 0), else the largest error,
/// at least kMinAutoHeat (the heat map and its colour bar both use it).
int heatTop(int heatScale, int maxError);

/// The heat map's colour for an error (8-bit steps) with `top` brightest: black for 0, viridis
/// over error / top otherwise; components in [0, 1].
glm::dvec3 heatColour(double error, int top);

}  // namespace facet::view
