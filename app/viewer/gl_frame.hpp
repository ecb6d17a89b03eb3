#pragma once
// The OpenGL side of showing a frame (the engine's, the twin's, or both composed): one RGBA8
// texture (GL_NEAREST, texel for texel at 1:1), the program from shaders/frame.vert +
// frame.frag (built by facet::gl's shared shader code), and the empty VAO that the core profile
// requires for the attribute-less fullscreen triangle. Needs a current GL 3.3 context.

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "gl_objects.hpp"
#include "layout.hpp"

namespace facet::view {

/// Texture, program and VAO for drawing the frame; the handles delete them with the GlFrame
/// (the context must still be current then).
class GlFrame {
  public:
    /// Builds frame.vert + frame.frag; the Error names the shader file and holds the GLSL log.
    Status init();

    /// Copies the frame into the texture: glTexSubImage2D (RGBA, unsigned byte), or a new
    /// texture image when the size changed.
    void upload(const Framebuffer& frame);

    /// Clears the window (bars) and draws the texture into `view` (window pixels, top-left
    /// origin) of a framebuffer `windowHeight` pixels tall. It sets every piece of GL state it
    /// relies on, so whatever ImGui or the OpenGL twin left bound does not matter.
    void draw(const Rect& view, int windowWidth, int windowHeight) const;

  private:
    gl::Program program_;
    gl::VertexArray vao_;
    gl::TextureName texture_;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace facet::view
