#include "gl_variant.hpp"

namespace facet::gl {

Variant variantFor(const RenderSettings& s, const Mesh& mesh) {
    const bool usesColor =
        s.shader != ShaderKind::Depth && (s.shader != ShaderKind::Texture || s.combine);
    const bool lit = usesColor && s.lighting != Lighting::Off && mesh.vertexCount() > 0;
    Variant v;
    v.mode = s.mode;
    v.affine = s.interp == Interp::Affine;
    v.gouraud = lit && s.lighting == Lighting::Gouraud;
    v.phong = lit && s.lighting == Lighting::Phong;
    // Gouraud lights white when the mesh has no colours, so its colour varies anyway.
    v.color = usesColor && (mesh.hasColors() || v.gouraud);
    v.texture = s.shader == ShaderKind::Texture;
    v.combine = v.texture && s.combine;
    v.depthShader = s.shader == ShaderKind::Depth;
    return v;
}

std::string definesFor(const Variant& v, bool clipControl) {
    std::string d;
    auto define = [&d](const char* name, const char* value = "") {
        d.append("#define ").append(name).append(" ").append(value).append("\n");
    };
    const bool points = v.mode == DrawMode::Vertices;
    if (points) define("POINTS");
    if (v.mode == DrawMode::Wireframe) define("LINES");
    // A vertex square has one colour: its vertex's, with nothing to interpolate.
    define("INTERP", points ? "flat" : v.affine ? "noperspective" : "smooth");
    if (clipControl) define("CLIP_ZERO_TO_ONE");
    if (v.color) define("VARY_COLOR");
    if (v.gouraud) define("GOURAUD");
    if (v.phong) define("PHONG");
    if (v.texture) define("TEXTURE");
    // The engine samples lines and points at level 0: they have no uv derivatives.
    if (v.texture && v.mode != DrawMode::Solid) define("TEXTURE_LOD0");
    if (v.combine) define("COMBINE");
    if (v.depthShader) define("DEPTH_SHADER");
    return d;
}

}  // namespace facet::gl
