#pragma once
// The OpenGL twin of facet::Renderer: the same scene with the same settings drawn by OpenGL
// (Mesa's llvmpipe on a machine without a GPU) and read back into a facet::Framebuffer, as a
// yardstick for speed and an independent check of the pictures. It follows the specification
// where GL lets it: camera and pixel centres, top-left fill rule, LESS depth, the lighting
// formula, repeat wrap, the engine's own mip chain. Where GL decides itself (8-bit texture
// filter weights, the level of detail, the diamond-exit rule of lines) the pictures differ
// within the tolerances tests/app/gl_twin_test.cpp states. Subdivided interpolation is drawn
// perspective-correct.

#include <cstddef>
#include <memory>
#include <string>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"

namespace facet {

/// What a twin frame did, for the CLI, the benchmark and tests.
struct GlStats {
    std::size_t trianglesIn = 0;   ///< triangles submitted (solid mode)
    std::size_t linesDrawn = 0;    ///< edges submitted (wireframe)
    std::size_t pointsDrawn = 0;   ///< vertex squares submitted
    std::size_t normalsDrawn = 0;  ///< normal segments submitted (showNormals)
    float depthNear = 0.0f;        ///< Depth shader: smallest depth in the frame
    float depthFar = 0.0f;         ///< Depth shader: largest depth in the frame
    std::size_t uploadBytes = 0;   ///< vertex, index and texture bytes sent (upload())
    double uploadMs = 0.0;         ///< CPU preparation and uploads (normals, edges, buffers)
    double drawMs = 0.0;           ///< clear and draw calls until glFinish returned (CPU clock)
    double readbackMs = 0.0;       ///< colour and depth readback, depth colours, legend
};

namespace gl {
struct RendererState;
}

/// Renders scenes with OpenGL into a Framebuffer. Every call, including the destructor, needs
/// the context current that was current at create(); GL state it changes is restored.
class GlRenderer {
  public:
    /// Reads the shaders (compiled per variant on first use); needs a current OpenGL 3.3 core
    /// context. 4.5 or ARB_clip_control gives full depth precision.
    static Result<GlRenderer> create();

    GlRenderer(GlRenderer&& other) noexcept;
    GlRenderer& operator=(GlRenderer&& other) noexcept;
    /// Deletes the GL objects (the context must be current).
    ~GlRenderer();

    /// Draws the scene at its camera's size into `frame` (resized), like Renderer::render:
    /// colour with row 0 at the top, depth as camera-space Z with +inf where nothing drew.
    /// upload(), draw() and readBack() in one call, so every frame sends the mesh again.
    /// Errors: a shader variant that does not build, a size beyond the driver's limit.
    Result<GlStats> render(const Scene& scene, const RenderSettings& settings, Framebuffer& frame);

    /// The three steps of render() for an application that keeps a static mesh resident (the
    /// benchmark): upload() once, then draw() per frame, then readBack() when the picture is
    /// wanted. Each adds its counts and its time to `stats`.
    /// upload(): computes the vertex normals the settings need and sends the streams the
    /// variant reads, the indices and the texture, and keeps them for draw().
    Status upload(const Scene& scene, const RenderSettings& settings, GlStats& stats);
    /// Clears and draws what the last upload() sent, up to glFinish; an Error when that upload
    /// was of another mesh, texture or variant than `scene` and `settings` need.
    Status draw(const Scene& scene, const RenderSettings& settings, GlStats& stats);
    /// Reads the last draw()'s colour and depth into `frame` (resized) and, for the Depth
    /// shader, colours it and draws the legend as render() does.
    Status readBack(const Scene& scene, const RenderSettings& settings, Framebuffer& frame,
                    GlStats& stats);

    /// Where the twin's picture departs from the engine's for these settings beyond colour
    /// rounding, one line each, for the viewer to say so; empty when it does not.
    static std::string differences(const RenderSettings& settings);

    /// GL_RENDERER of the context, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    const std::string& device() const;

  private:
    explicit GlRenderer(std::unique_ptr<gl::RendererState> state);
    std::unique_ptr<gl::RendererState> state_;
};

}  // namespace facet
