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

/// Reads a .scene file and loads its mesh and texture (line 10, or else the OBJ's map_Kd); on
/// failure nothing is returned but the error, which names the file and line at fault.
Result<Scene> loadScene(const std::string& path);

/// Replaces the scene's texture with the image at `path` (the CLI's --texture, the viewer's
/// texture field). On failure the scene is left exactly as it was.
Status loadSceneTexture(Scene& scene, const std::string& path);

}  // namespace facet
