#pragma once
// The GL state the twin changes, saved and put back, so the renderer can share a context with
// a window (the viewer draws its own frame and ImGui in it) without either seeing the other's
// settings.

#include <epoxy/gl.h>

namespace facet::gl {

/// Saves the state the twin touches on construction and restores it on destruction; then sets
/// the twin's baseline (no blending, scissor, stencil, dithering or sRGB; fill; full masks;
/// GL's default pixel packing and unpacking).
class StateGuard {
  public:
    /// Saves; `clipControl`: whether glClipControl exists (its state is saved only then).
    explicit StateGuard(bool clipControl);
    StateGuard(const StateGuard&) = delete;
    StateGuard& operator=(const StateGuard&) = delete;
    /// Restores everything saved.
    ~StateGuard();

  private:
    static constexpr GLenum kCaps[] = {
        GL_DEPTH_TEST,        GL_CULL_FACE,           GL_BLEND,
        GL_SCISSOR_TEST,      GL_STENCIL_TEST,        GL_DITHER,
        GL_FRAMEBUFFER_SRGB,  GL_POLYGON_OFFSET_FILL, GL_RASTERIZER_DISCARD,
        GL_PROGRAM_POINT_SIZE};
    static constexpr int kCapCount = sizeof(kCaps) / sizeof(kCaps[0]);

    bool clipControl_;
    GLboolean enabled_[kCapCount] = {};
    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0;
    GLint viewport_[4] = {};
    GLint clipOrigin_ = GL_LOWER_LEFT, clipDepth_ = GL_NEGATIVE_ONE_TO_ONE;
    GLint program_ = 0, vertexArray_ = 0, activeTexture_ = GL_TEXTURE0, texture0_ = 0;
    GLint arrayBuffer_ = 0, packBuffer_ = 0, unpackBuffer_ = 0;
    GLint depthFunc_ = GL_LESS, frontFace_ = GL_CCW, cullFace_ = GL_BACK;
    GLint polygonMode_[2] = {GL_FILL, GL_FILL};
    GLboolean depthMask_ = GL_TRUE, colorMask_[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    GLfloat clearColor_[4] = {}, clearDepth_ = 1.0f, lineWidth_ = 1.0f, pointSize_ = 1.0f;
    // How pixels travel to textures and back from the FBO: GL's defaults while the twin runs.
    static constexpr GLenum kPixelStore[] = {
        GL_UNPACK_ALIGNMENT, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS,
        GL_PACK_ALIGNMENT,   GL_PACK_ROW_LENGTH,   GL_PACK_SKIP_ROWS,   GL_PACK_SKIP_PIXELS};
    static constexpr int kPixelStoreCount = sizeof(kPixelStore) / sizeof(kPixelStore[0]);
    GLint pixelStore_[kPixelStoreCount] = {};
};

}  // namespace facet::gl
