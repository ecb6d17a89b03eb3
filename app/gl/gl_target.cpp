#include "gl_target.hpp"

#include <algorithm>
#include <string>

namespace facet::gl {

Status RenderTarget::resize(int width, int height, int samples) {
    samples = std::max(samples, 1);
    if (fbo_.get() != 0 && width == width_ && height == height_ && samples == samples_) return {};
    GLint limit = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &limit);
    if (width > limit || height > limit)
        return Error{{"OpenGL twin", 0},
                     std::to_string(width) + "x" + std::to_string(height) +
                         " exceeds the driver's largest framebuffer side, " +
                         std::to_string(limit)};
    GLint maxSamples = 1;
    glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
    if (samples > maxSamples)
        return Error{{"OpenGL twin", 0},
                     "MSAA " + std::to_string(samples) + "x exceeds the driver's most samples, " +
                         std::to_string(maxSamples)};
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
    if (samples > 1) {
        if (msFbo_.get() == 0) {
            msFbo_ = makeFramebuffer();
            msColor_ = makeRenderbuffer();
            msDepth_ = makeRenderbuffer();
        }
        glBindRenderbuffer(GL_RENDERBUFFER, msColor_.get());
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
        glBindRenderbuffer(GL_RENDERBUFFER, msDepth_.get());
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT32F, width,
                                         height);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glBindFramebuffer(GL_FRAMEBUFFER, msFbo_.get());
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  msColor_.get());
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  msDepth_.get());
        const GLenum msStatus = glCheckFramebufferStatus(GL_FRAMEBUFFER);
        if (msStatus != GL_FRAMEBUFFER_COMPLETE) {
            fbo_.reset();
            msFbo_.reset();
            return Error{
                {"OpenGL twin", 0},
                "multisampled framebuffer incomplete (status " + std::to_string(msStatus) + ")"};
        }
    } else {
        msFbo_.reset();
        msColor_.reset();
        msDepth_.reset();
    }
    width_ = width;
    height_ = height;
    samples_ = samples;
    return {};
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, samples_ > 1 ? msFbo_.get() : fbo_.get());
    glViewport(0, 0, width_, height_);
}

void RenderTarget::resolve() const {
    if (samples_ <= 1) return;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, msFbo_.get());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo_.get());
    // Same size: GL_NEAREST is required for depth and gives the plain average for colour.
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_,
                      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
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
