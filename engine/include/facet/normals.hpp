#pragma once
// Vertex normals for lighting (spec §6) and the "normals" display (§8). The file's own
// normals when it has them (Mesh::normals); else computed per position (Mesh::positionIds), so
// the vertices an OBJ split along a texture seam share one normal and no shading seam shows.

#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/mesh.hpp"

namespace facet {

/// One normal per vertex: Mesh::normals when the file gave them, else the normalised sum of the
/// area-weighted normals of the triangles around the vertex's position. The zero vector (no
/// diffuse or specular term, never NaN) when the position has no triangle of non-zero area, or
/// when its triangles' normals cancel (a two-sided sheet). Indices and position ids must be in
/// range, as every loader guarantees.
std::vector<glm::vec3> computeVertexNormals(const Mesh& mesh);

/// Length of the segments the normals display draws: the bounding-box diagonal / 100, so the
/// segments scale with the model (0 for an empty mesh).
float normalDisplayLength(const Mesh& mesh);

}  // namespace facet
