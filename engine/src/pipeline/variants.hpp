#pragma once
// Picking the pipeline variant once per draw: the settings reduced to what changes the pixel
// loop (a VariantKey), and dispatch() turning that runtime key into a compile-time Variant
// (shading/fragment.hpp). Only meaningful combinations are instantiated.

#include <type_traits>

#include "facet/advanced/draw.hpp"
#include "facet/settings.hpp"
#include "frontend/fetch.hpp"
#include "shading/fragment.hpp"

namespace facet::detail {

/// The runtime description of a variant, reduced to what matters for the shader so that
/// settings that change nothing map to the same instantiation.
struct VariantKey {
    ShaderKind shader;
    Interp interp;
    VaryingLayout layout;
    TextureFilter filter;
    bool combine;
};

/// Whether vertex colour (and so lighting) shows: not in a depth image or a bare texel.
inline bool usesColor(const RenderSettings& s) {
    return s.shader != ShaderKind::Depth && (s.shader != ShaderKind::Texture || s.combine);
}

inline VariantKey variantKey(const RenderSettings& s, const DrawInput& in) {
    const bool texture = s.shader == ShaderKind::Texture;
    VariantKey k{
        s.shader, s.interp, {}, texture ? s.filter : TextureFilter::Nearest, texture && s.combine};
    k.layout.color = usesColor(s) && !in.colors.empty();
    k.layout.uv = texture;
    k.layout.phong = usesColor(s) && s.lighting == Lighting::Phong && !in.normals.empty();
    return k;
}

template <class E, E... Values, class Fn>
void withEnum(E value, Fn&& fn) {
    ((value == Values ? (fn(std::integral_constant<E, Values>{}), 0) : 0), ...);
}

template <class Fn>
void withBool(bool value, Fn&& fn) {
    if (value)
        fn(std::true_type{});
    else
        fn(std::false_type{});
}

/// Calls fn with the Variant type for `key`; only meaningful combinations are instantiated.
template <class Fn>
void dispatch(const VariantKey& key, Fn&& fn) {
    withEnum<Interp, Interp::Affine, Interp::Subdivided,
             Interp::Perspective>(key.interp, [&](auto interp) {
        constexpr Interp I = decltype(interp)::value;
        constexpr TextureFilter N = TextureFilter::Nearest;
        auto colored = [&](auto shader) {
            constexpr ShaderKind S = decltype(shader)::value;
            withBool(key.layout.color, [&](auto c) {
                withBool(key.layout.phong, [&](auto ph) {
                    fn(Variant<S, I, decltype(c)::value, false, decltype(ph)::value, N, false>{});
                });
            });
        };
        switch (key.shader) {
            case ShaderKind::Simple:
                colored(std::integral_constant<ShaderKind, ShaderKind::Simple>{});
                break;
            case ShaderKind::Painter:
                colored(std::integral_constant<ShaderKind, ShaderKind::Painter>{});
                break;
            case ShaderKind::Depth:
                fn(Variant<ShaderKind::Depth, I, false, false, false, N, false>{});
                break;
            case ShaderKind::Texture:
                withEnum<TextureFilter, TextureFilter::Nearest, TextureFilter::Bilinear,
                         TextureFilter::Trilinear>(key.filter, [&](auto filter) {
                    constexpr TextureFilter F = decltype(filter)::value;
                    constexpr ShaderKind T = ShaderKind::Texture;
                    if (!key.combine) {
                        fn(Variant<T, I, false, true, false, F, false>{});
                        return;
                    }
                    withBool(key.layout.color, [&](auto c) {
                        withBool(key.layout.phong, [&](auto ph) {
                            fn(Variant<T, I, decltype(c)::value, true, decltype(ph)::value, F,
                                       true>{});
                        });
                    });
                });
                break;
        }
    });
}

}  // namespace facet::detail
