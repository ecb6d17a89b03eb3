#pragma once
// Textures (conventions §7): an RGBA8 image with its mip chain, and the samplers the renderer
// calls per pixel. The fast samplers are inline here so a shading loop can inline them; the
// double-precision reference samplers below them are the executable reading of the conventions.
//
// Texels stay 8-bit (4 bytes each, a quarter of float storage, so more of the image stays in
// cache) and are widened to float per fetch. Filtering happens on the 0..255 values with a
// single scale by 1/255 at the end: a weight of exactly 0 or 1 then reproduces a texel bit for
// bit, so bilinear filtering at a texel centre returns that texel exactly (texelColor()).
//
// Non-finite coordinates (NaN, ±inf) wrap to 0, as does every float of magnitude ≥ 2^23 (all of
// which are integers). The level of detail maps NaN to 0 and +inf to the last level.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "facet/error.hpp"

namespace facet {

/// Largest accepted texture side, as for images (conventions §1).
inline constexpr int kMaxTextureSize = 16384;

/// One level of a mip chain: packed RGBA8 texels (R in the low byte, like Framebuffer::color),
/// row-major, row 0 at the top of the image.
struct MipLevel {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> texels;  ///< width * height entries

    /// The packed texel at (x, y); no bounds check.
    std::uint32_t at(int x, int y) const {
        return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
};

/// An image and its mip chain. A class because the samplers index texels without bounds checks:
/// only fromRgba() builds a chain, so every level is non-empty and holds width * height texels.
class Texture {
  public:
    /// A 1×1 white texture: neutral under "combine", and safe to sample when none was loaded.
    Texture();

    /// Builds a texture and its mip chain from packed RGBA8 pixels (row 0 at the top). Each
    /// level halves the previous one's sides (rounding down, never below 1) and every texel is
    /// the area-weighted mean of the source region it covers: the 2×2 box for even sides, a
    /// 3-tap box over 2.5, 1.5... texels for odd ones, so no source texel is skipped or doubled.
    /// Channels are averaged as stored (no sRGB decoding, like the rest of the colour maths)
    /// and rounded to nearest. `name` labels errors and the UI.
    static Result<Texture> fromRgba(int width, int height, std::vector<std::uint32_t> pixels,
                                    std::string name);

    /// Width of level 0.
    int width() const { return levels_.front().width; }
    /// Height of level 0.
    int height() const { return levels_.front().height; }
    /// Number of mip levels, 1 + floor(log2(max(width, height))).
    int levelCount() const { return static_cast<int>(levels_.size()); }
    /// Level i, 0 being the image itself; i must be in [0, levelCount()).
    const MipLevel& level(int i) const { return levels_[static_cast<std::size_t>(i)]; }
    /// The file (or label) the texture came from.
    const std::string& name() const { return name_; }

  private:
    std::vector<MipLevel> levels_;
    std::string name_;
};

/// Reads a PNG, JPEG, BMP or TGA file (through stb_image) as RGBA8 and builds its mip chain.
/// Missing, empty, corrupt or unsupported files and sides outside 1…16384 give an Error naming
/// the file.
Result<Texture> loadTexture(const std::string& path);

/// Repeat wrap, t − ⌊t⌋, in [0, 1]: exactly 1 only when a tiny negative t rounds up to it.
/// NaN, ±inf and |t| ≥ 2^23 (integers in float) give 0.
inline float wrapCoord(float t) {
    // The cast is only taken where it is defined; beyond 2^23 every float is an integer anyway.
    if (!(std::fabs(t) < 8388608.0f)) return 0.0f;
    const float w = t - static_cast<float>(static_cast<int>(t));  // exact: the fraction
    return w < 0.0f ? w + 1.0f : w;
}

/// The texel at (x, y) as an RGB colour in [0, 1]; what filtering returns at a texel centre.
inline glm::vec3 texelColor(const MipLevel& level, int x, int y) {
    const std::uint32_t p = level.at(x, y);
    return glm::vec3(static_cast<float>(p & 0xFFu), static_cast<float>((p >> 8) & 0xFFu),
                     static_cast<float>((p >> 16) & 0xFFu)) *
           (1.0f / 255.0f);
}

namespace detail {

/// A texel's RGB as 0..255 floats.
inline glm::vec3 texel255(const std::uint32_t* row, int x) {
    const std::uint32_t p = row[x];
    return {static_cast<float>(p & 0xFFu), static_cast<float>((p >> 8) & 0xFFu),
            static_cast<float>((p >> 16) & 0xFFu)};
}

/// Bilinear filtering of one level at already wrapped coordinates, in 0..255.
inline glm::vec3 bilinear255(const MipLevel& level, float wu, float wv) {
    const int w = level.width;
    const int h = level.height;
    // Texel centres sit at half-integers; x, y are in [−½, size − ½] since wu, wv are in [0, 1].
    const float x = wu * static_cast<float>(w) - 0.5f;
    const float y = wv * static_cast<float>(h) - 0.5f;
    int x0 = static_cast<int>(x);  // truncation; one less below 0 makes it floor
    int y0 = static_cast<int>(y);
    if (x < static_cast<float>(x0)) --x0;
    if (y < static_cast<float>(y0)) --y0;
    const float fx = x - static_cast<float>(x0);
    const float fy = y - static_cast<float>(y0);
    int x1 = x0 + 1;
    int y1 = y0 + 1;
    if (x0 < 0) x0 += w;
    if (y0 < 0) y0 += h;
    if (x1 >= w) x1 -= w;
    if (y1 >= h) y1 -= h;
    const std::uint32_t* r0 =
        level.texels.data() + static_cast<std::size_t>(y0) * static_cast<std::size_t>(w);
    const std::uint32_t* r1 =
        level.texels.data() + static_cast<std::size_t>(y1) * static_cast<std::size_t>(w);
    // a + (b − a)·f: exact at f = 0 and f = 1, and never above max(a, b).
    const glm::vec3 c00 = texel255(r0, x0);
    const glm::vec3 c10 = texel255(r0, x1);
    const glm::vec3 c01 = texel255(r1, x0);
    const glm::vec3 c11 = texel255(r1, x1);
    const glm::vec3 top = c00 + (c10 - c00) * fx;
    const glm::vec3 bottom = c01 + (c11 - c01) * fx;
    return top + (bottom - top) * fy;
}

}  // namespace detail

/// Nearest filtering on level 0: texel (⌊u'·W⌋, ⌊v'·H⌋) clamped to the image.
inline glm::vec3 sampleNearest(const Texture& tex, glm::vec2 uv) {
    const MipLevel& l0 = tex.level(0);
    // wrapCoord is in [0, 1], so the products are in [0, size]: the casts are defined and
    // truncation is floor; only 1.0 needs the clamp.
    const int x =
        std::min(static_cast<int>(wrapCoord(uv.x) * static_cast<float>(l0.width)), l0.width - 1);
    const int y =
        std::min(static_cast<int>(wrapCoord(uv.y) * static_cast<float>(l0.height)), l0.height - 1);
    return texelColor(l0, x, y);
}

/// Bilinear filtering on one level (clamped to the chain), texel centres at ((i+½)/W, (j+½)/H),
/// neighbours wrapping around the edges.
inline glm::vec3 sampleBilinear(const Texture& tex, glm::vec2 uv, int level = 0) {
    const int l = std::clamp(level, 0, tex.levelCount() - 1);
    return detail::bilinear255(tex.level(l), wrapCoord(uv.x), wrapCoord(uv.y)) * (1.0f / 255.0f);
}

/// Level of detail λ = log2 ρ, ρ = max(|(∂u/∂x·W, ∂v/∂x·H)|, |(∂u/∂y·W, ∂v/∂y·H)|) with W, H
/// the size of level 0, clamped to [0, levelCount − 1]; a NaN derivative gives 0.
inline float mipLevel(const Texture& tex, glm::vec2 duvDx, glm::vec2 duvDy) {
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
inline glm::vec3 sampleTrilinear(const Texture& tex, glm::vec2 uv, float lod) {
    const float wu = wrapCoord(uv.x);
    const float wv = wrapCoord(uv.y);
    const float last = static_cast<float>(tex.levelCount() - 1);
    const float l = lod > 0.0f ? std::min(lod, last) : 0.0f;  // NaN → 0
    const int l0 = static_cast<int>(l);
    const float f = l - static_cast<float>(l0);
    const glm::vec3 c0 = detail::bilinear255(tex.level(l0), wu, wv);
    if (f == 0.0f) return c0 * (1.0f / 255.0f);
    const glm::vec3 c1 = detail::bilinear255(tex.level(l0 + 1), wu, wv);
    return (c0 + (c1 - c0) * f) * (1.0f / 255.0f);
}

/// Trilinear filtering with λ from the screen-space derivatives of (u, v).
inline glm::vec3 sampleTrilinear(const Texture& tex, glm::vec2 uv, glm::vec2 duvDx,
                                 glm::vec2 duvDy) {
    return sampleTrilinear(tex, uv, mipLevel(tex, duvDx, duvDy));
}

}  // namespace facet

// The reference samplers: double precision, written straight from conventions §7 without any of
// the shortcuts above. The reference renderer uses them; tests hold the fast ones to them.
// Call them qualified (reference::sampleBilinear): argument-dependent lookup also finds the fast
// samplers, and GLM converts vec2 to dvec2 implicitly.
namespace facet::reference {

/// t − ⌊t⌋; non-finite t gives 0.
double wrapCoord(double t);

/// Texel (x, y) of a level as RGB in [0, 1].
glm::dvec3 texelColor(const MipLevel& level, int x, int y);

/// Nearest filtering on level 0.
glm::dvec3 sampleNearest(const Texture& tex, glm::dvec2 uv);

/// Bilinear filtering on one level (clamped to the chain).
glm::dvec3 sampleBilinear(const Texture& tex, glm::dvec2 uv, int level = 0);

/// Level of detail from the screen-space derivatives of (u, v), clamped to the chain.
double mipLevel(const Texture& tex, glm::dvec2 duvDx, glm::dvec2 duvDy);

/// Trilinear filtering at level of detail λ.
glm::dvec3 sampleTrilinear(const Texture& tex, glm::dvec2 uv, double lod);

}  // namespace facet::reference
