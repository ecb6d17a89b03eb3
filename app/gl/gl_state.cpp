#include "gl_state.hpp"

namespace facet::gl {

StateGuard::StateGuard(bool clipControl) : clipControl_(clipControl) {
    for (int i = 0; i < kCapCount; ++i) enabled_[i] = glIsEnabled(kCaps[i]);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_);
    if (clipControl_) {
        glGetIntegerv(GL_CLIP_ORIGIN, &clipOrigin_);
        glGetIntegerv(GL_CLIP_DEPTH_MODE, &clipDepth_);
    }
    glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
    glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
    glActiveTexture(GL_TEXTURE0);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture0_);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer_);
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer_);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
    glGetIntegerv(GL_FRONT_FACE, &frontFace_);
    glGetIntegerv(GL_CULL_FACE_MODE, &cullFace_);
    glGetIntegerv(GL_POLYGON_MODE, polygonMode_);
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
    glGetBooleanv(GL_COLOR_WRITEMASK, colorMask_);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clearColor_);
    glGetFloatv(GL_DEPTH_CLEAR_VALUE, &clearDepth_);
    glGetFloatv(GL_LINE_WIDTH, &lineWidth_);
    glGetFloatv(GL_POINT_SIZE, &pointSize_);
    for (int i = 0; i < kPixelStoreCount; ++i) glGetIntegerv(kPixelStore[i], &pixelStore_[i]);

    // The twin's baseline: every pixel written as computed, nothing mixed or masked.
    for (const GLenum cap : kCaps) glDisable(cap);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glLineWidth(1.0f);
    glPointSize(1.0f);
    for (const GLenum p : kPixelStore)
        glPixelStorei(p, p == GL_UNPACK_ALIGNMENT || p == GL_PACK_ALIGNMENT ? 4 : 0);
}

StateGuard::~StateGuard() {
    for (int i = 0; i < kCapCount; ++i) {
        if (enabled_[i])
            glEnable(kCaps[i]);
        else
            glDisable(kCaps[i]);
    }
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    if (clipControl_)
        glClipControl(static_cast<GLenum>(clipOrigin_), static_cast<GLenum>(clipDepth_));
    glUseProgram(static_cast<GLuint>(program_));
    glBindVertexArray(static_cast<GLuint>(vertexArray_));
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture0_));
    glActiveTexture(static_cast<GLenum>(activeTexture_));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(arrayBuffer_));
    glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(packBuffer_));
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpackBuffer_));
    glDepthFunc(static_cast<GLenum>(depthFunc_));
    glFrontFace(static_cast<GLenum>(frontFace_));
    glCullFace(static_cast<GLenum>(cullFace_));
    glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygonMode_[0]));
    glDepthMask(depthMask_);
    glColorMask(colorMask_[0], colorMask_[1], colorMask_[2], colorMask_[3]);
    glClearColor(clearColor_[0], clearColor_[1], clearColor_[2], clearColor_[3]);
    glClearDepth(static_cast<GLdouble>(clearDepth_));
    glLineWidth(lineWidth_);
    glPointSize(pointSize_);
    for (int i = 0; i < kPixelStoreCount; ++i) glPixelStorei(kPixelStore[i], pixelStore_[i]);
}

}  // namespace facet::gl
