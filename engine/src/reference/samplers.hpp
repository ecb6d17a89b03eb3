#pragma once
// The reference samplers: double precision, written straight from spec §7 without any of
// the fast samplers' shortcuts. The reference renderer uses them; tests hold the fast ones to
// them.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "facet/texture.hpp"

// Call them qualified (reference::sampleBilinear): argument-dependent lookup also finds the fast
// samplers, and GLM converts vec2 to dvec2 implicitly.
namespace facet::reference {

/// t − ⌊t⌋; non-finite t gives 0.
double wrapCoord(double t);

/// Texel (x, y) of a level as RGB in [0, 1].
glm::dvec3 texelColor(const MipLevel& level, int x, int y);

/// Nearest filtering on level 0.
glm::dvec3 sampleNearest(const Texture& tex, glm::dvec2 uv);

/// Bilinear filtering on one level (clamped to the chain).
glm::dvec3 sampleBilinear(const Texture& tex, glm::dvec2 uv, int level = 0);

/// Level of detail from the screen-space derivatives of (u, v), clamped to the chain.
double mipLevel(const Texture& tex, glm::dvec2 duvDx, glm::dvec2 duvDy);

/// Trilinear filtering at level of detail λ.
glm::dvec3 sampleTrilinear(const Texture& tex, glm::dvec2 uv, double lod);

}  // namespace facet::reference
