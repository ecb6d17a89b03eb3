#pragma once
// The fragment stage of the fast path: what colour a fragment gets and how it is written.
// A pipeline variant (shader, interpolation, varyings, filter, combine) is a type, so every
// branch on the settings below is resolved at compile time and the per-pixel code is straight.

#include <cstddef>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "binning/tile_buffer.hpp"
#include "facet/framebuffer.hpp"
#include "facet/settings.hpp"
#include "frontend/fetch.hpp"
#include "frontend/front_end.hpp"
#include "shading/fast_lighting.hpp"
#include "shading/samplers.hpp"
#include "shading/unit_pow.hpp"

namespace facet::detail {

/// One pipeline variant as compile-time constants.
template <ShaderKind S, Interp I, bool Color, bool Uv, bool Phong, TextureFilter F, bool Combine>
struct Variant {
    static constexpr ShaderKind kShader = S;
    static constexpr Interp kInterp = I;
    static constexpr VaryingLayout kLayout{Color, Uv, Phong};
    static constexpr int kCount = kLayout.count();
    static constexpr TextureFilter kFilter = F;
    static constexpr bool kCombine = Combine;
    /// Only trilinear filtering needs the screen-space derivatives of (u, v).
    static constexpr bool kDerivatives = S == ShaderKind::Texture && F == TextureFilter::Trilinear;
};

/// The 1×1 white texture a draw samples when it has none (neutral under "combine").
inline const Texture& whiteTexture() {
    static const Texture white;
    return white;
}

/// Rounds a colour to 8 bits per channel as spec §5 says; NaN becomes 0.
inline std::uint32_t toByte(float c) {
    const float v = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
    return static_cast<std::uint32_t>(v * 255.0f + 0.5f);
}
inline std::uint32_t packColor(const glm::vec3& c) {
    return packRgba(toByte(c.r), toByte(c.g), toByte(c.b));
}

/// What every fragment of a draw shares.
struct DrawConstants {
    const Texture* texture = nullptr;  ///< never null inside the stage (white when none)
    FastLighting lighting;
    glm::vec3 eye{0.0f};
    glm::vec3 baseColor{1.0f};  ///< the colour when the layout has none (white; red for normals)
    /// baseColor packed, once per draw: the colour of every pixel of a variant without varyings.
    std::uint32_t basePacked = packColor(baseColor);
    /// Where the vector loops' Phong lighting may leave out the specular power, once per draw.
    SpecularSkip specularSkip =
        detail::specularSkip(lighting.diffuse, lighting.specular, lighting.shininess);
};

struct RasterContext;

/// A vector pixel loop of one variant and SIMD target (span_loop-inl.hpp): covers `setup` and
/// shades with `planes` into `target` (the frame or a tile buffer); returns the pixels covered.
/// Picked once per draw.
using PixelLoopFn = std::size_t (*)(const RasterContext& ctx, const CoverageSetup& setup,
                                    const Planes& planes, const PixelTarget& target);

/// What a variant's triangle rasterizer needs besides the triangle; shared, read-only, by the
/// threads that rasterize disjoint tiles.
struct RasterContext {
    Framebuffer* fb;  ///< the frame; the tile renderer passes each tile's PixelTarget
    const DrawConstants* constants;
    int subdivision;  ///< N of Interp::Subdivided
    /// The variant's span loop for the SIMD target picked for this draw; null: scalar only.
    PixelLoopFn spans = nullptr;
    /// The variant's block loop (small triangles) for the same target; null: scalar only.
    PixelLoopFn blocks = nullptr;
};

/// Rounds a colour to 8 bits per channel as spec §5 says (facet::toByte); NaN becomes 0.
/// True when the shader tests and writes depth (LESS).
constexpr bool depthTested(ShaderKind s) {
    return s != ShaderKind::Simple;
}

/// The depth test alone, before any shading is paid for (early depth): same result as testing
/// after shading, since shading has no side effects. `fb`: a Framebuffer or a PixelTarget.
template <ShaderKind S, class Pixels>
inline bool passesDepth(const Pixels& fb, std::size_t i, float depth) {
    if constexpr (depthTested(S)) return depth < fb.depth[i];
    return true;
}

/// Stores a fragment that passed passesDepth() (into a Framebuffer or a PixelTarget).
template <ShaderKind S, class Pixels>
inline void storeFragment(Pixels& fb, std::size_t i, float depth, const glm::vec3& color) {
    if constexpr (depthTested(S)) fb.depth[i] = depth;
    if constexpr (S != ShaderKind::Depth) fb.color[i] = packColor(color);
}

/// A texel through the variant's filter; `lod` matters for trilinear only. Always inlined, like
/// the samplers (samplers.hpp says why): the vector loops call it on their few-lane blocks.
template <TextureFilter F>
[[gnu::always_inline]] inline glm::vec3 sampleTexture(const Texture& tex, glm::vec2 uv, float lod) {
    if constexpr (F == TextureFilter::Nearest) return sampleNearest(tex, uv);
    if constexpr (F == TextureFilter::Bilinear) return sampleBilinear(tex, uv);
    if constexpr (F == TextureFilter::Trilinear) return sampleTrilinear(tex, uv, lod);
}

/// unitPow() as a function object: the specular power of per-pixel (Phong) lighting, the same
/// function the span loop runs on every lane.
struct UnitPow {
    float operator()(float x, float s) const { return unitPow(x, s); }
};

/// The colour of a fragment from its interpolated varyings (spec §6, §7): vertex or
/// Gouraud colour as interpolated; Phong lights the interpolated normal here (phongTerms()); the
/// texture shader returns the texel, times that colour with "combine". Always inlined, so that
/// the vector loops' few-lane fallback runs it compiled for their target (samplers.hpp).
template <class V>
[[gnu::always_inline]] inline glm::vec3 fragmentColor(const float* a, const DrawConstants& k,
                                                      float lod) {
    constexpr VaryingLayout L = V::kLayout;
    glm::vec3 rgb = k.baseColor;
    if constexpr (L.color) rgb = vec3At(a, L.colorAt());
    if constexpr (L.phong) {
        const LightTerms t = phongTerms(vec3At(a, L.positionAt()), vec3At(a, L.normalAt()), k.eye,
                                        k.lighting, UnitPow{});
        rgb = shade(rgb, t.intensity);
    }
    if constexpr (V::kShader == ShaderKind::Texture) {
        const glm::vec3 texel =
            sampleTexture<V::kFilter>(*k.texture, {a[L.uvAt()], a[L.uvAt() + 1]}, lod);
        if constexpr (V::kCombine) return texel * rgb;
        return texel;
    }
    return rgb;
}

}  // namespace facet::detail
