#pragma once
// Advanced, unstable API (docs/library.md, "Stable and advanced API"): not covered by the
// version's compatibility promise; it follows the fast path's internals and may change in any
// release.
//
// The fast path below Renderer::render: geometry already in clip space drawn into a frame, the
// fill rule's coverage counted per pixel or sample, and the per-sample buffer of a multisampled
// draw. The accuracy sweeps place triangles at exact sub-pixel positions through it, and the
// engine's tests reach the rasterizer's rules through it without a scene.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/advanced/fast_lighting.hpp"
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/settings.hpp"

namespace facet {

class Texture;

/// Geometry already in clip space (see camera.hpp), as one draw consumes it. Only the streams
/// the settings need are read: colours for every shader but Depth (and Texture without
/// combine), uvs for Texture, normals and positions for Phong lighting.
struct DrawInput {
    std::span<const glm::vec4> clip;         ///< one per vertex
    std::span<const glm::vec3> colors;       ///< one per vertex (lit for Gouraud), or empty: white
    std::span<const glm::vec2> uvs;          ///< one per vertex, or empty: (0, 0)
    std::span<const glm::vec3> normals;      ///< world-space unit (or zero) normals, Phong
    std::span<const glm::vec3> positions;    ///< world-space positions, Phong
    std::span<const std::uint32_t> indices;  ///< three per triangle
    float nearPlane = 1e-3f;                 ///< clip.w below this is cut away
    const Texture* texture = nullptr;        ///< Texture shader; null samples as white
    FastLighting lighting;                   ///< Phong: the folded §6 parameters
    glm::vec3 eye{0.0f};                     ///< Phong: camera centre in world space
};

/// Draws clip-space geometry into `frame` with `renderer`'s scratch buffers, without clearing
/// it. With the Depth shader the depth-to-colour pass runs over the whole frame afterwards. An
/// error when the frame's size is outside the limits or its planes are not that size.
Result<RenderStats> draw(Renderer& renderer, const DrawInput& input, const RenderSettings& settings,
                         Framebuffer& frame);

/// Counts, per pixel, how many triangles cover its centre (fill-rule tests, overdraw views);
/// with settings.msaa > 1, per sample, in the per-sample buffer's layout (sampleBuffer()).
/// `counts` is resized to width*height*samples and zeroed first. Honours culling and clipping.
/// An error, `counts` untouched, when the size is outside the limits.
Status countCoverage(Renderer& renderer, const DrawInput& input, const RenderSettings& settings,
                     int width, int height, std::vector<std::uint16_t>& counts);

/// The per-sample buffer of `renderer`'s last multisampled draw, before the resolve: sample k
/// of pixel (x, y) at (x·b.x + k mod b.x, y·b.y + k div b.x), b = sampleBlock(msaa)
/// (facet/multisample.hpp); colours already mapped for the Depth shader. Empty before one.
const Framebuffer& sampleBuffer(const Renderer& renderer);

}  // namespace facet
