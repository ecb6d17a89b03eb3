#include "gl_frame.hpp"

#include <epoxy/gl.h>

#include <utility>

#include "gl_program.hpp"

namespace facet::view {

Status GlFrame::init() {
    Result<gl::Program> program = gl::loadProgram("frame.vert", "frame.frag");
    if (!program) return program.error();
    program_ = std::move(program).value();
    glUseProgram(program_.get());
    glUniform1i(glGetUniformLocation(program_.get(), "frame"), 0);
    glUseProgram(0);

    // Core profile: drawing needs a bound VAO even with no attributes at all.
    vao_ = gl::makeVertexArray();
    texture_ = gl::makeTexture();
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    // Nearest: at 1:1 each texel is one pixel, and a scaled frame shows its real pixels.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glBindTexture(GL_TEXTURE_2D, 0);
    return std::nullopt;
}

void GlFrame::upload(const Framebuffer& frame) {
    if (frame.width <= 0 || frame.height <= 0 || texture_.get() == 0) return;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);  // from client memory, whoever bound a buffer
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    // Packed RGBA8 with R in the low byte is the byte order R, G, B, A: GL_RGBA as it is, one
    // plain copy on llvmpipe. (Tried and dropped: handing llvmpipe B, G, R, A texels halves the
    // draw time through its row-copy path, but Mesa 22.3 then swaps red and blue in some
    // 64-pixel tiles and not in others.)
    if (frame.width != width_ || frame.height != height_) {
        width_ = frame.width;
        height_ = frame.height;
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     frame.color.data());
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE,
                        frame.color.data());
    }
}

void GlFrame::draw(const Rect& view, int windowWidth, int windowHeight) const {
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
    const bool fills =
        view.x <= 0 && view.y <= 0 && view.w >= windowWidth && view.h >= windowHeight && width_ > 0;
    if (!fills) {  // bars around a letterboxed frame; a full frame overwrites every pixel anyway
        glClearColor(0.08f, 0.08f, 0.08f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    if (!width_ || view.w <= 0 || view.h <= 0 || program_.get() == 0) return;
    // GL's viewport origin is the bottom left; `view` counts from the top.
    glViewport(view.x, windowHeight - view.y - view.h, view.w, view.h);
    glUseProgram(program_.get());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_.get());
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glViewport(0, 0, windowWidth, windowHeight);
}

}  // namespace facet::view
