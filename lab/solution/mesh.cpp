// Solution of step 7 (assignment section 6): vertex normals.

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "lab/steps.hpp"

namespace lab {

std::vector<glm::dvec3> computeNormals(const std::vector<glm::dvec3>& positions,
                                       const std::vector<std::uint32_t>& indices) {
    std::vector<glm::dvec3> sums(positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t a = indices[t], b = indices[t + 1], c = indices[t + 2];
        if (a >= positions.size() || b >= positions.size() || c >= positions.size()) continue;
        // The cross product's length is twice the triangle's area: adding it unnormalised
        // weights each face by its area, so slivers barely count.
        const glm::dvec3 n = glm::cross(positions[b] - positions[a], positions[c] - positions[a]);
        sums[a] += n;
        sums[b] += n;
        sums[c] += n;
    }
    for (glm::dvec3& n : sums) {
        const double len = glm::length(n);
        n = len > 0.0 ? n / len : glm::dvec3(0.0);  // no face: no normal, never NaN
    }
    return sums;
}

}  // namespace lab
