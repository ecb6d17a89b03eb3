// Step 5 (assignment section 4, "Triangular face rasterization"). Write the function, delete its
// notStarted line, then run `make lab-check`.

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/common.hpp>

#include "lab/steps.hpp"

namespace lab {

// Step 5. Append to `out` one Fragment per pixel of the width × height image that lies inside
// the triangle (v1, v2, v3):
//  - C = makeBarycentricCoordsMatrix(v1, v2, v3) (the zero matrix: no area, no pixel);
//  - the candidates are the pixels of the triangle's bounding box that are in the image; a
//    pixel (i, j) is tested at its centre p = (i + 0.5, j + 0.5);
//  - (α, β, γ) = C · (1, p.x, p.y); the pixel is inside when all three are >= 0;
//  - the fragment's position is p; colour, normal and uv are α·a1 + β·a2 + γ·a3 of the
//    vertices' (linear interpolation); clamp the colour to [0, 1] (glm::clamp);
//  - depth: 1/Z, not Z, is linear across the image: depth = 1 / (α/z1 + β/z2 + γ/z3).
void rasterizeFace(const Fragment& v1, const Fragment& v2, const Fragment& v3, int width,
                   int height, std::vector<Fragment>& out) {
    (void)v1;
    (void)v2;
    (void)v3;
    (void)width;
    (void)height;
    (void)out;
    markNotStarted(Step::RasterizeFace);
}

}  // namespace lab
