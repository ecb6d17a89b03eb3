#pragma once
// The forms of mesh.hpp's and normals.hpp's functions that take their scratch buffers from the
// caller: the renderer keeps those buffers between frames, so a steady frame allocates nothing.
// Engine-internal; applications call the public forms, which allocate their own.

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/mesh.hpp"

namespace facet {

/// uniqueEdges() of a bare index list into `edges`, with `keys` as scratch. Both keep their
/// capacity, so a repeated call allocates nothing.
void uniqueEdges(std::span<const std::uint32_t> indices, std::vector<std::uint32_t>& edges,
                 std::vector<std::uint64_t>& keys);

/// computeVertexNormals() into `normals`, with `scratch` for the sums: both keep their
/// capacity, so a renderer that calls this every frame allocates only when the mesh grows.
void computeVertexNormals(const Mesh& mesh, std::vector<glm::vec3>& normals,
                          std::vector<glm::dvec4>& scratch);

}  // namespace facet
