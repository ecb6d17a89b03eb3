#include "scene_defaults.hpp"

namespace facet::view {

void lightingChosen(RenderSettings& settings) {
    if (settings.shader == ShaderKind::Texture && settings.lighting != Lighting::Off)
        settings.combine = true;
}

std::string noEffectNote(const Scene& scene, const RenderSettings& settings) {
    if (settings.shader == ShaderKind::Simple && settings.mode == DrawMode::Solid)
        return "The simple shader has no depth test: farther triangles drawn later cover nearer "
               "ones (the see-through patchwork). Try the painter shader, or cull back faces.";
    if (settings.shader != ShaderKind::Texture) return {};
    if (!scene.texture)
        return "The scene has no texture: the texture shader samples white. Load an image in "
               "the Texture panel or drop one on the window.";
    if (!scene.mesh->hasUvs())
        return "This mesh has no texture coordinates: every pixel samples the texel at uv = "
               "(0, 0).";
    if (settings.lighting != Lighting::Off && !settings.combine)
        return "Lighting has no effect: the texture shader shows the bare texel unless "
               "\"combine\" multiplies it by the lit colour.";
    return {};
}

}  // namespace facet::view
