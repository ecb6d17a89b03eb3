// Steps 10 and 11 (assignment section 7, "Texture mapping"). Write both, delete their
// notStarted lines, run `make lab-check`, and choose the texture shader on
// example_textured.scene.

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "lab/steps.hpp"

namespace lab {

// Step 10. The texel nearest to (u, v). u runs across the image (0 at the left edge, 1 at the
// right), v down it (0 at the top row). The texture repeats: only the fractional part
// u' = u − floor(u) counts (so 2.25 and −0.75 are both a quarter across), likewise v'. The
// texel is at column floor(u' · width), row floor(v' · height), clamped to the image; return
// at(column, row). A non-finite u or v counts as 0.
glm::dvec3 Texture::sample(double u, double v) const {
    (void)u;
    (void)v;
    return notStarted(Step::TextureSample, glm::dvec3(1.0, 0.0, 1.0));
}

// Step 11. Like painterShade (see lab/src/given.cpp): if the depth buffer's test passes, the
// pixel gets texture.sample(fragment.uv.x, fragment.uv.y) — times fragment.color when `combine`
// — and the depth buffer gets the fragment's depth. Write nothing outside the canvas.
void textureShade(Canvas& canvas, const Fragment& fragment, const Texture& texture, bool combine) {
    (void)texture;
    (void)combine;
    markNotStarted(Step::TextureShader);
    painterShade(canvas, fragment);
}

}  // namespace lab
