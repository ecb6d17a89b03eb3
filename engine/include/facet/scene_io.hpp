#pragma once
// The .scene format (conventions §1): ten line-oriented fields, the last optional.

#include <string>
#include <string_view>

#include "facet/error.hpp"
#include "facet/scene.hpp"

namespace facet {

/// Parses scene text without loading the mesh; `fileName` labels errors and anchors relative
/// paths (Scene::meshPath and texturePath hold the paths as written, resolved later).
Result<Scene> parseScene(std::string_view text, const std::string& fileName);

/// Resolves a path named in a scene file: next to the scene, then the current folder, then the
/// bare file name next to the scene. Returns the first that exists, or an empty string.
std::string resolveScenePath(const std::string& sceneFile, const std::string& named);

/// Reads a .scene file and loads its mesh; on failure nothing is returned but the error.
Result<Scene> loadScene(const std::string& path);

}  // namespace facet
