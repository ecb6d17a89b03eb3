#pragma once
// The .scene format (spec §1): ten line-oriented fields, the last optional; a bare mesh
// opened as a scene (§3b); and the writer that saves a scene back to that format.

#include <optional>
#include <string>
#include <string_view>

#include <glm/vec3.hpp>

#include "facet/error.hpp"
#include "facet/load_control.hpp"
#include "facet/scene.hpp"

namespace facet {

/// Parses scene text without loading the mesh; `fileName` labels errors and anchors relative
/// paths (Scene::meshPath and texturePath hold the paths as written, resolved later).
Result<Scene> parseScene(std::string_view text, const std::string& fileName);

/// Resolves a path named in a scene file: next to the scene, then the current folder, then the
/// bare file name next to the scene. Returns the first that exists, or an empty string.
std::string resolveScenePath(const std::string& sceneFile, const std::string& named);

/// Reads a .scene file and loads its mesh and texture (line 10, or else the OBJ's map_Kd); on
/// failure nothing is returned but the error, which names the file and line at fault. The
/// optional `control` gets the progress and may cancel (then Error::cancelled is set).
Result<Scene> loadScene(const std::string& path, const LoadControl* control = nullptr);

/// Replaces the scene's texture with the image at `path` (the CLI's --texture, the viewer's
/// texture field). On failure the scene is left exactly as it was.
Status loadSceneTexture(Scene& scene, const std::string& path,
                        const LoadControl* control = nullptr);

/// What a file holds, as far as opening it goes.
enum class FileKind { unknown, scene, mesh, image };

/// Decides what `path` holds from its first bytes (image signatures, an OFF header, OBJ
/// statements, a first line naming a .off/.obj file), else from its extension; unknown when
/// neither tells (also for a file that cannot be read).
FileKind fileKind(const std::string& path);

/// Image size a bare mesh gets when none is given (spec §3b).
inline constexpr int kBareMeshWidth = 1280;
inline constexpr int kBareMeshHeight = 720;

/// The world axis a bare mesh stands on (spec §3b): +Y by default, +Z for models made
/// Z-up (scans, CAD), +X for the rest.
enum class UpAxis { X, Y, Z };

/// Parses "x", "y" or "z" (either case); nullopt otherwise.
std::optional<UpAxis> parseUpAxis(std::string_view name);

/// "x", "y" or "z".
std::string_view toString(UpAxis axis);

/// The world direction `axis` names, a unit vector.
glm::dvec3 upVector(UpAxis axis);

/// The scene spec §3b gives a bare mesh at `width` × `height`: a three-quarter view of its
/// bounding sphere with `up` up on screen (the camera's y hint is its opposite, as the course's
/// (0, −1, 0) is for +Y), a point light near the camera, a neutral material. Scene::path and
/// meshPath are `meshPath`; no texture is loaded.
Scene sceneForMesh(Mesh mesh, const std::string& meshPath, int width, int height,
                   UpAxis up = UpAxis::Y);

/// How a bare mesh is framed when opened: image size and up axis (a .scene ignores these).
struct OpenOptions {
    int width = kBareMeshWidth;    ///< image width of a bare mesh's scene
    int height = kBareMeshHeight;  ///< image height of a bare mesh's scene
    UpAxis up = UpAxis::Y;         ///< the world axis shown up on screen

    /// Every field equal.
    bool operator==(const OpenOptions&) const = default;
};

/// Opens a .scene file, or a bare .off/.obj mesh as sceneForMesh() at `width` × `height` (with
/// its OBJ map_Kd texture). Anything else is an error saying what was expected. The optional
/// `control` gets the progress and may cancel (then Error::cancelled is set).
Result<Scene> openSceneFile(const std::string& path, int width = kBareMeshWidth,
                            int height = kBareMeshHeight, const LoadControl* control = nullptr);

/// The same with a bare mesh framed by `options` (size and up axis).
Result<Scene> openSceneFile(const std::string& path, const OpenOptions& options,
                            const LoadControl* control = nullptr);

/// The .scene text (spec §1) of `scene`: mesh and texture paths relative to the folder
/// of `sceneFile`, numbers in shortest round-trip form, so loading it gives the same scene.
Result<std::string> sceneText(const Scene& scene, const std::string& sceneFile);

/// Writes sceneText() to `sceneFile`.
Status writeScene(const Scene& scene, const std::string& sceneFile);

}  // namespace facet
