#pragma once
// Advanced, unstable API (docs/library.md, "Stable and advanced API"): not covered by the
// version's compatibility promise; it follows the fast path's internals and may change in any
// release.
//
// The fast path's float form of spec §6's lighting (facet/lighting.hpp has the formula and the
// double version the reference uses): the parameters folded once per frame into the constants the
// per-vertex (Gouraud) and per-pixel (Phong) shading read. The OpenGL twin feeds the same
// constants to its shaders so that both light alike.

#include <glm/vec4.hpp>

#include "facet/lighting.hpp"
#include "facet/scene.hpp"

namespace facet {

/// LightingParams folded into the float constants the fast path needs; rebuild it every frame
/// (it costs a few multiplications) so edits to the parameters show at once.
struct FastLighting {
    /// The light's homogeneous position scaled to the same point or direction with w ≥ 0 and
    /// largest |component| 1, so xyz − w·p is a finite vector towards the light even for a point
    /// beyond float range (tiny w).
    glm::vec4 light{0.0f, 0.0f, 1.0f, 0.0f};
    float ambientTerm = 0.0f;  ///< Ia·Ka
    float diffuse = 0.0f;      ///< Id·Kd
    float specular = 0.0f;     ///< Id·Ks
    float shininess = 1.0f;    ///< s
};

/// Folds the parameters for the float path.
FastLighting prepareLighting(const LightingParams& params);

}  // namespace facet
