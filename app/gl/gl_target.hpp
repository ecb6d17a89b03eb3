#pragma once
// The twin's offscreen frame (an FBO with RGBA8 colour and 32-bit float depth) and its readback
// into the engine's Framebuffer layout, so the two renderers' frames compare and display alike.
// With multisampling, drawing goes to a second, multisampled FBO that resolve() blits into the
// first (GL's box-filter resolve of the colour samples).

#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "gl_objects.hpp"

namespace facet::gl {

/// An FBO sized like the image. Window row y holds image row y (twin.vert maps them so), so
/// the first row read back is the image's top row, as Framebuffer wants.
class RenderTarget {
  public:
    /// (Re)allocates the attachments when the size or sample count changed (`samples` > 1:
    /// with the multisampled FBO); an Error when the driver's size or sample limit is lower or
    /// an FBO is incomplete.
    Status resize(int width, int height, int samples = 1);

    /// Binds the FBO to draw into (the multisampled one when there is one), with a viewport
    /// covering it.
    void bind() const;

    /// Multisampled: blits colour and depth into the single-sample FBO that readColor() and
    /// readDepth() read (colour averaged per pixel; depth, which GL cannot average, one of the
    /// samples). Nothing otherwise.
    void resolve() const;

    /// Colour into frame.color (frame must be width × height): packed RGBA8, R in the low
    /// byte, which is GL_RGBA/GL_UNSIGNED_BYTE on a little-endian machine.
    void readColor(Framebuffer& frame) const;

    /// Depth into `depth` (resized), as camera-space Z: the buffer stores nearPlane / Z
    /// (twin.vert), so Z = nearPlane / stored, and a stored 0 (the clear value) is +inf.
    void readDepth(std::vector<float>& depth, float nearPlane) const;

  private:
    FramebufferName fbo_;
    Renderbuffer color_;
    Renderbuffer depth_;
    FramebufferName msFbo_;  // the multisampled FBO, when samples_ > 1
    Renderbuffer msColor_;
    Renderbuffer msDepth_;
    int width_ = 0;
    int height_ = 0;
    int samples_ = 1;
};

}  // namespace facet::gl
