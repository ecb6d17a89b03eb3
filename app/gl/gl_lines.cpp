#include "gl_lines.hpp"

#include <epoxy/gl.h>

namespace facet::gl {

void WireframeIndices::build(const Mesh& mesh) {
    uniqueEdges(mesh.indices, indices);
    edgeIndices = indices.size();
    joined.assign(mesh.vertexCount(), 0);
    for (std::size_t i = 0; i < edgeIndices; ++i) joined[indices[i]] = 1;
    for (std::uint32_t v = 0; v < joined.size(); ++v)
        if (joined[v]) indices.push_back(v);
}

void normalSegments(const Mesh& mesh, const std::vector<glm::vec3>& normals, float length,
                    std::vector<glm::vec3>& segments) {
    segments.clear();
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        if (normals[i] == glm::vec3(0.0f)) continue;  // no face: no direction to show
        segments.push_back(mesh.positions[i]);
        segments.push_back(mesh.positions[i] + length * normals[i]);
    }
}

void drawLines(bool indexed, std::size_t lines, std::size_t points) {
    if (!indexed) {
        glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines));
        glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(points));
        return;
    }
    glDrawElements(GL_LINES, static_cast<GLsizei>(lines), GL_UNSIGNED_INT, nullptr);
    const auto offset = static_cast<std::uintptr_t>(lines * sizeof(std::uint32_t));
    glDrawElements(GL_POINTS, static_cast<GLsizei>(points), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(offset));
}

}  // namespace facet::gl
