#pragma once
// Start-up settings that show what a scene has (issue 14, point 6), and the Render panel's rule
// that no setting silently does nothing. `facet render` keeps the course's defaults; only the
// viewer picks these.

#include <string>

#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::view {

/// Shader, lighting and combine for a freshly opened scene: a texture with uvs opens with the
/// texture shader, combine and Gouraud; a bare mesh (no .scene) with Gouraud; a .scene without a
/// usable texture keeps the course's unlit painter.
void applySceneDefaults(const Scene& scene, bool bareMesh, RenderSettings& settings);

/// Call after the user changed the lighting: under the texture shader lighting only shows
/// through combine, so switching lighting on turns combine on.
void lightingChosen(RenderSettings& settings);

/// Why a setting has no visible effect with these settings and this scene, or empty: lighting
/// under the texture shader without combine, the texture shader without a texture or uvs.
std::string noEffectNote(const Scene& scene, const RenderSettings& settings);

}  // namespace facet::view
