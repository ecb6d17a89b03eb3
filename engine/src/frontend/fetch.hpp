#pragma once
// The per-vertex values a draw interpolates across its primitives ("varyings"), packed into one
// small float array so clipping and plane setup treat them uniformly. A layout says which are
// present: only what the settings and the mesh need is fetched and interpolated (an unlit,
// untextured draw of a mesh without colours interpolates nothing but depth).

#include <array>
#include <cstddef>
#include <string_view>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/advanced/draw.hpp"

namespace facet::detail {

/// rgb (3) + uv (2) + normal (3) + world position (3).
inline constexpr int kMaxVaryings = 11;

/// Which varyings a draw carries, and where each sits in the packed array.
struct VaryingLayout {
    bool color = false;  ///< per-vertex (possibly Gouraud-lit) rgb
    bool uv = false;     ///< texture coordinates
    bool phong = false;  ///< world normal and world position for per-pixel lighting

    constexpr int colorAt() const { return 0; }
    constexpr int uvAt() const { return color ? 3 : 0; }
    constexpr int normalAt() const { return uvAt() + (uv ? 2 : 0); }
    constexpr int positionAt() const { return normalAt() + (phong ? 3 : 0); }
    constexpr int count() const { return positionAt() + (phong ? 3 : 0); }
    /// Space-separated names for --stats, depth (as 1/w) first.
    constexpr std::string_view names() const {
        // One literal per layout: the names live as long as the program.
        constexpr std::string_view kNames[8] = {"1/w",        "1/w rgb",       "1/w uv",
                                                "1/w rgb uv", "1/w n p",       "1/w rgb n p",
                                                "1/w uv n p", "1/w rgb uv n p"};
        return kNames[(color ? 1 : 0) + (uv ? 2 : 0) + (phong ? 4 : 0)];
    }
};

/// A vertex as the clipper and plane setup see it: clip position and packed varyings.
struct ClipVertex {
    glm::vec4 pos;
    std::array<float, kMaxVaryings> a;
};

/// Writes vertex i's varyings that the layout asks for to a[0 … layout.count()). Missing
/// streams give white, (0, 0) and zero normals, so a layout never reads past a span.
inline void fetchVaryings(const DrawInput& in, const VaryingLayout& layout, std::size_t i,
                          float* a) {
    auto put = [&](int at, const auto& value, int n) {
        for (int k = 0; k < n; ++k) a[at + k] = value[k];
    };
    if (layout.color) put(layout.colorAt(), in.colors.empty() ? glm::vec3(1.0f) : in.colors[i], 3);
    if (layout.uv) put(layout.uvAt(), in.uvs.empty() ? glm::vec2(0.0f) : in.uvs[i], 2);
    if (layout.phong) {
        put(layout.normalAt(), in.normals.empty() ? glm::vec3(0.0f) : in.normals[i], 3);
        put(layout.positionAt(), in.positions.empty() ? glm::vec3(0.0f) : in.positions[i], 3);
    }
}

/// Fetches vertex i's clip position and the varyings the layout asks for (fetchVaryings()).
inline ClipVertex fetchVertex(const DrawInput& in, const VaryingLayout& layout, std::size_t i) {
    ClipVertex v{in.clip[i], {}};
    fetchVaryings(in, layout, i, v.a.data());
    return v;
}

/// The same packed varyings as plain vectors, for the fragment stage.
inline glm::vec3 vec3At(const float* a, int at) {
    return {a[at], a[at + 1], a[at + 2]};
}

}  // namespace facet::detail
