// The scene's lighting inputs folded into the float constants of the fast path (its
// per-pixel formula is shading/fast_lighting.hpp; the double one is reference/lighting.cpp).

#include "facet/advanced/fast_lighting.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace facet {

namespace {

/// Narrows to float, saturating at the largest float: an overflow to +inf would turn a zero
/// factor (n·h = 0, Ks = 0) into NaN.
float narrow(double x) {
    return static_cast<float>(std::min(x, static_cast<double>(std::numeric_limits<float>::max())));
}

}  // namespace

FastLighting prepareLighting(const LightingParams& params) {
    // (x, y, z, w) and (−x, −y, −z, −w) are the same point; w ≥ 0 keeps xyz − w·p pointing at
    // the light. Any positive scale is the same point too; the largest |component| 1 keeps the
    // numbers in float range whatever the file said.
    glm::dvec4 q = params.light.position;
    if (q.w < 0.0) q = -q;
    const double largest = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z), q.w});
    if (largest > 0.0) q /= largest;

    const Material& m = params.material;
    const double id = params.light.intensity;
    FastLighting f;
    f.light = glm::vec4(q);
    f.ambientTerm = narrow(params.ambient * m.ka);
    f.diffuse = narrow(id * m.kd);
    f.specular = narrow(id * m.ks);
    f.shininess = static_cast<float>(m.s);  // +inf is a valid exponent (see the header)
    return f;
}

}  // namespace facet
