// Mesh queries shared by the renderer, the viewer and the tests.

#include "facet/mesh.hpp"

#include <algorithm>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "scene/scratch.hpp"

namespace facet {

float Bounds::diagonal() const {
    if (min.x > max.x || min.y > max.y || min.z > max.z) return 0.0f;
    return glm::length(max - min);
}

Bounds computeBounds(const Mesh& mesh) {
    Bounds b;
    if (mesh.positions.empty()) return b;
    b.min = b.max = mesh.positions.front();
    for (const glm::vec3& p : mesh.positions) {
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
    }
    return b;
}

void uniqueEdges(std::span<const std::uint32_t> indices, std::vector<std::uint32_t>& edges,
                 std::vector<std::uint64_t>& keys) {
    // One 64-bit key per edge sorts lexicographically by (lower, higher) and dedups cheaply.
    keys.clear();
    keys.reserve(indices.size());
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t a = indices[t + e];
            const std::uint32_t b = indices[t + (e + 1) % 3];
            if (a == b) continue;  // a collapsed edge draws nothing a vertex would not
            keys.push_back((std::uint64_t{std::min(a, b)} << 32) | std::max(a, b));
        }
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());

    edges.clear();
    edges.reserve(2 * keys.size());
    for (const std::uint64_t k : keys) {
        edges.push_back(static_cast<std::uint32_t>(k >> 32));
        edges.push_back(static_cast<std::uint32_t>(k));
    }
}

void uniqueEdges(std::span<const std::uint32_t> indices, std::vector<std::uint32_t>& edges) {
    std::vector<std::uint64_t> keys;
    uniqueEdges(indices, edges, keys);
}

std::vector<std::uint32_t> uniqueEdges(const Mesh& mesh) {
    std::vector<std::uint32_t> edges;
    std::vector<std::uint64_t> keys;
    uniqueEdges(mesh.indices, edges, keys);
    return edges;
}

}  // namespace facet
