#pragma once
// The per-vertex values a draw interpolates across its primitives ("varyings"), packed into one
// small float array so clipping and plane setup treat them uniformly. A layout says which are
// present: only what the settings and the mesh need is fetched and interpolated (an unlit,
// untextured draw of a mesh without colours interpolates nothing but depth).

#include <array>
#include <cstddef>
#include <string_view>
#include <type_traits>

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

/// One stream of packed varyings: `size` floats per vertex at `data`, or, for a stream the mesh
/// lacks (data null), `fill` for each of them.
struct VaryingStream {
    const float* data = nullptr;  ///< vertex i's floats at data[size·i …], or null
    int size = 0;                 ///< floats per vertex
    float fill = 0.0f;            ///< every float of a missing stream
};

/// The streams a layout asks for, in packed order: what fetchVaryings() copies, and what the
/// lanes stage (setup_lanes.cpp) gathers.
struct VaryingStreams {
    VaryingStream s[4];
    int count = 0;  ///< streams in s
};

/// The streams of `layout` in `in`. Missing streams give white, (0, 0) and zero normals, so a
/// layout never reads past a span.
inline VaryingStreams varyingStreams(const DrawInput& in, const VaryingLayout& layout) {
    static_assert(sizeof(glm::vec3) == 3 * sizeof(float) && sizeof(glm::vec2) == 2 * sizeof(float));
    VaryingStreams out;
    auto add = [&](const auto& span, int size, float fill) {
        out.s[out.count++] = {span.empty() ? nullptr : &span[0][0], size, fill};
    };
    if (layout.color) add(in.colors, 3, 1.0f);
    if (layout.uv) add(in.uvs, 2, 0.0f);
    if (layout.phong) {
        add(in.normals, 3, 0.0f);
        add(in.positions, 3, 0.0f);
    }
    return out;
}

/// Writes vertex i's varyings of `streams` to `a`, packed (their sizes summed: layout.count()).
inline void fetchVaryings(const VaryingStreams& streams, std::size_t i, float* a) {
    for (int k = 0; k < streams.count; ++k) {
        const VaryingStream& s = streams.s[k];
        // Sizes 2 and 3 spelt out: copies the compiler unrolls, no call to memmove per vertex.
        auto put = [&](auto size) {
            for (int c = 0; c < size; ++c)
                a[c] =
                    s.data != nullptr
                        ? s.data[static_cast<std::size_t>(size()) * i + static_cast<std::size_t>(c)]
                        : s.fill;
            a += size;
        };
        if (s.size == 3)
            put(std::integral_constant<int, 3>{});
        else
            put(std::integral_constant<int, 2>{});
    }
}

/// Writes vertex i's varyings that the layout asks for to a[0 … layout.count()).
inline void fetchVaryings(const DrawInput& in, const VaryingLayout& layout, std::size_t i,
                          float* a) {
    fetchVaryings(varyingStreams(in, layout), i, a);
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
