#include "gl_frame.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

namespace facet::view {
namespace {

bool readFile(const std::string& path, std::string& text) {
    std::ifstream f(path, std::ios::binary);
    if (!f) return false;
    std::ostringstream s;
    s << f.rdbuf();
    text = s.str();
    return true;
}

/// Compiles one stage; on failure `error` holds the file name and the driver's log.
GLuint compile(GLenum stage, const std::string& path, std::string& error) {
    std::string source;
    if (!readFile(path, source)) {
        error = path + ": cannot read the shader";
        return 0;
    }
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)));
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        error = path + ": " + log.data();
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

}  // namespace

GlFrame::~GlFrame() {
    if (texture_) glDeleteTextures(1, &texture_);
    if (vao_) glDeleteVertexArrays(1, &vao_);
    if (program_) glDeleteProgram(program_);
}

bool GlFrame::init(const std::string& shaderDir, std::string& error) {
    const GLuint vs = compile(GL_VERTEX_SHADER, shaderDir + "/frame.vert", error);
    if (!vs) return false;
    const GLuint fs = compile(GL_FRAGMENT_SHADER, shaderDir + "/frame.frag", error);
    if (!fs) {
        glDeleteShader(vs);
        return false;
    }
    program_ = glCreateProgram();
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);  // flagged; freed with the program
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        char log[1024] = {};
        glGetProgramInfoLog(program_, sizeof log, nullptr, log);
        error = shaderDir + ": linking frame.vert + frame.frag failed: " + log;
        return false;
    }
    glUseProgram(program_);
    glUniform1i(glGetUniformLocation(program_, "frame"), 0);
    glUseProgram(0);

    // Core profile: drawing needs a bound VAO even with no attributes at all.
    glGenVertexArrays(1, &vao_);
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    // Nearest: at 1:1 each texel is one pixel, and a scaled frame shows its real pixels.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    return true;
}

void GlFrame::upload(const Framebuffer& frame) {
    if (frame.width <= 0 || frame.height <= 0) return;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
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
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glViewport(0, 0, windowWidth, windowHeight);
    const bool fills =
        view.x <= 0 && view.y <= 0 && view.w >= windowWidth && view.h >= windowHeight && width_ > 0;
    if (!fills) {  // bars around a letterboxed frame; a full frame overwrites every pixel anyway
        glClearColor(0.08f, 0.08f, 0.08f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    if (!width_ || view.w <= 0 || view.h <= 0) return;
    // GL's viewport origin is the bottom left; `view` counts from the top.
    glViewport(view.x, windowHeight - view.y - view.h, view.w, view.h);
    glUseProgram(program_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture_);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    glViewport(0, 0, windowWidth, windowHeight);
}

}  // namespace facet::view
