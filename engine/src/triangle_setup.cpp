// The triangle front end (see triangle_setup.hpp). Screen positions and planes are computed in
// double from the unsnapped vertices, so interpolation does not inherit the snapping error; only
// coverage uses the sub-pixel grid (1/256 px, or coarser with RenderSettings::subPixelBits).

#include "triangle_setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "clip.hpp"

namespace facet::detail {
namespace {

/// Pixels beyond each image border inside which triangles are rasterized without 2D clipping.
/// Keeps snapped coordinates below 2^24 grid units, so edge products stay far below 2^63.
constexpr double kGuardBand = 32768.0;

/// Twice the signed area of a screen triangle; positive means back-facing (y-down pixels).
double signedArea2(const glm::dvec2 (&s)[3]) {
    return (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[1].y - s[0].y) * (s[2].x - s[0].x);
}

void setPlane(float (&dst)[3], double c, double a, double b) {
    dst[0] = static_cast<float>(c);
    dst[1] = static_cast<float>(a);
    dst[2] = static_cast<float>(b);
}

/// Builds the planes; returns false for a degenerate triangle.
bool makePlanes(const glm::dvec2 (&s)[3], const ClipVertex (&v)[3], int count, int baseX, int baseY,
                Planes& p) {
    const double area = signedArea2(s);
    if (!(area != 0.0) || !std::isfinite(area)) return false;
    const double bx = baseX + 0.5, by = baseY + 0.5;
    const double l1 =
        ((s[0].x - s[2].x) * (by - s[2].y) - (s[0].y - s[2].y) * (bx - s[2].x)) / area;
    const double l2 =
        ((s[1].x - s[0].x) * (by - s[0].y) - (s[1].y - s[0].y) * (bx - s[0].x)) / area;
    const double l1x = -(s[0].y - s[2].y) / area, l1y = (s[0].x - s[2].x) / area;
    const double l2x = -(s[1].y - s[0].y) / area, l2y = (s[1].x - s[0].x) / area;
    const double r0 = 1.0 / v[0].pos.w, r1 = 1.0 / v[1].pos.w, r2 = 1.0 / v[2].pos.w;
    p.baseX = baseX;
    p.baseY = baseY;
    setPlane(p.l1, l1, l1x, l1y);
    setPlane(p.l2, l2, l2x, l2y);
    setPlane(p.u1, l1 * r1, l1x * r1, l1y * r1);
    setPlane(p.u2, l2 * r2, l2x * r2, l2y * r2);
    setPlane(p.q, r0 + l1 * (r1 - r0) + l2 * (r2 - r0), l1x * (r1 - r0) + l2x * (r2 - r0),
             l1y * (r1 - r0) + l2y * (r2 - r0));
    for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
        p.a0[k] = v[0].a[k];
        p.d1[k] = v[1].a[k] - v[0].a[k];
        p.d2[k] = v[2].a[k] - v[0].a[k];
    }
    return true;
}

}  // namespace

std::size_t drawTriangles(const DrawInput& in, const VaryingLayout& layout, bool cull, int width,
                          int height, std::size_t first, std::size_t end, RasterizeFn emit,
                          void* context, RenderStats& stats, int subPixelBits) {
    const SnapGrid grid = SnapGrid::ofBits(subPixelBits);
    const PixelRect screen{0, 0, width - 1, height - 1};
    const glm::dvec2 guardLo(-kGuardBand, -kGuardBand);
    const glm::dvec2 guardHi(width + kGuardBand, height + kGuardBand);
    const float W = static_cast<float>(width), H = static_cast<float>(height);
    const std::size_t nv = in.clip.size();
    const int count = layout.count();
    Planes planes;
    std::size_t fragments = 0;
    end = std::min(end, in.indices.size() / 3);

    for (std::size_t t = 3 * first; t < 3 * end; t += 3) {
        const std::uint32_t idx[3] = {in.indices[t], in.indices[t + 1], in.indices[t + 2]};
        if (idx[0] >= nv || idx[1] >= nv || idx[2] >= nv) continue;
        ++stats.trianglesIn;
        bool finite = true, allFront = true, anyFront = false;
        for (const std::uint32_t i : idx) {
            const glm::vec4& p = in.clip[i];
            finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.w);
            allFront = allFront && p.w >= in.nearPlane;
            anyFront = anyFront || p.w >= in.nearPlane;
        }
        if (!finite || !anyFront) continue;
        if (allFront) {  // whole triangle off one side of the image: nothing to do
            auto all = [&](auto pred) {
                return pred(in.clip[idx[0]]) && pred(in.clip[idx[1]]) && pred(in.clip[idx[2]]);
            };
            if (all([](const glm::vec4& p) { return p.x < 0.0f; }) ||
                all([&](const glm::vec4& p) { return p.x > W * p.w; }) ||
                all([](const glm::vec4& p) { return p.y < 0.0f; }) ||
                all([&](const glm::vec4& p) { return p.y > H * p.w; }))
                continue;
        }
        // Varyings are fetched only for triangles that may reach the screen.
        const ClipVertex v[3] = {fetchVertex(in, layout, idx[0]), fetchVertex(in, layout, idx[1]),
                                 fetchVertex(in, layout, idx[2])};
        const NearPolygon poly =
            allFront ? NearPolygon{{v[0], v[1], v[2]}, 3} : clipNear(v, in.nearPlane);
        bool clipped = !allFront, culled = false, drawn = false;

        for (std::size_t k = 1; k + 1 < poly.size; ++k) {
            const ClipVertex tri[3] = {poly.v[0], poly.v[k], poly.v[k + 1]};
            glm::dvec2 s[3];
            bool inGuard = true;
            for (int j = 0; j < 3; ++j) {
                s[j] = glm::dvec2(tri[j].pos.x, tri[j].pos.y) / static_cast<double>(tri[j].pos.w);
                inGuard = inGuard && s[j].x >= guardLo.x && s[j].x <= guardHi.x &&
                          s[j].y >= guardLo.y && s[j].y <= guardHi.y;
            }
            // Planes are built only for triangles that cover a pixel centre: most triangles of
            // a dense mesh cover none, and the planes cost more than the coverage test.
            const double minX = std::min({s[0].x, s[1].x, s[2].x});
            const double minY = std::min({s[0].y, s[1].y, s[2].y});
            const int baseX = static_cast<int>(std::clamp(std::floor(minX), 0.0, W - 1.0));
            const int baseY = static_cast<int>(std::clamp(std::floor(minY), 0.0, H - 1.0));

            if (inGuard) {
                const std::int64_t xs[3] = {grid(s[0].x), grid(s[1].x), grid(s[2].x)};
                const std::int64_t ys[3] = {grid(s[0].y), grid(s[1].y), grid(s[2].y)};
                CoverageSetup setup;
                const Facing facing = setupCoverage(xs, ys, screen, setup);
                if (facing == Facing::Degenerate) continue;
                if (cull && facing == Facing::Back) {
                    culled = true;
                    continue;
                }
                drawn = true;
                if (!setup.box.empty() && makePlanes(s, tri, count, baseX, baseY, planes))
                    fragments += emit(context, setup, planes);
                continue;
            }
            if (!makePlanes(s, tri, count, baseX, baseY, planes)) continue;
            // Beyond the guard band: clip the screen triangle to it for coverage only; the
            // planes above still describe the whole triangle, so interpolation is unchanged.
            clipped = true;
            if (cull && signedArea2(s) > 0.0) {
                culled = true;
                continue;
            }
            const ScreenPolygon cover = clipToRect(s, guardLo, guardHi);
            for (std::size_t j = 1; j + 1 < cover.size; ++j) {
                const std::int64_t xs[3] = {grid(cover.v[0].x), grid(cover.v[j].x),
                                            grid(cover.v[j + 1].x)};
                const std::int64_t ys[3] = {grid(cover.v[0].y), grid(cover.v[j].y),
                                            grid(cover.v[j + 1].y)};
                CoverageSetup setup;
                if (setupCoverage(xs, ys, screen, setup) == Facing::Degenerate) continue;
                drawn = true;
                if (!setup.box.empty()) fragments += emit(context, setup, planes);
            }
        }
        stats.trianglesClipped += clipped ? 1 : 0;
        stats.trianglesCulled += (culled && !drawn) ? 1 : 0;
        stats.trianglesRasterized += drawn ? 1 : 0;
    }
    return fragments;
}

}  // namespace facet::detail
