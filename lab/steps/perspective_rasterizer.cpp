// Step 12 (assignment section 7, the PerspectiveCorrectRasterizer). Write the function, delete
// its notStarted line, then run `make lab-check`.

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/common.hpp>

#include "lab/steps.hpp"

namespace lab {

// Step 12. The same pixels as rasterizeFace, but the attributes interpolated as on the 3D
// triangle rather than across the image: with (α, β, γ) the image-space weights at the pixel
// centre, a/Z and 1/Z are linear in the image, so
//   q = α/z1 + β/z2 + γ/z3,   weights (α/z1, β/z2, γ/z3) / q,   depth = 1 / q,
// and colour (clamped to [0, 1]), normal and uv are interpolated with those weights.
// Compare the brick wall of example_textured.scene before and after.
void rasterizeFacePerspective(const Fragment& v1, const Fragment& v2, const Fragment& v3, int width,
                              int height, std::vector<Fragment>& out) {
    (void)v1;
    (void)v2;
    (void)v3;
    (void)width;
    (void)height;
    (void)out;
    markNotStarted(Step::PerspectiveRasterizer);
}

}  // namespace lab
