#pragma once
// Which shader variant a frame needs: the twin's counterpart of the engine's pipeline variant
// (pipeline.cpp), reduced to what changes the GLSL, and spelled as the #defines twin.vert and
// twin.frag read.

#include <string>

#include "facet/mesh.hpp"
#include "facet/settings.hpp"

namespace facet::gl {

/// One pipeline variant.
struct Variant {
    DrawMode mode = DrawMode::Solid;
    bool affine = false;       ///< noperspective varyings (Subdivided is drawn perspective)
    bool color = false;        ///< a colour varying: vertex colours, or Gouraud's lit colour
    bool gouraud = false;      ///< lighting per vertex
    bool phong = false;        ///< lighting per fragment
    bool texture = false;      ///< the Texture shader
    bool combine = false;      ///< texel × colour
    bool depthShader = false;  ///< the Depth shader
};

/// The variant for these settings and mesh, with the engine's rules: colour and lighting show
/// except in a depth image or a bare texel; a mesh without colours is white.
Variant variantFor(const RenderSettings& settings, const Mesh& mesh);

/// The variant as #define lines; `clipControl` adds CLIP_ZERO_TO_ONE (see twin.vert).
std::string definesFor(const Variant& variant, bool clipControl);

}  // namespace facet::gl
