// Solution of step 12 (assignment section 7): rasterizeFace with perspective-correct attributes.

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/common.hpp>

#include "lab/steps.hpp"

namespace lab {

void rasterizeFacePerspective(const Fragment& v1, const Fragment& v2, const Fragment& v3, int width,
                              int height, std::vector<Fragment>& out) {
    const glm::dmat3 c = makeBarycentricCoordsMatrix(v1, v2, v3);
    if (c == glm::dmat3(0.0)) return;

    const double minX = std::min({v1.position.x, v2.position.x, v3.position.x});
    const double maxX = std::max({v1.position.x, v2.position.x, v3.position.x});
    const double minY = std::min({v1.position.y, v2.position.y, v3.position.y});
    const double maxY = std::max({v1.position.y, v2.position.y, v3.position.y});
    const int i0 = static_cast<int>(std::max(0.0, std::ceil(minX - 0.5)));
    const int i1 = static_cast<int>(std::min(width - 1.0, std::floor(maxX - 0.5)));
    const int j0 = static_cast<int>(std::max(0.0, std::ceil(minY - 0.5)));
    const int j1 = static_cast<int>(std::min(height - 1.0, std::floor(maxY - 0.5)));

    for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
            const glm::dvec2 p(i + 0.5, j + 0.5);
            const glm::dvec3 w = c * glm::dvec3(1.0, p.x, p.y);
            if (w.x < 0.0 || w.y < 0.0 || w.z < 0.0) continue;
            // An attribute divided by Z is linear in the image, and so is 1/Z: interpolate
            // both and divide. The weights below are those of the 3D triangle.
            const glm::dvec3 overZ(w.x / v1.depth, w.y / v2.depth, w.z / v3.depth);
            const double q = overZ.x + overZ.y + overZ.z;
            const glm::dvec3 pw = overZ / q;
            Fragment f;
            f.position = p;
            f.depth = 1.0 / q;
            f.color = glm::clamp(pw.x * v1.color + pw.y * v2.color + pw.z * v3.color, 0.0, 1.0);
            f.normal = pw.x * v1.normal + pw.y * v2.normal + pw.z * v3.normal;
            f.uv = pw.x * v1.uv + pw.y * v2.uv + pw.z * v3.uv;
            out.push_back(f);
        }
    }
}

}  // namespace lab
