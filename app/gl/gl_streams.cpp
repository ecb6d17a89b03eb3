#include "gl_streams.hpp"

namespace facet::gl {

VertexStreams::VertexStreams() : vao_(makeVertexArray()), indices_(makeBuffer()) {
    for (Buffer& b : buffers_) b = makeBuffer();
}

void VertexStreams::fill(GLenum target, const Buffer& buffer, std::size_t& capacity,
                         const void* data, std::size_t bytes) {
    glBindBuffer(target, buffer.get());
    // Every frame reads the buffer back through glFinish before the next upload, so rewriting
    // in place never waits for the GPU; storage is reallocated only to grow.
    if (bytes > capacity) {
        glBufferData(target, static_cast<GLsizeiptr>(bytes), data, GL_STREAM_DRAW);
        capacity = bytes;
    } else if (bytes > 0) {
        glBufferSubData(target, 0, static_cast<GLsizeiptr>(bytes), data);
    }
}

std::size_t VertexStreams::upload(Attribute a, std::span<const float> floats, int components) {
    const auto i = static_cast<GLuint>(a);
    glBindVertexArray(vao_.get());
    fill(GL_ARRAY_BUFFER, buffers_[i], capacity_[i], floats.data(), floats.size_bytes());
    glVertexAttribPointer(i, components, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(i);
    return floats.size_bytes();
}

void VertexStreams::constant(Attribute a, const glm::vec4& value) {
    const auto i = static_cast<GLuint>(a);
    glBindVertexArray(vao_.get());
    glDisableVertexAttribArray(i);
    // The current value is context state, not vertex array state: set before every draw.
    glVertexAttrib4f(i, value.x, value.y, value.z, value.w);
}

std::size_t VertexStreams::uploadIndices(std::span<const std::uint32_t> indices) {
    glBindVertexArray(vao_.get());  // the element binding belongs to the vertex array
    fill(GL_ELEMENT_ARRAY_BUFFER, indices_, indexCapacity_, indices.data(), indices.size_bytes());
    return indices.size_bytes();
}

void VertexStreams::setDivisor(GLuint divisor) {
    glBindVertexArray(vao_.get());
    for (GLuint i = 0; i < kAttributeCount; ++i) glVertexAttribDivisor(i, divisor);
}

void VertexStreams::bind() const {
    glBindVertexArray(vao_.get());
}

}  // namespace facet::gl
