#pragma once
// The twin's GLSL: finding shaders/twin.vert, twin.frag and twin_lighting.glsl, and building a
// program for one pipeline variant by inserting #defines after the #version line. One source
// for every variant, like the engine's one template for every pipeline state.

#include <string>

#include "facet/error.hpp"
#include "gl_objects.hpp"

namespace facet::gl {

/// The twin's shader texts, read once.
struct ShaderSources {
    std::string folder;    ///< where they were found
    std::string vertex;    ///< twin.vert
    std::string fragment;  ///< twin.frag
    std::string lighting;  ///< twin_lighting.glsl: conventions §6, shared by both stages
};

/// Reads the sources from the folder compiled in (the source tree's shaders/), else a shaders/
/// folder beside the executable or up to three levels above it.
Result<ShaderSources> loadShaderSources();

/// Compiles and links one variant: `defines` ("#define NAME value" lines) go after each
/// stage's #version line, the lighting functions after them. The Error carries the driver's
/// log and the defines, so a broken variant names itself.
Result<Program> buildProgram(const ShaderSources& sources, const std::string& defines);

}  // namespace facet::gl
