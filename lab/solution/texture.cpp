// Solution of steps 10 and 11 (assignment section 7): sampling with repetition, and the texture
// shader.

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "lab/steps.hpp"

namespace lab {
namespace {

// The fractional part t − ⌊t⌋ in [0, 1): u = 2.25 and u = -0.75 both land a quarter across.
double repeat(double t) {
    return std::isfinite(t) ? t - std::floor(t) : 0.0;
}

}  // namespace

glm::dvec3 Texture::sample(double u, double v) const {
    // The nearest texel: the one whose square holds (u'·W, v'·H). The clamp catches u' that
    // rounds to 1 (u = -1e-20 gives 1 - 0).
    const int x = std::clamp(static_cast<int>(std::floor(repeat(u) * width)), 0, width - 1);
    const int y = std::clamp(static_cast<int>(std::floor(repeat(v) * height)), 0, height - 1);
    return at(x, y);
}

void textureShade(Canvas& canvas, const Fragment& fragment, const Texture& texture, bool combine) {
    if (!canvas.depth.testFragment(fragment)) return;
    const glm::ivec2 p = pixelOf(fragment);
    if (p.x < 0 || p.y < 0 || p.x >= canvas.width || p.y >= canvas.height) return;
    glm::dvec3 c = texture.sample(fragment.uv.x, fragment.uv.y);
    if (combine) c *= fragment.color;
    canvas.color[static_cast<std::size_t>(p.y) * canvas.width + p.x] = c;
    canvas.depth.writeFragment(fragment);
}

}  // namespace lab
