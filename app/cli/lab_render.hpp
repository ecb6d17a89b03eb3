#pragma once
// `facet render --renderer lab`: the course's pipeline through the lab's steps (lab/).

#include <string>

#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::app {

/// Renders `scene` with the lab renderer, writes the PNG to `output` and says which steps are
/// still stubs and where the lab pipeline draws the settings differently. Returns an exit code.
int renderLab(const Scene& scene, const RenderSettings& settings, const std::string& output);

}  // namespace facet::app
