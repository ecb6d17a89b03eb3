#pragma once
// The fast path: scene -> clip space -> near/guard-band clipping -> fixed-point rasterization ->
// shading into a Framebuffer. Variants are template specialisations picked once per draw.
// Drawing clip-space geometry directly, coverage counts and the per-sample buffer are the
// advanced API (facet/advanced/draw.hpp).

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/camera.hpp"  // checkFrame, resolveNearPlane
#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet {

struct DebugMap;
namespace detail {
struct RendererAccess;
}

/// What a draw did, for --stats, the viewer and tests.
struct RenderStats {
    std::size_t trianglesIn = 0;          ///< triangles submitted
    std::size_t trianglesCulled = 0;      ///< back faces dropped (culling on)
    std::size_t trianglesClipped = 0;     ///< triangles that crossed the near plane or guard band
    std::size_t trianglesRasterized = 0;  ///< triangles that reached the rasterizer
    std::size_t linesDrawn = 0;           ///< segments drawn in wireframe mode
    std::size_t pointsDrawn = 0;          ///< vertex squares drawn
    std::size_t normalsDrawn = 0;         ///< normal segments drawn (showNormals)
    std::size_t fragments = 0;            ///< pixels that passed coverage (before the depth test)
    /// Triangle parts (a triangle in one 64×64 tile) rejected by hierarchical depth, wholly
    /// behind what the tile holds; their pixels are not visited, so not in `fragments`.
    std::size_t hiZTriangles = 0;
    float depthNear = 0.0f;       ///< smallest depth left in the frame (depth shader)
    float depthFar = 0.0f;        ///< largest depth left in the frame (depth shader)
    std::size_t vertexBytes = 0;  ///< bytes per vertex the draw read or derived (clip included)
    int varyings = 0;             ///< floats interpolated per fragment, depth (1/w) included
    /// Wall-clock time of render()'s stages, in ms (clocked per draw, never per pixel):
    /// clear, vertex work (transform, normals, Gouraud), rasterize + shade, and the passes after
    /// (normals display, legend).
    double clearMs = 0.0, vertexMs = 0.0, rasterMs = 0.0, postMs = 0.0;
    /// Parts of rasterMs for `facet bench`'s per-triangle costs, in ms summed over threads:
    /// the front end (reject, clip, snap, cull, set-up) and binning (records into tiles).
    double frontEndMs = 0.0, binningMs = 0.0;
    std::string_view varyingNames;  ///< what they are, e.g. "depth rgb uv" (static storage)
};

/// Renders frames; keeps scratch buffers so a steady frame size allocates nothing per frame.
class Renderer {
  public:
    Renderer();
    ~Renderer();
    Renderer(Renderer&&) noexcept;
    Renderer& operator=(Renderer&&) noexcept;

    /// Clears `frame` (resized to the camera's image) and renders the scene into it; with a
    /// debug view (settings.view), the view's heat map and legend (debug_view.hpp). An error
    /// (checkFrame's) and `frame` untouched when the camera or the frame's size is refused.
    Result<RenderStats> render(const Scene& scene, const RenderSettings& settings,
                               Framebuffer& frame);

    /// Renders the frame settings.view looks at (the settings of debugViewBase: solid, one
    /// sample) into `frame` and measures the view into `map` with an instrumented draw of it.
    /// Refuses what render() refuses.
    Result<RenderStats> renderDebugView(const Scene& scene, const RenderSettings& settings,
                                        Framebuffer& frame, DebugMap& map);

  private:
    friend struct detail::RendererAccess;  // the advanced API (facet/advanced/draw.hpp)
    struct Impl;  // the scratch buffers and caches kept between frames (pipeline/renderer.cpp)
    std::unique_ptr<Impl> impl_;
};

}  // namespace facet
