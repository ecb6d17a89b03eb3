#pragma once
// Finding the files the viewer ships with (the default scene, the GLSL shaders): the source
// tree's folder compiled in, then beside the executable, then the current folder, so a build
// runs from anywhere and a moved build still finds copies placed next to it.

#include <string>

namespace facet::view {

/// The first existing `relative` under: `compiledDir`, the executable's folder and its parents
/// (up to three levels), the current folder. Empty when none exists.
std::string findResource(const std::string& relative, const std::string& compiledDir);

/// assets/default.scene (the source tree's assets folder is compiled in).
std::string defaultScenePath();

/// The folder holding frame.vert and frame.frag.
std::string shaderDir();

}  // namespace facet::view
