#pragma once
// Owning handles for OpenGL object names, so the twin's buffers, textures and programs live
// exactly as long as the object holding them. Like every GL call they need the context that
// created them to be current, including when they are destroyed.

#include <epoxy/gl.h>

#include <utility>

namespace facet::gl {

/// A GL object name that deletes its object when destroyed; move-only.
template <class Traits>
class Handle {
  public:
    Handle() = default;
    /// Takes ownership of `name` (0 means none).
    explicit Handle(GLuint name) : name_(name) {}
    Handle(Handle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { reset(); }

    /// The GL name, 0 when empty.
    GLuint get() const { return name_; }
    /// Deletes the object now.
    void reset() {
        if (name_ != 0) Traits::destroy(name_);
        name_ = 0;
    }

  private:
    GLuint name_ = 0;
};

// The delete calls differ per kind (epoxy's entry points are pointers, not constants, hence
// the small wrappers rather than function-pointer template arguments).
struct BufferTraits {
    static void destroy(GLuint n) { glDeleteBuffers(1, &n); }
};
struct VertexArrayTraits {
    static void destroy(GLuint n) { glDeleteVertexArrays(1, &n); }
};
struct TextureTraits {
    static void destroy(GLuint n) { glDeleteTextures(1, &n); }
};
struct RenderbufferTraits {
    static void destroy(GLuint n) { glDeleteRenderbuffers(1, &n); }
};
struct FramebufferTraits {
    static void destroy(GLuint n) { glDeleteFramebuffers(1, &n); }
};
struct ProgramTraits {
    static void destroy(GLuint n) { glDeleteProgram(n); }
};

using Buffer = Handle<BufferTraits>;
using VertexArray = Handle<VertexArrayTraits>;
using TextureName = Handle<TextureTraits>;
using Renderbuffer = Handle<RenderbufferTraits>;
using FramebufferName = Handle<FramebufferTraits>;
using Program = Handle<ProgramTraits>;

/// A new buffer object.
inline Buffer makeBuffer() {
    GLuint n = 0;
    glGenBuffers(1, &n);
    return Buffer(n);
}
/// A new vertex array object.
inline VertexArray makeVertexArray() {
    GLuint n = 0;
    glGenVertexArrays(1, &n);
    return VertexArray(n);
}
/// A new texture object.
inline TextureName makeTexture() {
    GLuint n = 0;
    glGenTextures(1, &n);
    return TextureName(n);
}
/// A new renderbuffer object.
inline Renderbuffer makeRenderbuffer() {
    GLuint n = 0;
    glGenRenderbuffers(1, &n);
    return Renderbuffer(n);
}
/// A new framebuffer object.
inline FramebufferName makeFramebuffer() {
    GLuint n = 0;
    glGenFramebuffers(1, &n);
    return FramebufferName(n);
}

}  // namespace facet::gl
