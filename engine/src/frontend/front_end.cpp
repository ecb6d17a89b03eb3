// The triangle front end (see front_end.hpp), one function per stage so the loop at the bottom
// reads as the pipeline does. Screen positions and planes are computed in double from the
// unsnapped vertices, so interpolation does not inherit the snapping error; only coverage uses
// the sub-pixel grid (1/256 px, or coarser with RenderSettings::subPixelBits).

#include "frontend/front_end.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "frontend/near_clip.hpp"

namespace facet::detail {
namespace {

/// Pixels beyond each image border inside which triangles are rasterized without 2D clipping.
/// Keeps snapped coordinates below 2^24 grid units, so edge products stay far below 2^63.
constexpr double kGuardBand = 32768.0;

/// What the fetch stage learnt of a triangle from its clip positions alone.
enum class Reach {
    Nowhere,      ///< non-finite, wholly behind the near plane, or wholly off one image side
    InFront,      ///< wholly in front of the near plane
    CrossesNear,  ///< partly behind it: the near clip runs
};

/// Stage 1, fetch and reject: only the clip positions are read, so the varyings of the many
/// triangles that cannot reach the screen are never fetched.
Reach classify(const DrawInput& in, const std::uint32_t (&idx)[3], float W, float H) {
    bool finite = true, allFront = true, anyFront = false;
    for (const std::uint32_t i : idx) {
        const glm::vec4& p = in.clip[i];
        finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.w);
        allFront = allFront && p.w >= in.nearPlane;
        anyFront = anyFront || p.w >= in.nearPlane;
    }
    if (!finite || !anyFront) return Reach::Nowhere;
    if (!allFront) return Reach::CrossesNear;
    auto all = [&](auto pred) {
        return pred(in.clip[idx[0]]) && pred(in.clip[idx[1]]) && pred(in.clip[idx[2]]);
    };
    if (all([](const glm::vec4& p) { return p.x < 0.0f; }) ||
        all([&](const glm::vec4& p) { return p.x > W * p.w; }) ||
        all([](const glm::vec4& p) { return p.y < 0.0f; }) ||
        all([&](const glm::vec4& p) { return p.y > H * p.w; }))
        return Reach::Nowhere;
    return Reach::InFront;
}

/// The screen rectangle inside which snapped coordinates stay exact.
struct GuardBand {
    glm::dvec2 lo, hi;
    bool contains(const glm::dvec2& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
    }
};

/// Stage 3, project: screen positions in double; true when all three are inside the guard band.
bool project(const glm::vec4 (&pos)[3], const GuardBand& guard, glm::dvec2 (&s)[3]) {
    bool inGuard = true;
    for (int j = 0; j < 3; ++j) {
        s[j] = screenPosition(pos[j]);
        inGuard = inGuard && guard.contains(s[j]);
    }
    return inGuard;
}

/// Stage 3, snap: the triangle a, b, c on the sub-pixel grid, its edges and pixel box set up
/// for coverage; the facing it returns is what the cull stage decides on.
Facing snap(const SnapGrid& grid, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c,
            const PixelRect& screen, CoverageSetup& setup, std::int64_t reach) {
    const std::int64_t xs[3] = {grid(a.x), grid(b.x), grid(c.x)};
    const std::int64_t ys[3] = {grid(a.y), grid(b.y), grid(c.y)};
    return setupCoverage(xs, ys, screen, setup, reach);
}

/// The pixel the planes are relative to: the triangle's top-left, clamped to the image.
void planeBase(const glm::dvec2 (&s)[3], float W, float H, int& baseX, int& baseY) {
    const double minX = std::min({s[0].x, s[1].x, s[2].x});
    const double minY = std::min({s[0].y, s[1].y, s[2].y});
    baseX = static_cast<int>(std::clamp(std::floor(minX), 0.0, W - 1.0));
    baseY = static_cast<int>(std::clamp(std::floor(minY), 0.0, H - 1.0));
}

}  // namespace

std::size_t drawTriangles(const DrawInput& in, const VaryingLayout& layout, bool cull, int width,
                          int height, std::size_t first, std::size_t end, RasterizeFn emit,
                          void* context, RenderStats& stats, int subPixelBits, int sampleReach) {
    const SnapGrid grid = SnapGrid::ofBits(subPixelBits);
    const PixelRect screen{0, 0, width - 1, height - 1};
    const GuardBand guard{{-kGuardBand, -kGuardBand}, {width + kGuardBand, height + kGuardBand}};
    const float W = static_cast<float>(width), H = static_cast<float>(height);
    const std::size_t nv = in.clip.size();
    const int count = layout.count();
    Planes planes;
    std::size_t fragments = 0;
    end = std::min(end, in.indices.size() / 3);

    for (std::size_t t = 3 * first; t < 3 * end; t += 3) {
        // 1. Fetch and reject.
        const std::uint32_t idx[3] = {in.indices[t], in.indices[t + 1], in.indices[t + 2]};
        if (idx[0] >= nv || idx[1] >= nv || idx[2] >= nv) continue;
        ++stats.trianglesIn;
        const Reach reach = classify(in, idx, W, H);
        if (reach == Reach::Nowhere) continue;
        bool clipped = reach == Reach::CrossesNear, culled = false, drawn = false;

        // One triangle of the fan: `vertices()` gives its clip vertices with their varyings,
        // asked for only when the planes are built.
        auto drawPart = [&](const glm::vec4(&pos)[3], auto&& vertices) {
            // 3. Project.
            glm::dvec2 s[3];
            const bool inGuard = project(pos, guard, s);
            int baseX = 0, baseY = 0;
            planeBase(s, W, H, baseX, baseY);

            if (inGuard) {
                // 3. Snap, 4. cull, 5. planes: only for triangles that cover a pixel centre,
                // since most triangles of a dense mesh cover none and the planes (and the
                // varyings they need) cost more than the coverage test.
                CoverageSetup setup;
                const Facing facing = snap(grid, s[0], s[1], s[2], screen, setup, sampleReach);
                if (facing == Facing::Degenerate) return;
                if (cull && facing == Facing::Back) {
                    culled = true;
                    return;
                }
                drawn = true;
                if (!setup.box.empty() && makePlanes(s, vertices(), count, baseX, baseY, planes))
                    fragments += emit(context, setup, planes);
                return;
            }
            // Beyond the guard band: 5. planes of the whole triangle, 4. cull, then the screen
            // triangle is clipped to the band for coverage only (3. snap per part), so
            // interpolation is unchanged.
            if (!makePlanes(s, vertices(), count, baseX, baseY, planes)) return;
            clipped = true;
            if (cull && signedArea2(s) > 0.0) {
                culled = true;
                return;
            }
            const ScreenPolygon cover = clipToRect(s, guard.lo, guard.hi);
            for (std::size_t j = 1; j + 1 < cover.size; ++j) {
                CoverageSetup setup;
                if (snap(grid, cover.v[0], cover.v[j], cover.v[j + 1], screen, setup,
                         sampleReach) == Facing::Degenerate)
                    continue;
                drawn = true;
                if (!setup.box.empty()) fragments += emit(context, setup, planes);
            }
        };

        const glm::vec4 pos[3] = {in.clip[idx[0]], in.clip[idx[1]], in.clip[idx[2]]};
        auto fetch = [&](ClipVertex(&v)[3]) {
            for (int j = 0; j < 3; ++j) v[j] = fetchVertex(in, layout, idx[j]);
        };
        if (reach == Reach::InFront) {
            // No copies: the triangle is its own fan, its varyings fetched on demand.
            ClipVertex v[3];
            drawPart(pos, [&]() -> const ClipVertex(&)[3] {
                fetch(v);
                return v;
            });
        } else {
            // 2. Near clip: a fan of one or two triangles.
            ClipVertex v[3];
            fetch(v);
            const NearPolygon poly = clipNear(v, in.nearPlane);
            for (std::size_t k = 1; k + 1 < poly.size; ++k) {
                const ClipVertex tri[3] = {poly.v[0], poly.v[k], poly.v[k + 1]};
                const glm::vec4 fanPos[3] = {tri[0].pos, tri[1].pos, tri[2].pos};
                drawPart(fanPos, [&]() -> const ClipVertex(&)[3] { return tri; });
            }
        }
        stats.trianglesClipped += clipped ? 1 : 0;
        stats.trianglesCulled += (culled && !drawn) ? 1 : 0;
        stats.trianglesRasterized += drawn ? 1 : 0;
    }
    return fragments;
}

}  // namespace facet::detail
