#pragma once
// The OpenGL side of showing a CPU frame: one RGBA8 texture (GL_NEAREST, texel for texel at 1:1),
// the shader program from shaders/frame.vert + frame.frag, and the empty VAO that the core
// profile requires for the attribute-less fullscreen triangle. Needs a current GL 3.3 context.

#include <string>

#include "facet/framebuffer.hpp"
#include "layout.hpp"

namespace facet::view {

/// Texture, program and VAO for drawing the frame; GL names kept as plain unsigned so this
/// header does not pull in the GL headers.
class GlFrame {
  public:
    GlFrame() = default;
    GlFrame(const GlFrame&) = delete;
    GlFrame& operator=(const GlFrame&) = delete;
    /// Releases the GL objects (the context must still be current).
    ~GlFrame();

    /// Compiles and links the shaders found in `shaderDir`; false with `error` set on failure.
    bool init(const std::string& shaderDir, std::string& error);

    /// Copies the frame into the texture: glTexSubImage2D (RGBA, unsigned byte), or a new
    /// texture image when the size changed.
    void upload(const Framebuffer& frame);

    /// Clears the window (bars) and draws the texture into `view` (window pixels, top-left
    /// origin) of a framebuffer `windowHeight` pixels tall.
    void draw(const Rect& view, int windowWidth, int windowHeight) const;

  private:
    unsigned program_ = 0;
    unsigned vao_ = 0;
    unsigned texture_ = 0;
    int width_ = 0;
    int height_ = 0;
};

}  // namespace facet::view
