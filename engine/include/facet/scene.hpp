#pragma once
// The contents of a .scene file (spec §1) plus the mesh it names. Plain data: the viewer
// edits these fields directly between frames.

#include <memory>
#include <string>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/mesh.hpp"

namespace facet {

class Texture;

/// Pinhole camera: pose by look-at, intrinsics by focal length in pixels and image size.
struct Camera {
    glm::dvec3 eye{0.0, 0.0, -5.0};  ///< camera centre in world space
    glm::dvec3 look{0.0, 0.0, 0.0};  ///< point the optical axis passes through
    glm::dvec3 up{0.0, -1.0, 0.0};   ///< y hint: camera +y (image down) leans towards it
    double focal = 512.0;            ///< focal length in pixels
    int width = 512;                 ///< image width in pixels
    int height = 512;                ///< image height in pixels

    /// Every field equal.
    bool operator==(const Camera&) const = default;
};

/// The scene's one light: a point at position.xyz / w, or a direction (w = 0) it comes from.
struct Light {
    glm::dvec4 position{0.0, 0.0, 8.0, 1.0};  ///< homogeneous position
    double intensity = 1.0;                   ///< Id

    /// Every field equal.
    bool operator==(const Light&) const = default;
};

/// Phong material coefficients (spec §6).
struct Material {
    double ka = 0.5;  ///< ambient
    double kd = 0.5;  ///< diffuse
    double ks = 0.5;  ///< specular
    double s = 1.0;   ///< shininess exponent

    /// Every field equal.
    bool operator==(const Material&) const = default;
};

/// Everything §6 needs besides the geometry, as plain fields a UI may change between frames.
struct LightingParams {
    double ambient = 1.0;  ///< Ia
    Light light;           ///< homogeneous position (w = 0: the direction light comes from), Id
    Material material;     ///< Ka, Kd, Ks, s (all ≥ 0)

    /// Every field equal.
    bool operator==(const LightingParams&) const = default;
};

/// Everything one .scene file describes, with its mesh loaded.
struct Scene {
    std::string path;         ///< the .scene file itself
    std::string meshPath;     ///< resolved mesh path
    std::string texturePath;  ///< resolved path of the loaded texture, empty if none
    /// The geometry, shared and immutable: copying a Scene (to a render thread, say) copies a
    /// pointer. Never null (an empty mesh by default, the file's after loading); to change the
    /// geometry, point it at a new Mesh.
    std::shared_ptr<const Mesh> mesh = std::make_shared<const Mesh>();
    /// The scene's texture (line 10, else the OBJ's map_Kd), or null. Shared and immutable, so
    /// copying a Scene is cheap and a UI can swap it without touching the renderer.
    std::shared_ptr<const Texture> texture;
    Camera camera;
    LightingParams lighting;  ///< Ia, the light and the material
};

}  // namespace facet
