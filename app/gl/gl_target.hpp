#pragma once
// The twin's offscreen frame (an FBO with RGBA8 colour and 32-bit float depth) and its readback
// into the engine's Framebuffer layout, so the two renderers' frames compare and display alike.

#include <vector>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"
#include "gl_objects.hpp"

namespace facet::gl {

/// An FBO sized like the image. Window row y holds image row y (twin.vert maps them so), so
/// the first row read back is the image's top row, as Framebuffer wants.
class RenderTarget {
  public:
    /// (Re)allocates the attachments when the size changed; an Error when the driver's size
    /// limit is lower or the FBO is incomplete.
    Status resize(int width, int height);

    /// Binds the FBO for drawing and reading, with a viewport covering it.
    void bind() const;

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
    int width_ = 0;
    int height_ = 0;
};

}  // namespace facet::gl
