#pragma once
// The Render panel's rule that no setting silently does nothing. What a scene opens with is the
// library's rule (facet/scene_defaults.hpp, applyOpeningSettings), the same as the CLI's.

#include <string>

#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::view {

/// Call after the user changed the lighting: under the texture shader lighting only shows
/// through combine, so switching lighting on turns combine on.
void lightingChosen(RenderSettings& settings);

/// Why a setting has no visible effect with these settings and this scene, or empty: lighting
/// under the texture shader without combine, the texture shader without a texture or uvs.
std::string noEffectNote(const Scene& scene, const RenderSettings& settings);

}  // namespace facet::view
