#include "gl_frame.hpp"

#include <epoxy/gl.h>

#include <cstddef>
#include <utility>

#include "gl_program.hpp"

namespace facet::view {
namespace {

/// A new texture that shows texels as they are: GL_NEAREST, clamped, one level.
gl::TextureName makeFrameTexture() {
    gl::TextureName texture = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, texture.get());
    // Nearest: at 1:1 each texel is one pixel, and a scaled frame shows its real pixels.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    return texture;
}

/// Sets the clear colour to packed R, G, B bytes (opaque): each byte comes back exactly.
void clearColor(std::uint32_t rgba) {
    const auto channel = [rgba](int shift) {
        return static_cast<float>((rgba >> shift) & 0xFFu) / 255.0f;
    };
    glClearColor(channel(0), channel(8), channel(16), 1.0f);
}

/// Writes `frame` into `out` with each pixel's bytes R, G, B, A reordered to B, G, R, A and its
/// alpha made opaque (as the triangle's shader does): the window's pixel format.
void stageBgra(const Framebuffer& frame, std::vector<std::uint32_t>& out) {
    out.resize(frame.color.size());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const std::uint32_t p = frame.color[i];  // R | G << 8 | B << 16 | A << 24
        out[i] = ((p & 0xFFu) << 16) | (p & 0xFF00u) | ((p >> 16) & 0xFFu) | 0xFF000000u;
    }
}

}  // namespace

Status GlFrame::init() {
    Result<gl::Program> program = gl::loadProgram("frame.vert", "frame.frag");
    if (!program) return program.error();
    program_ = std::move(program).value();
    glUseProgram(program_.get());
    glUniform1i(glGetUniformLocation(program_.get(), "frame"), 0);
    glUseProgram(0);

    // Core profile: drawing needs a bound VAO even with no attributes at all.
    vao_ = gl::makeVertexArray();
    scaled_.name = makeFrameTexture();
    copied_.name = makeFrameTexture();
    readFbo_ = gl::makeFramebuffer();
    return {};
}

void GlFrame::upload(const Framebuffer& frame, const Rect& view) {
    if (frame.width <= 0 || frame.height <= 0 || scaled_.name.get() == 0) return;
    blit_ = view.w == frame.width && view.h == frame.height;
    Texture& t = blit_ ? copied_ : scaled_;
    // Packed RGBA8 with R in the low byte is the byte order R, G, B, A: GL_RGBA as it is for
    // the triangle. For the blit, an unsized GL_RGBA texture takes the format of its data:
    // llvmpipe then stores B, G, R, A bytes like the window, the upload is a memcpy and the blit
    // a row copy. (A sized GL_RGBA8 stays R, G, B, A whatever the data: the upload would
    // swizzle and the blit run a shader on every pixel, 15 ms instead of 0.7 at 1280x720.)
    const GLint internalFormat = blit_ ? GL_RGBA : GL_RGBA8;
    const GLenum format = blit_ ? GL_BGRA : GL_RGBA;
    const void* pixels = frame.color.data();
    if (blit_) {
        stageBgra(frame, staged_);
        pixels = staged_.data();
    }
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, t.name.get());
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);  // from client memory, whoever bound a buffer
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    if (frame.width != t.width || frame.height != t.height) {
        t.width = frame.width;
        t.height = frame.height;
        glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, t.width, t.height, 0, format,
                     GL_UNSIGNED_BYTE, pixels);
        if (blit_) {
            glBindFramebuffer(GL_READ_FRAMEBUFFER, readFbo_.get());
            glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                   copied_.name.get(), 0);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        }
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, t.width, t.height, format, GL_UNSIGNED_BYTE,
                        pixels);
    }
}

void GlFrame::draw(const Rect& view, const Backdrop& backdrop, int windowWidth,
                   int windowHeight) const {
    // The window's own framebuffer, every pixel written as the shader computes it.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glViewport(0, 0, windowWidth, windowHeight);
    const Texture& t = blit_ ? copied_ : scaled_;
    const bool shown = t.width > 0 && view.w > 0 && view.h > 0 && program_.get() != 0;
    const Rect& back = backdrop.rect;
    const bool hasBackdrop = back.w > 0 && back.h > 0;
    // The usual window: the side bar at the left and the frame filling the rest. One clear in
    // the side bar's colour then does for both (the frame covers its share).
    const bool backdropIsTheRest = shown && hasBackdrop && back.x == 0 && back.y == 0 &&
                                   back.h == windowHeight && view.x == back.w && view.y == 0 &&
                                   view.h == windowHeight && view.x + view.w == windowWidth;
    const bool fills =
        shown && view.x <= 0 && view.y <= 0 && view.w >= windowWidth && view.h >= windowHeight;
    if (backdropIsTheRest) {
        clearColor(backdrop.rgba);
        glClear(GL_COLOR_BUFFER_BIT);
    } else if (!fills) {  // bars around a letterboxed frame
        glClearColor(0.08f, 0.08f, 0.08f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    if (shown) drawFrame(view, windowWidth, windowHeight);
    if (hasBackdrop && !backdropIsTheRest) {
        // After the frame, as ImGui's own background would have been drawn.
        glEnable(GL_SCISSOR_TEST);
        glScissor(back.x, windowHeight - back.y - back.h, back.w, back.h);
        clearColor(backdrop.rgba);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
    }
}

void GlFrame::drawFrame(const Rect& view, int windowWidth, int windowHeight) const {
    const Texture& t = blit_ ? copied_ : scaled_;
    // GL's window origin is the bottom left; `view` counts from the top.
    const int bottom = windowHeight - view.y - view.h;
    if (blit_ && view.w == t.width && view.h == t.height) {
        // Same size, same pixel format, no scissor, and flipped: row 0 of the texture (the
        // frame's top) goes to the view's top. Mesa keeps a window top row first in memory and
        // a texture row 0 first, so this flip is what makes the blit a plain row copy.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, readFbo_.get());
        glBlitFramebuffer(0, 0, t.width, t.height, view.x, bottom + t.height, view.x + t.width,
                          bottom, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        return;
    }
    glViewport(view.x, bottom, view.w, view.h);
    glUseProgram(program_.get());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, scaled_.name.get());
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glViewport(0, 0, windowWidth, windowHeight);
}

}  // namespace facet::view
