#pragma once
// A triangle mesh as structure-of-arrays with one index buffer. Optional attributes are empty
// vectors when the file has none, so a draw stores and interpolates only what exists.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace facet {

/// Indexed triangle mesh; every non-empty attribute array has one entry per vertex.
struct Mesh {
    std::vector<glm::vec3> positions;  ///< object/world space (the course has no model matrix)
    std::vector<glm::vec3> colors;     ///< RGB in [0,1]; empty means every vertex is white
    std::vector<glm::vec2> uvs;  ///< texture coordinates, v = 0 at the image top; may be empty
    std::vector<std::uint32_t>
        indices;  ///< three per triangle, counter-clockwise seen from outside
    /// Unit normals from the file (an OBJ whose every face corner has a `vn`); empty otherwise,
    /// and then lighting computes them (normals.hpp).
    std::vector<glm::vec3> normals;
    /// The file position each vertex was made from, when the loader split some position into
    /// several vertices (different `vt` or `vn`); empty means every vertex is its own position.
    /// Computed normals are shared per position, so texture seams leave no shading seam.
    std::vector<std::uint32_t> positionIds;
    std::string texturePath;  ///< resolved path of an OBJ map_Kd texture, empty if none

    /// Number of vertices.
    std::size_t vertexCount() const { return positions.size(); }
    /// Number of triangles.
    std::size_t triangleCount() const { return indices.size() / 3; }
    /// True when per-vertex colours are present.
    bool hasColors() const { return !colors.empty(); }
    /// True when texture coordinates are present.
    bool hasUvs() const { return !uvs.empty(); }
    /// True when the file gave the normals lighting uses.
    bool hasNormals() const { return !normals.empty(); }

    /// Every attribute, index and path equal.
    bool operator==(const Mesh&) const = default;
};

/// Axis-aligned bounds of a mesh's positions (min > max when the mesh is empty).
struct Bounds {
    glm::vec3 min{1.0f};
    glm::vec3 max{-1.0f};
    /// Length of the box diagonal, 0 for an empty mesh.
    float diagonal() const;

    /// Every field equal.
    bool operator==(const Bounds&) const = default;
};

/// Bounds of all positions.
Bounds computeBounds(const Mesh& mesh);

/// Unique undirected edges of the triangles, each once as (lower index, higher index), sorted;
/// collapsed edges (a == b) are left out.
std::vector<std::uint32_t> uniqueEdges(const Mesh& mesh);

/// The same for a bare index list, written into `edges` (its capacity is reused).
void uniqueEdges(std::span<const std::uint32_t> indices, std::vector<std::uint32_t>& edges);

}  // namespace facet
