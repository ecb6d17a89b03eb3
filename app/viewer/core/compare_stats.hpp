#pragma once
// The Compare view's numbers over the pixels that matter: those either side covers. Averaged
// over the whole frame, a small object on a wide background reads as nearly equal (the brick
// wall's mean error was 9.18 over the frame against 48.7 over the wall). And the heat map's
// colour bar: what each colour means.

#include <glm/vec3.hpp>

#include "facet/evaluation/image_diff.hpp"
#include "facet/framebuffer.hpp"

namespace facet::view {

/// Compares two frames over their covered pixels: those where either depth plane holds a
/// fragment, or whose colours differ (something was drawn there without depth: normals, a
/// legend). `pixels` counts them, `meanError` averages over them; the maximum and the count of
/// differing pixels are the whole frame's (no uncovered pixel differs). Frames without depth
/// planes count every pixel. Different sizes compare nothing (sameSize false).
ImageDiff diffCovered(const Framebuffer& a, const Framebuffer& b);

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
