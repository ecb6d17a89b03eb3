#pragma once
// Finding the files the viewer ships with (the default scene): the source tree's folder
// compiled in, then beside the executable, then the current folder, so a build runs from
// anywhere and a moved build still finds copies placed next to it. The GLSL shaders are found
// by facet::gl (gl_program.hpp), for the viewer and the OpenGL twin alike.

#include <string>

namespace facet::view {

/// The first existing `relative` under: `compiledDir`, the executable's folder and its parents
/// (up to three levels), the current folder. Empty when none exists.
std::string findResource(const std::string& relative, const std::string& compiledDir);

/// assets/default.scene (the source tree's assets folder is compiled in).
std::string defaultScenePath();

}  // namespace facet::view
