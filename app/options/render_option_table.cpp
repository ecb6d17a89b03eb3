#include "render_option_table.hpp"

#include <charconv>
#include <optional>

#include "facet/limits.hpp"
#include "facet/scene_io.hpp"

namespace facet::app {

using V = RenderOptionValues;

std::vector<std::string> choices(const std::vector<std::string_view>& names) {
    return {names.begin(), names.end()};
}

const std::vector<RenderOptionSpec>& renderOptionTable() {
    static const std::vector<RenderOptionSpec> table{
        {"scene",
         "The .scene file, or a bare .off/.obj mesh (framed from a three-quarter view, lit by a "
         "light near the camera)",
         {},
         &V::scene},
        {"--size",
         "Image size WxH (a .scene: the focal length scales with the width; a bare mesh: framed "
         "for this size, 1280x720 by default)",
         {},
         &V::size},
        {"--texture",
         "Texture image (PNG, JPEG, BMP, TGA), replacing the scene's",
         {},
         &V::texture},
        // Checked by checkRenderOptions, so the message names the value given.
        {"--up",
         "A bare mesh: the world axis it stands on, shown up: x, y or z (y by default; z for "
         "scans and CAD models made Z-up)",
         {},
         &V::up},
        {"--mode", "Draw mode", choices(drawModeNames()), &V::mode},
        {"--shader",
         "Shader (default: what the scene opens with: texture for a mesh with uvs and a texture, "
         "painter otherwise)",
         choices(shaderNames()), &V::shader},
        {"--interp", "Interpolation: affine, perspective, subdivided[:N]", {}, &V::interp},
        {"--lighting",
         "Lighting: off, gouraud (per vertex) or phong (per pixel) (default: what the scene "
         "opens with: off for a mesh whose vertex colours vary, as the course's scenes, gouraud "
         "otherwise)",
         choices(lightingNames()), &V::lighting},
        {"--filter", "Texture filter (default: bilinear)", choices(filterNames()), &V::filter},
        {"--combine",
         "Texture shader: multiply the texel by the (lit) vertex colour (default: on for a "
         "textured mesh without vertex colours, off otherwise)",
         {},
         &V::combine},
        {"--no-combine", "Texture shader: the texel alone", {}, &V::noCombine},
        {"--cull", "Drop back-facing triangles", {}, &V::cull},
        {"--normals", "Draw vertex normals as red segments", {}, &V::normals},
        {"--view",
         "Debug view instead of the shaded image, a heat map with a legend (docs/debug-views.md): "
         "overdraw (fragments per pixel), triangle-size (pixels of the triangle that wrote each "
         "pixel), bin-load (triangles per 64x64 tile), depth-test (passed, failed, no fragment), "
         "texture-lod (mip level under trilinear), interp-error (affine against perspective, "
         "8-bit steps)",
         choices(debugViewNames()), &V::view},
    };
    return table;
}

RegisteredOptions addRenderOptionTable(CLI::App& cmd, RenderOptionValues& values) {
    RegisteredOptions added;
    for (const RenderOptionSpec& spec : renderOptionTable()) {
        CLI::Option* option = nullptr;
        if (const auto* text = std::get_if<std::string V::*>(&spec.field)) {
            std::string& field = values.*(*text);
            option = cmd.add_option(spec.name, field, spec.help);
            if (!spec.choices.empty()) option->check(CLI::IsMember(spec.choices));
            if (!field.empty()) option->capture_default_str();
        } else {
            option = cmd.add_flag(spec.name, values.*std::get<bool V::*>(spec.field), spec.help);
        }
        added.emplace(spec.name, option);
    }
    added.at("--no-combine")->excludes(added.at("--combine"));
    return added;
}

bool parseSize(const std::string& text, int& width, int& height) {
    const auto x = text.find_first_of("xX");
    if (x == std::string::npos) return false;
    const char* b = text.data();
    const char* e = b + text.size();
    int w = 0, h = 0;
    const auto r1 = std::from_chars(b, b + x, w);
    const auto r2 = std::from_chars(b + x + 1, e, h);
    if (r1.ec != std::errc{} || r1.ptr != b + x || r2.ec != std::errc{} || r2.ptr != e)
        return false;
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide) return false;
    width = w;
    height = h;
    return true;
}

Status checkRenderOptions(const RenderOptionValues& o) {
    if (!parseInterpSpec(o.interp))
        return Error{{},
                     "--interp wants affine, perspective, subdivided or subdivided:N (N in 2.." +
                         std::to_string(kMaxSubdivision) + "), got '" + o.interp + "'"};
    if (!o.up.empty() && !parseUpAxis(o.up))
        return Error{{}, "--up " + o.up + ": expected x, y or z"};
    int w = 0, h = 0;
    if (!o.size.empty() && !parseSize(o.size, w, h))
        return Error{{},
                     "--size wants WxH with 1.." + std::to_string(kMaxImageSide) + " each, got '" +
                         o.size + "'"};
    return {};
}

Status applyRenderOptions(const RenderOptionValues& o, RenderSettings& settings) {
    const auto mode = parseDrawMode(o.mode);
    const auto interp = parseInterpSpec(o.interp);
    const auto view = parseDebugView(o.view);
    const auto shader = o.shader.empty() ? std::optional(settings.shader) : parseShader(o.shader);
    const auto lighting =
        o.lighting.empty() ? std::optional(settings.lighting) : parseLighting(o.lighting);
    const auto filter = o.filter.empty() ? std::optional(settings.filter) : parseFilter(o.filter);
    if (!mode || !interp || !view || !shader || !lighting || !filter)
        return Error{{}, "unknown mode, interpolation, view, shader, lighting or filter name"};
    settings.mode = *mode;
    settings.interp = interp->interp;
    settings.subdivision = interp->subdivision;
    settings.view = *view;
    settings.shader = *shader;
    settings.lighting = *lighting;
    settings.filter = *filter;
    if (o.combine) settings.combine = true;
    if (o.noCombine) settings.combine = false;
    settings.cullBackFaces = o.cull;
    settings.showNormals = o.normals;
    return {};
}

}  // namespace facet::app
