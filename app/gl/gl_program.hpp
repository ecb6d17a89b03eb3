#pragma once
// GLSL programs from shader files, for everything in facet that draws with OpenGL: the twin's
// pipeline (twin.vert, twin.frag, twin_lighting.glsl) and the viewer's fullscreen triangle
// (frame.vert, frame.frag). Finding the shaders folder, reading the files, compiling, linking
// and the error messages live here once: a file that is missing, unreadable or does not compile
// is an Error naming the file with the driver's GLSL log, never an abort.

#include <string>

#include "facet/error.hpp"
#include "gl_objects.hpp"

namespace facet::gl {

/// One stage's GLSL text and the file it came from (named in error messages).
struct StageSource {
    std::string path;  ///< the file, for messages
    std::string text;  ///< what is compiled
};

/// The folder holding `file`: $FACET_SHADERS when set (for trying shader edits without a
/// rebuild), else the source tree's shaders/ compiled in, else shaders/ beside the executable
/// or up to three levels above it. The Error says where it looked.
Result<std::string> findShaderFolder(const std::string& file);

/// Reads a shader file; the Error names it.
Result<StageSource> readShaderFile(const std::string& path);

/// Compiles both stages and links them. An Error names the file of the stage that failed (both
/// for a link error) and carries the driver's log, then `note` (what was being built).
Result<Program> linkProgram(const StageSource& vertex, const StageSource& fragment,
                            const std::string& note = "");

/// findShaderFolder(vertexFile), then reads, compiles and links `vertexFile` + `fragmentFile`.
Result<Program> loadProgram(const std::string& vertexFile, const std::string& fragmentFile);

/// The twin's shader texts, read once.
struct ShaderSources {
    std::string folder;    ///< where they were found
    StageSource vertex;    ///< twin.vert
    StageSource fragment;  ///< twin.frag
    std::string lighting;  ///< twin_lighting.glsl: spec §6, shared by both stages
};

/// Reads twin.vert, twin.frag and twin_lighting.glsl from findShaderFolder("twin.vert").
Result<ShaderSources> loadShaderSources();

/// Compiles and links one twin variant: `defines` ("#define NAME value" lines) go after each
/// stage's #version line, the lighting functions after them. The Error carries the driver's
/// log and the defines, so a broken variant names itself.
Result<Program> buildProgram(const ShaderSources& sources, const std::string& defines);

}  // namespace facet::gl
