// spec §9: the settings a freshly opened scene shows.

#include "facet/scene_defaults.hpp"

#include <algorithm>

namespace facet {

bool hasVaryingColors(const Mesh& mesh) {
    if (mesh.colors.empty()) return false;
    const glm::vec3 first = mesh.colors.front();
    return std::any_of(mesh.colors.begin(), mesh.colors.end(),
                       [&](const glm::vec3& c) { return c != first; });
}

void applyOpeningSettings(const Scene& scene, RenderSettings& settings) {
    const bool textured = scene.texture != nullptr && scene.mesh->hasUvs();
    const bool colored = hasVaryingColors(*scene.mesh);
    settings.shader = textured ? ShaderKind::Texture : ShaderKind::Painter;
    // Combine multiplies the texel by the lit vertex colour: what an uncoloured textured mesh
    // (Spot) wants, and what would tint the course's coloured wall.
    settings.combine = textured && !colored;
    settings.lighting = colored ? Lighting::Off : Lighting::Gouraud;
}

}  // namespace facet
