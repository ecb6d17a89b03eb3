#pragma once
// Vertex streams on the GL side: one vertex array with a buffer per attribute and an index
// buffer, refilled per frame with only the streams the draw reads. A stream the draw reads but
// the mesh lacks becomes a constant attribute (white colour, uv (0, 0)), as in the engine.

#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/vec4.hpp>

#include "gl_objects.hpp"

namespace facet::gl {

/// Attribute locations, as twin.vert declares them.
enum class Attribute : GLuint { Position = 0, Color = 1, Uv = 2, Normal = 3 };
inline constexpr int kAttributeCount = 4;

/// A vertex array and its buffers. Needs a current context from construction on.
class VertexStreams {
  public:
    VertexStreams();

    /// Uploads `floats` (components per vertex, tightly packed) as attribute `a`; returns the
    /// bytes sent.
    std::size_t upload(Attribute a, std::span<const float> floats, int components);

    /// Makes `a` the same value for every vertex (no buffer read).
    void constant(Attribute a, const glm::vec4& value);

    /// Uploads the index buffer; returns the bytes sent.
    std::size_t uploadIndices(std::span<const std::uint32_t> indices);

    /// 0: attributes advance per vertex; 1: per instance (the vertex squares).
    void setDivisor(GLuint divisor);

    /// Binds the vertex array (and with it the index buffer).
    void bind() const;

  private:
    /// Fills `buffer` with `bytes`, growing its storage only when it is too small.
    static void fill(GLenum target, const Buffer& buffer, std::size_t& capacity, const void* data,
                     std::size_t bytes);

    VertexArray vao_;
    Buffer buffers_[kAttributeCount];
    std::size_t capacity_[kAttributeCount] = {};
    Buffer indices_;
    std::size_t indexCapacity_ = 0;
};

}  // namespace facet::gl
