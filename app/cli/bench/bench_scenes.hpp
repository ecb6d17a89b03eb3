#pragma once
// Scenes the benchmark builds in memory: the geometry-bound sphere, the fill-bound stack of
// full-screen quads, a procedural texture, and what makes a file scene drawable by every config
// (uvs and a texture where it has none).

#include <memory>
#include <string>

#include "facet/error.hpp"
#include "facet/scene.hpp"
#include "facet/texture.hpp"

namespace facet::app {

/// A 512×512 checkerboard with a colour gradient, shared by every generated textured case.
std::shared_ptr<const Texture> checkerTexture();

/// A UV sphere of about `triangles` triangles (4·r² for r rings, 2r sectors; the exact count is
/// the mesh's), filling 90 % of the image height at any size, lit from the upper left.
Scene sphereScene(int triangles, int width, int height);

/// `layers` full-screen quads (two triangles each, overhanging the image by 5 %) stacked along
/// the view axis and listed back to front, so every layer passes the depth test and is shaded:
/// the worst case for fill. Each carries uvs (tiled 4× across, shifted per layer) and a tint.
Scene overdrawScene(int layers, int width, int height);

/// Loads a .scene file and sets its size (0 keeps the file's), scaling the focal length with the
/// width as `facet render --size` does.
Result<Scene> fileScene(const std::string& path, int width, int height);

/// Makes every config drawable: a mesh without uvs gets planar ones (the bounding box's two
/// largest axes, tiled 4×), a scene without a texture gets `fallbackTexture` or the checker.
/// Returns what was added, e.g. "planar uvs, checker texture (generated)", or "".
std::string completeForTexturing(Scene& scene, const std::string& fallbackTexture = "");

}  // namespace facet::app
