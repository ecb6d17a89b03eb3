#include "gl_target.hpp"

#include <string>

namespace facet::gl {

Status RenderTarget::resize(int width, int height) {
    if (fbo_.get() != 0 && width == width_ && height == height_) return std::nullopt;
    GLint limit = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &limit);
    if (width > limit || height > limit)
        return Error{{"OpenGL twin", 0},
                     std::to_string(width) + "x" + std::to_string(height) +
                         " exceeds the driver's largest framebuffer side, " +
                         std::to_string(limit)};
    if (fbo_.get() == 0) {
        fbo_ = makeFramebuffer();
        color_ = makeRenderbuffer();
        depth_ = makeRenderbuffer();
    }
    glBindRenderbuffer(GL_RENDERBUFFER, color_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_.get());
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_.get());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        fbo_.reset();  // so the next call rebuilds it from scratch
        return Error{{"OpenGL twin", 0},
                     "framebuffer incomplete (status " + std::to_string(status) + ")"};
    }
    width_ = width;
    height_ = height;
    return std::nullopt;
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.get());
    glViewport(0, 0, width_, height_);
}

// Tightly packed rows: the StateGuard sets GL's default packing for the twin's frame, whatever
// the caller left (the viewer packs with alignment 1 for its screenshots).
void RenderTarget::readColor(Framebuffer& frame) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, frame.color.data());
}

void RenderTarget::readDepth(std::vector<float>& depth, float nearPlane) const {
    depth.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_.get());
    glReadPixels(0, 0, width_, height_, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    // No branch, so the loop vectorises: the clear value 0 gives nearPlane / 0 = +inf, which
    // is kEmptyDepth.
    for (float& d : depth) d = nearPlane / d;
}

}  // namespace facet::gl
