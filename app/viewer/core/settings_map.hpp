#pragma once
// How the viewer's controls map onto engine settings: combo indices from the engine's name
// lists, colours between ImGui floats and 0xRRGGBB, the interpolation choice with its N, and
// the frame size and focal length for a window. No GL here: the unit tests call all of it.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::view {

/// Position of `name` in `names`, or 0 when absent (a combo box then shows the first entry).
int nameIndex(const std::vector<std::string_view>& names, std::string_view name);

/// 0xRRGGBB from three floats in [0, 1] (clamped, rounded to nearest; NaN counts as 0).
std::uint32_t hexFromRgb(const float rgb[3]);

/// Three floats in [0, 1] from 0xRRGGBB.
void rgbFromHex(std::uint32_t hex, float rgb[3]);

/// The interpolation a RenderSettings selects, with its N.
InterpSpec interpOf(const RenderSettings& settings);

/// Selects an interpolation (N clamped to kMinSubdivision…kMaxSubdivision).
void applyInterp(RenderSettings& settings, InterpSpec spec);

/// "affine", "perspective" or "subdivided 16": labels for the UI and the Compare panel.
std::string interpLabel(InterpSpec spec);

/// What the frame does when the window is resized.
enum class SizePolicy {
    FollowWindow,  ///< frame = window size, focal scaled by the height ratio so the framing stays
    SceneSize,     ///< frame = the scene's width × height, letterboxed into the window
};

/// Size and focal length of the frame to render: `scene` holds the scene's image size and the
/// user's focal length for it; the result keeps `scene`'s pose. Window sizes below 1 give 1.
Camera frameCamera(const Camera& scene, SizePolicy policy, int windowWidth, int windowHeight);

}  // namespace facet::view
