#pragma once
// The reference path: a deliberately simple renderer in double precision that follows the
// conventions literally (no fixed point, no tiling, no cleverness). It is the oracle the fast
// path is tested against and the executable specification of what a correct image is.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet::reference {

/// A rendered image in double precision, plus where a correct fast path may differ from it.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<glm::dvec3> color;  ///< RGB in [0,1], row 0 at the top
    std::vector<double> depth;      ///< camera-space depth, +inf where nothing drew
    /// 1 where the outcome hinges on rounding: a pixel centre within 1/256 px of a triangle edge,
    /// a depth test decided by a relative margin under 1e-5, or a line/point endpoint within
    /// 1/256 px of a pixel border. Elsewhere a correct fast path must agree exactly.
    std::vector<std::uint8_t> ambiguous;

    /// 8-bit RGBA with the conventions' rounding (clamp, round to nearest), packed like
    /// Framebuffer::color.
    std::vector<std::uint32_t> toRgba() const;
};

/// Geometry in the same homogeneous clip space as the fast path, in double.
struct Input {
    std::span<const glm::dvec4> clip;
    std::span<const glm::dvec3> colors;  ///< empty for white
    std::span<const std::uint32_t> indices;
    double nearPlane = 1e-3;
};

/// Clip-space positions of the scene's mesh, computed directly from conventions §4 in double.
std::vector<glm::dvec4> projectScene(const Scene& scene);

/// Renders the scene at the camera's size with the given settings.
Image render(const Scene& scene, const RenderSettings& settings);

/// Draws clip-space geometry onto a background-filled image of the given size.
Image draw(const Input& input, const RenderSettings& settings, int width, int height);

}  // namespace facet::reference
