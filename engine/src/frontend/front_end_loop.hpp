#pragma once
// The triangle front end's loop (see front_end.hpp), one function per stage so the loop at the
// bottom reads as the pipeline does. A template on what receives its triangles, so that the tile
// renderer's binning is a typed call (none through a pointer and a void* per triangle) and
// data flows one way: front end -> binning -> coverage -> shading. Screen positions and planes are
// computed in double from the unsnapped vertices, so interpolation does not inherit the snapping
// error; only coverage uses the sub-pixel grid (1/256 px, or coarser with
// RenderSettings::subPixelBits).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "frontend/front_end.hpp"
#include "frontend/near_clip.hpp"

namespace facet::detail::front {

/// How many triangles ahead the front end asks for vertex data (see frontEnd()).
inline constexpr std::size_t kPrefetch = 12;

/// What the fetch stage learnt of a triangle from its clip positions alone.
enum class Reach {
    Nowhere,      ///< non-finite, wholly behind the near plane, or wholly off one image side
    InFront,      ///< wholly in front of the near plane
    CrossesNear,  ///< partly behind it: the near clip runs
};

/// Stage 1, reject: decided on the vertices' flags alone, so the varyings of the many
/// triangles that cannot reach the screen are never fetched.
inline Reach classify(const ScreenVertex* (&v)[3]) {
    const std::uint32_t all = v[0]->flags & v[1]->flags & v[2]->flags;
    const std::uint32_t any = v[0]->flags | v[1]->flags | v[2]->flags;
    if (!(all & ScreenVertex::kFinite) || !(any & ScreenVertex::kFront)) return Reach::Nowhere;
    if (!(all & ScreenVertex::kFront)) return Reach::CrossesNear;
    constexpr std::uint32_t kOutside =
        ScreenVertex::kLeft | ScreenVertex::kRight | ScreenVertex::kAbove | ScreenVertex::kBelow;
    return (all & kOutside) ? Reach::Nowhere : Reach::InFront;
}

/// Stage 3, snap (guard-band parts): the triangle a, b, c on the sub-pixel grid, wound and boxed
/// for coverage; the facing it returns is what the cull stage decides on.
inline Facing snap(const SnapGrid& grid, const glm::dvec2& a, const glm::dvec2& b,
                   const glm::dvec2& c, const PixelRect& screen, SnappedTriangle& out,
                   std::int64_t reach) {
    const std::int64_t xs[3] = {grid(a.x), grid(b.x), grid(c.x)};
    const std::int64_t ys[3] = {grid(a.y), grid(b.y), grid(c.y)};
    return snapTriangle(xs, ys, screen, out, reach);
}

/// Stage 3, snap, for vertices already on the grid (ScreenVertex::gx, gy).
inline Facing snapped(const ScreenVertex (&v)[3], const PixelRect& screen, SnappedTriangle& out,
                      std::int64_t reach) {
    const std::int64_t xs[3] = {v[0].gx, v[1].gx, v[2].gx};
    const std::int64_t ys[3] = {v[0].gy, v[1].gy, v[2].gy};
    return snapTriangle(xs, ys, screen, out, reach);
}

/// ⌊v⌋ clamped to [0, hi] (hi a whole number), as std::clamp(std::floor(v), 0.0, hi) gives it
/// for finite v, without the call to floor that baseline x86-64 (no SSE4.1 round) makes: the
/// profile showed it at 3 % of a frame. Truncation is the floor for v ≥ 0.
inline int floorClamped(double v, double hi) {
    if (!(v >= 0.0)) return 0;
    if (v >= hi) return static_cast<int>(hi);
    return static_cast<int>(v);
}

/// The pixel the planes are relative to: the triangle's top-left, clamped to the image.
inline void planeBase(const glm::dvec2 (&s)[3], float W, float H, int& baseX, int& baseY) {
    baseX = floorClamped(std::min({s[0].x, s[1].x, s[2].x}), W - 1.0);
    baseY = floorClamped(std::min({s[0].y, s[1].y, s[2].y}), H - 1.0);
}

/// Runs the front end over triangles [first, end) of `job` and calls emit(setup, planes)
/// (the coverage setup of a snapped triangle with a non-empty box, edgesOf(), and the planes of
/// the whole triangle, unclipped by the guard band) for each part that covers pixels; returns the
/// sum of what `emit` returned. Adds its counters to `stats`. drawTriangles() is this with a
/// rasterizer as `emit`. With job.lanes (and job.screen), chunks of triangles first take the lanes
/// stage, which settles most of them a vector at a time; the loop then visits only its survivors
/// and the triangles it leaves to the scalar stages below, in submission order, so the triangles
/// emitted and the counters are the same either way.
template <class Emit>
std::size_t frontEnd(const DrawJob& job, std::size_t first, std::size_t end, Emit&& emit,
                     RenderStats& stats) {
    const DrawInput& in = *job.in;
    const VaryingLayout& layout = job.layout;
    const bool cull = job.cull;
    const std::int64_t sampleReach = job.sampleReach;
    const ScreenVertex* screen = job.screen;
    const ScreenSpace space =
        ScreenSpace::of(job.width, job.height, in.nearPlane, job.subPixelBits);
    const PixelRect rect{0, 0, job.width - 1, job.height - 1};
    const std::size_t nv = in.clip.size();
    const int count = layout.count();
    Planes planes;
    CoverageSetup setup;
    std::size_t fragments = 0;
    end = std::min(end, in.indices.size() / 3);

    const VaryingStreams streams = varyingStreams(in, layout);
    auto fetch = [&](const std::uint32_t(&idx)[3], ClipVertex(&v)[3]) {
        for (int j = 0; j < 3; ++j) {
            v[j].pos = in.clip[idx[j]];
            fetchVaryings(streams, idx[j], v[j].a.data());
        }
    };
    // 5. Planes of a triangle in the guard band that covers a pixel centre, then emit `setup`.
    auto planesAndEmit = [&](const ClipVertex(&v)[3]) {
        glm::dvec2 s[3];
        for (int j = 0; j < 3; ++j) s[j] = screenPosition(v[j].pos);
        int baseX = 0, baseY = 0;
        planeBase(s, space.W, space.H, baseX, baseY);
        if (makePlanes(s, v, count, baseX, baseY, planes)) fragments += emit(setup, planes);
    };

    // The scalar stages, one triangle.
    auto triangle = [&](std::size_t t) {
        // 1. Fetch and reject.
        const std::uint32_t idx[3] = {in.indices[t], in.indices[t + 1], in.indices[t + 2]};
        if (idx[0] >= nv || idx[1] >= nv || idx[2] >= nv) return;
        ++stats.trianglesIn;
        ScreenVertex own[3];
        const ScreenVertex* corner[3];
        for (int j = 0; j < 3; ++j) {
            if (screen) {
                corner[j] = screen + idx[j];
            } else {
                own[j] = space.vertex(in.clip[idx[j]]);
                corner[j] = own + j;
            }
        }
        const Reach reach = classify(corner);
        if (reach == Reach::Nowhere) return;
        bool clipped = reach == Reach::CrossesNear, culled = false, drawn = false;

        // One triangle of the fan: `sv` its screen vertices, `vertices()` its clip vertices
        // with their varyings, asked for only when the planes are built.
        auto drawPart = [&](const ScreenVertex(&sv)[3], auto&& vertices) {
            if (sv[0].flags & sv[1].flags & sv[2].flags & ScreenVertex::kInGuard) {
                // 3. Snap, 4. cull, 5. planes: only for triangles that cover a pixel centre,
                // since most triangles of a dense mesh cover none and the planes (and the
                // varyings they need) cost more than the coverage test.
                SnappedTriangle tri;
                const Facing facing = snapped(sv, rect, tri, sampleReach);
                if (facing == Facing::Degenerate) return;
                if (cull && facing == Facing::Back) {
                    culled = true;
                    return;
                }
                drawn = true;
                if (tri.box.empty() || (sampleReach == 0 && coversNoCentre(tri))) return;
                edgesOf(tri, setup);
                planesAndEmit(vertices());
                return;
            }
            // Beyond the guard band: 5. planes of the whole triangle, 4. cull, then the screen
            // triangle is clipped to the band for coverage only (3. snap per part), so
            // interpolation is unchanged.
            const ClipVertex(&v)[3] = vertices();
            glm::dvec2 s[3];
            for (int j = 0; j < 3; ++j) s[j] = screenPosition(v[j].pos);
            int baseX = 0, baseY = 0;
            planeBase(s, space.W, space.H, baseX, baseY);
            if (!makePlanes(s, v, count, baseX, baseY, planes)) return;
            clipped = true;
            if (cull && signedArea2(s) > 0.0) {
                culled = true;
                return;
            }
            const ScreenPolygon cover = clipToRect(s, space.lo, space.hi);
            for (std::size_t j = 1; j + 1 < cover.size; ++j) {
                SnappedTriangle tri;
                if (snap(space.grid, cover.v[0], cover.v[j], cover.v[j + 1], rect, tri,
                         sampleReach) == Facing::Degenerate)
                    continue;
                drawn = true;
                if (tri.box.empty()) continue;
                edgesOf(tri, setup);
                fragments += emit(setup, planes);
            }
        };

        if (reach == Reach::InFront) {
            // No copies: the triangle is its own fan, its varyings fetched on demand.
            const ScreenVertex sv[3] = {*corner[0], *corner[1], *corner[2]};
            ClipVertex v[3];
            drawPart(sv, [&]() -> const ClipVertex(&)[3] {
                fetch(idx, v);
                return v;
            });
        } else {
            // 2. Near clip: a fan of one or two triangles.
            ClipVertex v[3];
            fetch(idx, v);
            const NearPolygon poly = clipNear(v, in.nearPlane);
            for (std::size_t k = 1; k + 1 < poly.size; ++k) {
                const ClipVertex tri[3] = {poly.v[0], poly.v[k], poly.v[k + 1]};
                const ScreenVertex sv[3] = {space.vertex(tri[0].pos), space.vertex(tri[1].pos),
                                            space.vertex(tri[2].pos)};
                drawPart(sv, [&]() -> const ClipVertex(&)[3] { return tri; });
            }
        }
        stats.trianglesClipped += clipped ? 1 : 0;
        stats.trianglesCulled += (culled && !drawn) ? 1 : 0;
        stats.trianglesRasterized += drawn ? 1 : 0;
    };

    if (!(job.lanes && screen)) {
        for (std::size_t t = 3 * first; t < 3 * end; t += 3) {
            // The vertices of a mesh come in no useful order, so each corner's fetch would wait
            // on memory; asking for those of a triangle kPrefetch ahead hides that wait.
            if (t + 3 * kPrefetch < 3 * end) {
                for (std::size_t j = t + 3 * kPrefetch; j < t + 3 * kPrefetch + 3; ++j) {
                    const std::uint32_t i = in.indices[j];
                    if (i >= nv) continue;
                    __builtin_prefetch(in.clip.data() + i);
                    if (screen) __builtin_prefetch(screen + i);
                }
            }
            triangle(t);
        }
        return fragments;
    }

    const LaneInput lanes{in.indices.data(), nv,       screen,         job.width, job.height,
                          job.sampleReach,   job.cull, in.clip.data(), streams};
    LaneChunk chunk;
    for (std::size_t c = first; c < end; c += LaneChunk::kSize) {
        job.lanes(lanes, c, std::min(end, c + LaneChunk::kSize), chunk);
        stats.trianglesIn += chunk.trianglesIn;
        stats.trianglesCulled += chunk.trianglesCulled;
        stats.trianglesRasterized += chunk.trianglesRasterized;
        std::uint32_t survivor = 0;  // survivors before entry e (LaneChunk::planes)
        for (std::uint32_t e = 0; e < chunk.count; ++e) {
            // The clip positions of a triangle a few entries ahead (see kPrefetch); not needed
            // when the lanes built the planes (they read the clip positions already).
            if (!chunk.planes && e + kPrefetch / 2 < chunk.count) {
                const std::size_t ahead =
                    3 * (c + (chunk.at[e + kPrefetch / 2] & ~LaneChunk::kScalar));
                for (std::size_t j = ahead; j < ahead + 3; ++j)
                    if (in.indices[j] < nv) __builtin_prefetch(in.clip.data() + in.indices[j]);
            }
            const std::uint32_t k = chunk.at[e] & ~LaneChunk::kScalar;
            const std::size_t t = 3 * (c + k);
            if (chunk.at[e] & LaneChunk::kScalar) {
                triangle(t);
                continue;
            }
            // The coverage setup as edgesOf() gives it: the lanes' edges, the steps from the
            // snapped vertices.
            for (int i = 0; i < 3; ++i) {
                const int m = (i + 1) % 3;
                setup.e0[i] = chunk.e0[i][k];
                setup.stepX[i] = -std::int64_t{chunk.y[m][k] - chunk.y[i][k]} * kSubPixel;
                setup.stepY[i] = std::int64_t{chunk.x[m][k] - chunk.x[i][k]} * kSubPixel;
            }
            setup.box = {chunk.box[0][k], chunk.box[1][k], chunk.box[2][k], chunk.box[3][k]};
            setup.area2 = chunk.area2[k];
            if (!chunk.planes) {
                const std::uint32_t idx[3] = {in.indices[t], in.indices[t + 1], in.indices[t + 2]};
                ClipVertex v[3];
                fetch(idx, v);
                planesAndEmit(v);
                continue;
            }
            // 5. Planes built by the lanes, varyings included.
            const std::uint32_t j = survivor++;
            if (chunk.base[0][j] < 0) continue;  // degenerate in double: makePlanes() fails
            planes.baseX = chunk.base[0][j];
            planes.baseY = chunk.base[1][j];
            float* const to[5] = {planes.l1, planes.l2, planes.u1, planes.u2, planes.q};
            for (int i = 0; i < 5; ++i)
                for (int m = 0; m < 3; ++m) to[i][m] = chunk.plane[3 * i + m][j];
            for (int v = 0; v < count; ++v) {
                planes.a0[v] = chunk.varying[v][j];
                planes.d1[v] = chunk.varying[kMaxVaryings + v][j];
                planes.d2[v] = chunk.varying[2 * kMaxVaryings + v][j];
            }
            fragments += emit(setup, planes);
        }
    }
    return fragments;
}

}  // namespace facet::detail::front
