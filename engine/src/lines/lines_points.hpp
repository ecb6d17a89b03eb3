#pragma once
// Wireframe and vertex modes of the fast path: each edge near-clipped and walked with
// line_raster.hpp's Bresenham, each vertex a square; varyings interpolated along the line and
// shaded by the same fragment code as triangles. Templates over a Variant (shading/fragment.hpp).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "frontend/fetch.hpp"
#include "frontend/near_clip.hpp"
#include "lines/line_raster.hpp"
#include "shading/fragment.hpp"

namespace facet::detail {

/// Screen coordinates beyond this are not drawn as lines (their integer maths would overflow).
inline constexpr double kLineLimit = 1099511627776.0;  // 2^40

/// Wireframe: each listed edge once, near-clipped, Bresenham with interpolated varyings
/// (Subdivided is perspective-correct on lines). Texture lookups on lines use level 0.
template <class V>
void drawLines(const DrawInput& in, std::span<const std::uint32_t> edges, Framebuffer& fb,
               const DrawConstants& k, RenderStats& stats) {
    constexpr VaryingLayout L = V::kLayout;
    for (std::size_t e = 0; e + 1 < edges.size(); e += 2) {
        if (edges[e] >= in.clip.size() || edges[e + 1] >= in.clip.size()) continue;
        ClipVertex a = fetchVertex(in, L, edges[e]);
        ClipVertex b = fetchVertex(in, L, edges[e + 1]);
        if (!clipSegmentNear(a, b, in.nearPlane)) continue;
        const double ax = static_cast<double>(a.pos.x) / a.pos.w,
                     ay = static_cast<double>(a.pos.y) / a.pos.w;
        const double bx = static_cast<double>(b.pos.x) / b.pos.w,
                     by = static_cast<double>(b.pos.y) / b.pos.w;
        if (!(std::abs(ax) < kLineLimit && std::abs(ay) < kLineLimit && std::abs(bx) < kLineLimit &&
              std::abs(by) < kLineLimit))
            continue;
        ++stats.linesDrawn;
        const float ra = 1.0f / a.pos.w, rb = 1.0f / b.pos.w;
        forEachLinePixel(
            static_cast<std::int64_t>(std::floor(ax)), static_cast<std::int64_t>(std::floor(ay)),
            static_cast<std::int64_t>(std::floor(bx)), static_cast<std::int64_t>(std::floor(by)),
            fb.width, fb.height, [&](int x, int y, std::int64_t step, std::int64_t steps) {
                ++stats.fragments;
                const float t =
                    steps > 0 ? static_cast<float>(step) / static_cast<float>(steps) : 0.0f;
                const float wa = (1.0f - t) * ra, wb = t * rb;
                const float depth = 1.0f / (wa + wb);
                const std::size_t i = fb.index(x, y);
                if (!passesDepth<V::kShader>(fb, i, depth)) return;
                const float m = V::kInterp == Interp::Affine ? t : wb * depth;
                float v[V::kCount > 0 ? V::kCount : 1];
                for (std::size_t j = 0; j < static_cast<std::size_t>(V::kCount); ++j)
                    v[j] = a.a[j] + m * (b.a[j] - a.a[j]);
                storeFragment<V::kShader>(fb, i, depth, fragmentColor<V>(v, k, 0.0f));
            });
    }
}

/// Vertices: a pointSize square around the pixel holding each vertex in front of the near
/// plane, in the vertex's own colour (lit at the vertex for Phong, texel at its uv).
template <class V>
void drawPoints(const DrawInput& in, int pointSize, Framebuffer& fb, const DrawConstants& k,
                RenderStats& stats) {
    const int lo = -(pointSize - 1) / 2, hi = lo + pointSize - 1;
    for (std::size_t i = 0; i < in.clip.size(); ++i) {
        const glm::vec4& p = in.clip[i];
        if (!(p.w >= in.nearPlane) || !std::isfinite(p.x) || !std::isfinite(p.y)) continue;
        const double x = std::floor(static_cast<double>(p.x) / p.w),
                     y = std::floor(static_cast<double>(p.y) / p.w);
        if (x + hi < 0 || y + hi < 0 || x + lo >= fb.width || y + lo >= fb.height) continue;
        ++stats.pointsDrawn;
        const ClipVertex v = fetchVertex(in, V::kLayout, i);
        const glm::vec3 color = fragmentColor<V>(v.a.data(), k, 0.0f);
        const int px = static_cast<int>(x), py = static_cast<int>(y);
        for (int yy = std::max(0, py + lo); yy <= std::min(fb.height - 1, py + hi); ++yy)
            for (int xx = std::max(0, px + lo); xx <= std::min(fb.width - 1, px + hi); ++xx) {
                ++stats.fragments;
                const std::size_t j = fb.index(xx, yy);
                if (passesDepth<V::kShader>(fb, j, p.w))
                    storeFragment<V::kShader>(fb, j, p.w, color);
            }
    }
}

}  // namespace facet::detail
