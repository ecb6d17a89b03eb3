#pragma once
// The fast texture samplers the pixel loops call per pixel, inline so a shading loop can inline
// them. Filtering happens on the 0..255 values with a single scale by 1/255 at the end: a weight
// of exactly 0 or 1 then reproduces a texel bit for bit, so bilinear filtering at a texel centre
// returns that texel exactly (texelColor()).
//
// Every sampler is always inlined: the vector loops (span_loop-inl.hpp, compiled per SIMD target)
// shade their few-lane blocks through these scalar samplers, and an out-of-line copy is compiled
// for the baseline target, legacy SSE. A call into SSE code with the AVX-512 registers' upper
// halves in use paid about a microsecond-scale state transition per pixel on the bench machine
// (docs/performance.md); inlined, the sampler is compiled with the caller's target. The results
// are the same bits: the engine builds with -ffp-contract=off, so no target fuses an operation.
//
// Non-finite coordinates (NaN, ±inf) wrap to 0, as does every float of magnitude ≥ 2^23 (all of
// which are integers). The level of detail maps NaN to 0 and +inf to the last level.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <glm/ext/vector_int2.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "facet/texture.hpp"

namespace facet {

/// Repeat wrap, t − ⌊t⌋, in [0, 1]: exactly 1 only when a tiny negative t rounds up to it.
/// NaN, ±inf and |t| ≥ 2^23 (integers in float) give 0.
[[gnu::always_inline]] inline float wrapCoord(float t) {
    // The cast is only taken where it is defined; beyond 2^23 every float is an integer anyway.
    if (!(std::fabs(t) < 8388608.0f)) return 0.0f;
    const float w = t - static_cast<float>(static_cast<int>(t));  // exact: the fraction
    return w < 0.0f ? w + 1.0f : w;
}

/// The texel at (x, y) as an RGB colour in [0, 1]; what filtering returns at a texel centre.
[[gnu::always_inline]] inline glm::vec3 texelColor(const MipLevel& level, int x, int y) {
    const std::uint32_t p = level.at(x, y);
    return glm::vec3(static_cast<float>(p & 0xFFu), static_cast<float>((p >> 8) & 0xFFu),
                     static_cast<float>((p >> 16) & 0xFFu)) *
           (1.0f / 255.0f);
}

namespace detail {

/// A texel's RGB as 0..255 floats.
[[gnu::always_inline]] inline glm::vec3 texel255(const std::uint32_t* row, int x) {
    const std::uint32_t p = row[x];
    return {static_cast<float>(p & 0xFFu), static_cast<float>((p >> 8) & 0xFFu),
            static_cast<float>((p >> 16) & 0xFFu)};
}

/// The four texels bilinear filtering reads at wrapped coordinates (wu, wv) and the blend
/// fractions: (x0, y0) weighs (1 − fx)(1 − fy), (x1, y0) fx(1 − fy) and so on.
struct BilinearTaps {
    int x0, y0, x1, y1;
    float fx, fy;
};

/// The taps of one level at already wrapped coordinates.
[[gnu::always_inline]] inline BilinearTaps bilinearTaps(const MipLevel& level, float wu, float wv) {
    const int w = level.width;
    const int h = level.height;
    // Texel centres sit at half-integers; x, y are in [−½, size − ½] since wu, wv are in [0, 1].
    const float x = wu * static_cast<float>(w) - 0.5f;
    const float y = wv * static_cast<float>(h) - 0.5f;
    int x0 = static_cast<int>(x);  // truncation; one less below 0 makes it floor
    int y0 = static_cast<int>(y);
    if (x < static_cast<float>(x0)) --x0;
    if (y < static_cast<float>(y0)) --y0;
    BilinearTaps t{x0, y0, x0 + 1, y0 + 1, x - static_cast<float>(x0), y - static_cast<float>(y0)};
    if (t.x0 < 0) t.x0 += w;
    if (t.y0 < 0) t.y0 += h;
    if (t.x1 >= w) t.x1 -= w;
    if (t.y1 >= h) t.y1 -= h;
    return t;
}

/// Bilinear filtering of one level at already wrapped coordinates, in 0..255.
[[gnu::always_inline]] inline glm::vec3 bilinear255(const MipLevel& level, float wu, float wv) {
    const BilinearTaps t = bilinearTaps(level, wu, wv);
    const auto w = static_cast<std::size_t>(level.width);
    const std::uint32_t* r0 = level.texels.data() + static_cast<std::size_t>(t.y0) * w;
    const std::uint32_t* r1 = level.texels.data() + static_cast<std::size_t>(t.y1) * w;
    // a + (b − a)·f: exact at f = 0 and f = 1, and never above max(a, b).
    const glm::vec3 c00 = texel255(r0, t.x0);
    const glm::vec3 c10 = texel255(r0, t.x1);
    const glm::vec3 c01 = texel255(r1, t.x0);
    const glm::vec3 c11 = texel255(r1, t.x1);
    const glm::vec3 top = c00 + (c10 - c00) * t.fx;
    const glm::vec3 bottom = c01 + (c11 - c01) * t.fx;
    return top + (bottom - top) * t.fy;
}

/// Trilinear filtering's two levels: ⌊λ⌋ and ⌊λ⌋ + 1 mixed by `fraction` (λ clamped to the
/// chain, NaN as 0); a fraction of 0 reads level `first` only.
struct TrilinearLevels {
    int first;
    float fraction;
};

/// The levels trilinear filtering reads at level of detail `lod`.
[[gnu::always_inline]] inline TrilinearLevels trilinearLevels(const Texture& tex, float lod) {
    const float last = static_cast<float>(tex.levelCount() - 1);
    const float l = lod > 0.0f ? std::min(lod, last) : 0.0f;  // NaN → 0
    const int l0 = static_cast<int>(l);
    return {l0, l - static_cast<float>(l0)};
}

}  // namespace detail

/// Nearest filtering's texel on level 0: (⌊u'·W⌋, ⌊v'·H⌋) clamped to the image.
[[gnu::always_inline]] inline glm::ivec2 nearestTexel(const Texture& tex, glm::vec2 uv) {
    const MipLevel& l0 = tex.level(0);
    // wrapCoord is in [0, 1], so the products are in [0, size]: the casts are defined and
    // truncation is floor; only 1.0 needs the clamp.
    return {
        std::min(static_cast<int>(wrapCoord(uv.x) * static_cast<float>(l0.width)), l0.width - 1),
        std::min(static_cast<int>(wrapCoord(uv.y) * static_cast<float>(l0.height)), l0.height - 1)};
}

/// Nearest filtering: the colour of nearestTexel().
[[gnu::always_inline]] inline glm::vec3 sampleNearest(const Texture& tex, glm::vec2 uv) {
    const glm::ivec2 t = nearestTexel(tex, uv);
    return texelColor(tex.level(0), t.x, t.y);
}

/// Bilinear filtering on one level (clamped to the chain), texel centres at ((i+½)/W, (j+½)/H),
/// neighbours wrapping around the edges.
[[gnu::always_inline]] inline glm::vec3 sampleBilinear(const Texture& tex, glm::vec2 uv,
                                                       int level = 0) {
    const int l = std::clamp(level, 0, tex.levelCount() - 1);
    return detail::bilinear255(tex.level(l), wrapCoord(uv.x), wrapCoord(uv.y)) * (1.0f / 255.0f);
}

/// Level of detail λ = log2 ρ, ρ = max(|(∂u/∂x·W, ∂v/∂x·H)|, |(∂u/∂y·W, ∂v/∂y·H)|) with W, H
/// the size of level 0, clamped to [0, levelCount − 1]; a NaN derivative gives 0.
[[gnu::always_inline]] inline float mipLevel(const Texture& tex, glm::vec2 duvDx, glm::vec2 duvDy) {
    const float w = static_cast<float>(tex.width());
    const float h = static_cast<float>(tex.height());
    const float ax = duvDx.x * w, ay = duvDx.y * h;
    const float bx = duvDy.x * w, by = duvDy.y * h;
    const float la = ax * ax + ay * ay;
    const float lb = bx * bx + by * by;
    if (!(la + lb >= 0.0f)) return 0.0f;  // a NaN in either (std::max would drop one of them)
    // log2 of the squared length, halved: no square root, same value.
    const float lod = 0.5f * std::log2(std::max(la, lb));
    if (!(lod > 0.0f)) return 0.0f;  // also −inf from zero derivatives
    return std::min(lod, static_cast<float>(tex.levelCount() - 1));
}

/// Trilinear filtering: bilinear on levels ⌊λ⌋ and ⌊λ⌋+1 mixed by the fraction of λ (clamped as
/// mipLevel() does). An integer λ samples that one level only, so λ ≤ 0 is sampleBilinear().
[[gnu::always_inline]] inline glm::vec3 sampleTrilinear(const Texture& tex, glm::vec2 uv,
                                                        float lod) {
    const float wu = wrapCoord(uv.x);
    const float wv = wrapCoord(uv.y);
    const detail::TrilinearLevels levels = detail::trilinearLevels(tex, lod);
    const float f = levels.fraction;
    const glm::vec3 c0 = detail::bilinear255(tex.level(levels.first), wu, wv);
    if (f == 0.0f) return c0 * (1.0f / 255.0f);
    const glm::vec3 c1 = detail::bilinear255(tex.level(levels.first + 1), wu, wv);
    return (c0 + (c1 - c0) * f) * (1.0f / 255.0f);
}

/// Trilinear filtering with λ from the screen-space derivatives of (u, v).
[[gnu::always_inline]] inline glm::vec3 sampleTrilinear(const Texture& tex, glm::vec2 uv,
                                                        glm::vec2 duvDx, glm::vec2 duvDy) {
    return sampleTrilinear(tex, uv, mipLevel(tex, duvDx, duvDy));
}

}  // namespace facet
