#pragma once
// The OpenGL side of showing a frame (the engine's, the twin's, or both composed). Shown at its
// own size (the usual case), the frame is copied into the window with glBlitFramebuffer from a
// texture in the window's own pixel format (B, G, R, A bytes), which Mesa's llvmpipe turns into
// a row-by-row memcpy: drawing it as a textured triangle instead runs a fragment shader on every
// pixel (8 ms a frame at 1280x720 on a quiet 2-core machine, 0.7 ms for the copy). Scaled
// (letterboxed), it is drawn as that triangle from an RGBA8 texture (GL_NEAREST) with the
// program from shaders/frame.vert + frame.frag (built by facet::gl's shared shader code) and the
// empty VAO that the core profile requires for an attribute-less triangle: llvmpipe's fast
// path for sampling B, G, R, A textures swaps red and blue in some 64-pixel tiles (Mesa 22.3),
// so scaled frames never use the blit's texture. Needs a current GL 3.3 context.

#include <cstdint>
#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "gl_objects.hpp"
#include "layout.hpp"

namespace facet::view {

/// Textures, read framebuffer, program and VAO for showing the frame; the handles delete them
/// with the GlFrame (the context must still be current then).
class GlFrame {
  public:
    /// Builds frame.vert + frame.frag; the Error names the shader file and holds the GLSL log.
    Status init();

    /// Copies the frame into the texture that showing it in `view` (window pixels) uses: the
    /// blit's (reordered to B, G, R, A on the CPU, alpha opaque) when `view` is the frame's
    /// size, the triangle's (RGBA as it is) otherwise. A new texture image when the size
    /// changed, glTexSubImage2D otherwise.
    void upload(const Framebuffer& frame, const Rect& view);

    /// Clears the window (bars), shows the last upload in `view` (window pixels, top-left
    /// origin) of a framebuffer `windowWidth` × `windowHeight`, as upload() chose for that view,
    /// and fills `backdrop`. It sets every piece of GL state it relies on, so whatever ImGui or
    /// the OpenGL twin left bound does not matter.
    void draw(const Rect& view, const Backdrop& backdrop, int windowWidth, int windowHeight) const;

  private:
    /// The frame alone, into a non-empty `view`: the blit or the triangle.
    void drawFrame(const Rect& view, int windowWidth, int windowHeight) const;

    /// A texture and the size of its image (0 × 0: none yet).
    struct Texture {
        gl::TextureName name;
        int width = 0;
        int height = 0;
    };

    gl::Program program_;
    gl::VertexArray vao_;
    Texture scaled_;                     // RGBA8, sampled by the triangle
    Texture copied_;                     // B, G, R, A bytes, the blit's source
    gl::FramebufferName readFbo_;        // copied_ as a read framebuffer
    std::vector<std::uint32_t> staged_;  // the frame reordered for copied_, reused
    bool blit_ = false;                  // the last upload went to copied_
};

}  // namespace facet::view
