#pragma once
// The twin's lines, wireframe and normals display, as spec §8 draws them: each edge
// once, from the pixel of one end to the pixel of the other, both ends included. twin.vert
// moves the ends to pixel centres; this file supplies the index lists and the extra pass for
// the ends that GL's lines leave out.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "facet/mesh.hpp"

namespace facet::gl {

/// The wireframe's index list: the unique edges, then each vertex on one of them once (a
/// point per edge end would draw every vertex about six times on a closed mesh).
struct WireframeIndices {
    std::vector<std::uint32_t> indices;  ///< edge pairs, then the joined vertices
    std::size_t edgeIndices = 0;         ///< how many of `indices` are edge pairs
    std::vector<std::uint8_t> joined;    ///< scratch: per vertex, whether an edge has it

    /// Rebuilds the lists for `mesh`, reusing their storage.
    void build(const Mesh& mesh);
};

/// The normals display's segments in world space: for each vertex with a non-zero normal, the
/// vertex and the vertex moved `length` along its normal, as the engine builds them.
void normalSegments(const Mesh& mesh, const std::vector<glm::vec3>& normals, float length,
                    std::vector<glm::vec3>& segments);

/// Draws lines and then their ends as one-pixel points, with the end's own colour and depth
/// like Bresenham's first and last steps: GL's diamond-exit rule leaves out a line's last
/// pixel (so strips do not draw shared ends twice) and draws nothing for a line inside one
/// pixel. Indexed: `lines` indices of pairs, then `points` indices from the same buffer;
/// else vertices in order, pairs for the lines and all of them again as points.
void drawLines(bool indexed, std::size_t lines, std::size_t points);

}  // namespace facet::gl
