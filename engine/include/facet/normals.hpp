#pragma once
// Vertex normals for lighting (conventions §6) and the "normals" display (§8). Normals belong to
// vertex indices, not positions: vertices duplicated for a uv seam or a hard edge keep their own.

#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/mesh.hpp"

namespace facet {

/// One normal per vertex: the normalised sum of the area-weighted normals of the triangles that
/// use it. The zero vector (no diffuse or specular term, never NaN) when the vertex has no
/// triangle of non-zero area, or when its triangles' normals cancel (a two-sided sheet).
/// Indices must be in range, as every loader guarantees.
std::vector<glm::vec3> computeVertexNormals(const Mesh& mesh);

/// The same into `normals`, with `scratch` for the sums: both keep their capacity, so a renderer
/// that calls this every frame allocates only when the mesh grows.
void computeVertexNormals(const Mesh& mesh, std::vector<glm::vec3>& normals,
                          std::vector<glm::dvec4>& scratch);

/// Length of the segments the normals display draws: the bounding-box diagonal / 100, so the
/// segments scale with the model (0 for an empty mesh).
float normalDisplayLength(const Mesh& mesh);

}  // namespace facet
