// Solution of step 5 (assignment section 4): a triangle's pixels with affine attributes.

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/common.hpp>

#include "lab/steps.hpp"

namespace lab {

void rasterizeFace(const Fragment& v1, const Fragment& v2, const Fragment& v3, int width,
                   int height, std::vector<Fragment>& out) {
    const glm::dmat3 c = makeBarycentricCoordsMatrix(v1, v2, v3);
    if (c == glm::dmat3(0.0)) return;  // no area, no pixel

    // The pixels whose centre (i + ½, j + ½) lies in the triangle's bounding box, in the image.
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
            const glm::dvec3 w = c * glm::dvec3(1.0, p.x, p.y);  // (α, β, γ)
            if (w.x < 0.0 || w.y < 0.0 || w.z < 0.0) continue;   // outside
            Fragment f;
            f.position = p;
            // Depth: 1/Z is what is linear in the image, so interpolate it and invert (the
            // depth test then compares true depths, as facet's does).
            f.depth = 1.0 / (w.x / v1.depth + w.y / v2.depth + w.z / v3.depth);
            f.color = glm::clamp(w.x * v1.color + w.y * v2.color + w.z * v3.color, 0.0, 1.0);
            f.normal = w.x * v1.normal + w.y * v2.normal + w.z * v3.normal;
            f.uv = w.x * v1.uv + w.y * v2.uv + w.z * v3.uv;
            out.push_back(f);
        }
    }
}

}  // namespace lab
