// Vertex normals (spec §6): area weighting comes for free because the un-normalised cross
// product (v1 − v0) × (v2 − v0) is twice the triangle's area times its unit normal.

#include "facet/normals.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <glm/geometric.hpp>

#include "scene/scratch.hpp"

namespace facet {

namespace {

/// Below this fraction of the summed magnitudes a vertex's sum is cancellation noise: its
/// direction would be rounding error, so it gets no normal rather than an arbitrary one.
/// Double sums of float-derived products carry relative error ~1e-16, far below this.
constexpr double kCancelled = 1e-9;

}  // namespace

std::vector<glm::vec3> computeVertexNormals(const Mesh& mesh) {
    std::vector<glm::vec3> normals;
    std::vector<glm::dvec4> scratch;
    computeVertexNormals(mesh, normals, scratch);
    return normals;
}

void computeVertexNormals(const Mesh& mesh, std::vector<glm::vec3>& normals,
                          std::vector<glm::dvec4>& scratch) {
    const std::size_t n = mesh.vertexCount();
    if (mesh.normals.size() == n && n > 0) {
        normals.assign(mesh.normals.begin(), mesh.normals.end());
        return;
    }
    // Sums per position: a vertex's own index when the loader split no position.
    const bool shared = mesh.positionIds.size() == n && n > 0;
    std::size_t slots = n;
    if (shared)
        slots =
            std::size_t{*std::max_element(mesh.positionIds.begin(), mesh.positionIds.end())} + 1;
    const auto slot = [&](std::uint32_t v) -> std::size_t {
        return shared ? mesh.positionIds[v] : v;
    };
    // Double accumulation: a vertex of a fine mesh sums many small, nearly parallel vectors.
    // xyz: the weighted sum; w: the sum of the weights' lengths (for the cancellation test).
    scratch.assign(slots, glm::dvec4(0.0));

    const std::size_t triangles = mesh.triangleCount();
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        assert(v[0] < n && v[1] < n && v[2] < n);
        const glm::dvec3 p0(mesh.positions[v[0]]);
        const glm::dvec3 p1(mesh.positions[v[1]]);
        const glm::dvec3 p2(mesh.positions[v[2]]);
        const glm::dvec3 weighted = glm::cross(p1 - p0, p2 - p0);
        const glm::dvec4 add(weighted, glm::length(weighted));
        for (int k = 0; k < 3; ++k) scratch[slot(v[k])] += add;
    }

    normals.assign(n, glm::vec3(0.0f));
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec4& s = scratch[slot(static_cast<std::uint32_t>(i))];
        const glm::dvec3 sum(s);
        const double length = glm::length(sum);
        // Also false for 0 = 0 (no face of non-zero area), so the division below is safe.
        if (length > kCancelled * s.w) normals[i] = glm::vec3(sum / length);
    }
}

float normalDisplayLength(const Mesh& mesh) {
    return computeBounds(mesh).diagonal() / 100.0f;
}

}  // namespace facet
