#pragma once
// The triangle front end of the fast path, shared by every pipeline variant. Its stages, in
// front_end.cpp: fetch (indices, trivial reject, varyings), near clip (near_clip.hpp), project
// and snap (screen positions, the sub-pixel grid, the guard band), cull, and plane setup
// (planes.hpp); then one call per covered triangle to a rasterizer that knows the variant. That
// call is per triangle, not per pixel, so the front end is compiled once and the variants only
// instantiate the pixel loop. What depends on one vertex alone (its snapped position, the reject
// and guard-band tests) is ScreenSpace::vertex() below, which the tile renderer runs once per
// vertex before the triangles.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "coverage/coverage.hpp"
#include "facet/advanced/draw.hpp"
#include "frontend/fetch.hpp"
#include "frontend/planes.hpp"

namespace facet::detail {

/// A clip position on screen, in double: the projection every later stage starts from.
inline glm::dvec2 screenPosition(const glm::vec4& clip) {
    return glm::dvec2(clip.x, clip.y) / static_cast<double>(clip.w);
}

/// Pixels beyond each image border inside which triangles are rasterized without 2D clipping.
/// Keeps snapped coordinates below 2^24 grid units, so edge products stay far below 2^63.
inline constexpr double kGuardBand = 32768.0;

/// What the front end learns of one clip-space vertex before it knows its triangles: its
/// position on the sub-pixel grid and which sides of the near plane, the image and the guard band
/// it lies on. Each vertex is shared by about six triangles of a mesh, so computing this once per
/// vertex (TileRenderer's vertex pass) instead of once per corner saves the divisions, snaps and
/// tests of five corners in six. 12 bytes, so that the pass's output costs less cache than the
/// clip positions it replaces in the reject and coverage stages: the screen position in double
/// is computed again only for the triangles that reach plane setup.
struct ScreenVertex {
    std::int32_t gx = 0;      ///< screen x on the sub-pixel grid, in 1/256 px (when kInGuard)
    std::int32_t gy = 0;      ///< screen y on the sub-pixel grid, in 1/256 px (when kInGuard)
    std::uint32_t flags = 0;  ///< the k* bits below

    static constexpr std::uint32_t kFinite = 1;   ///< x, y and w finite
    static constexpr std::uint32_t kFront = 2;    ///< w ≥ near
    static constexpr std::uint32_t kInGuard = 4;  ///< inside the guard band, gx and gy set
    static constexpr std::uint32_t kLeft = 8;     ///< x < 0: left of the image
    static constexpr std::uint32_t kRight = 16;   ///< x > W·w: right of it
    static constexpr std::uint32_t kAbove = 32;   ///< y < 0: above it
    static constexpr std::uint32_t kBelow = 64;   ///< y > H·w: below it
};

/// The screen a draw projects to: image size, near plane, guard band and sub-pixel grid.
struct ScreenSpace {
    float W = 0.0f, H = 0.0f;  ///< image size in pixels
    float nearPlane = 0.0f;    ///< DrawInput::nearPlane
    glm::dvec2 lo, hi;         ///< the guard band's corners
    SnapGrid grid;             ///< the coverage grid

    /// The screen of a width × height image, near plane `nearPlane`, grid of 2^-bits px.
    static ScreenSpace of(int width, int height, float nearPlane, int subPixelBits) {
        return {static_cast<float>(width),
                static_cast<float>(height),
                nearPlane,
                {-kGuardBand, -kGuardBand},
                {width + kGuardBand, height + kGuardBand},
                SnapGrid::ofBits(subPixelBits)};
    }
    /// Whether a screen position lies in the guard band (false for NaN).
    bool inGuard(const glm::dvec2& p) const {
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
    }
    /// Everything the front end derives from clip position `p` alone.
    ScreenVertex vertex(const glm::vec4& p) const {
        ScreenVertex v;
        const glm::dvec2 s = screenPosition(p);
        std::uint32_t f = 0;
        f |= std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.w) ? ScreenVertex::kFinite
                                                                            : 0u;
        f |= p.w >= nearPlane ? ScreenVertex::kFront : 0u;
        f |= p.x < 0.0f ? ScreenVertex::kLeft : 0u;
        f |= p.x > W * p.w ? ScreenVertex::kRight : 0u;
        f |= p.y < 0.0f ? ScreenVertex::kAbove : 0u;
        f |= p.y > H * p.w ? ScreenVertex::kBelow : 0u;
        if (inGuard(s)) {
            f |= ScreenVertex::kInGuard;
            // Inside the band |s·256| < 2^24, so the grid position fits 32 bits.
            v.gx = static_cast<std::int32_t>(grid(s.x));
            v.gy = static_cast<std::int32_t>(grid(s.y));
        }
        v.flags = f;
        return v;
    }
};

/// The front end's setup stage in vector lanes (setup_lanes.cpp): what it reads of a draw.
struct LaneInput {
    const std::uint32_t* indices = nullptr;  ///< the draw's indices, three per triangle
    std::size_t vertices = 0;                ///< clip positions (valid indices are below)
    const ScreenVertex* screen = nullptr;    ///< the vertex pass's output
    int width = 0, height = 0;               ///< image size in pixels
    int sampleReach = 0;                     ///< as DrawJob::sampleReach
    bool cull = false;                       ///< drop back faces
    /// The clip positions, for the survivors' planes (LaneChunk::planes); null: the loop builds
    /// them one triangle at a time.
    const glm::vec4* clip = nullptr;
    /// The varyings the planes carry (with `clip` only): the lanes gather them and set up their
    /// planes too (LaneChunk::varying).
    VaryingStreams varyings;
};

/// What the lanes stage tells the front end's loop of a chunk of up to kSize triangles: in
/// submission order, the triangles the loop must still visit (those left to the scalar path,
/// and those that survived reject, cull and the "covers no pixel centre" exit, whose snapped
/// triangle sits at their place in the arrays), and the counters of the triangles it settled.
/// Structure of arrays, written a whole vector at a time: `kSlack` entries past the end.
struct LaneChunk {
    static constexpr std::size_t kSize = 256;
    static constexpr std::size_t kSlack = 16;
    /// Set in an entry of `at` for a triangle the scalar path takes.
    static constexpr std::uint32_t kScalar = 0x80000000u;

    std::uint32_t count = 0;              ///< entries of `at`
    std::uint32_t at[kSize];              ///< triangle − chunk start, | kScalar for scalar
    std::int32_t x[3][kSize + kSlack];    ///< survivors' SnappedTriangle::x, by triangle
    std::int32_t y[3][kSize + kSlack];    ///< SnappedTriangle::y
    std::int32_t box[4][kSize + kSlack];  ///< SnappedTriangle::box: x0, y0, x1, y1
    std::int32_t area2[kSize + kSlack];   ///< SnappedTriangle::area2
    std::int32_t e0[3][kSize + kSlack];   ///< CoverageSetup::e0 (edgesOf()), by triangle
    /// Whether the lanes built the survivors' planes below (LaneInput::clip given); else the
    /// loop builds them. Indexed by survivor: the loop's n-th entry without kScalar is survivor
    /// n, so the planes are stored a whole vector of survivors at a time.
    bool planes = false;
    /// Planes::baseX, baseY of each survivor; baseX −1 where makePlanes() would return false
    /// (twice the area 0 in double), which the loop then drops as the scalar path does.
    std::int32_t base[2][kSize + kSlack];
    /// Planes::l1, l2, u1, u2 and q of each survivor, three floats each in that order.
    float plane[15][kSize + kSlack];
    /// Planes::a0, d1 and d2 of each survivor: varying v's a0 at row v, its d1 at row
    /// kMaxVaryings + v, its d2 at row 2·kMaxVaryings + v (rows of LaneInput::varyings' floats).
    float varying[3 * kMaxVaryings][kSize + kSlack];
    std::size_t trianglesIn = 0;  ///< RenderStats' counters of the lanes' triangles
    std::size_t trianglesCulled = 0;
    std::size_t trianglesRasterized = 0;
};

/// The lanes stage: reject, cull, box, and the exit for boxes without a pixel centre, for
/// triangles [first, end) of `in` (end − first ≤ LaneChunk::kSize), a whole vector of
/// triangles at once; then, with LaneInput::clip, the survivors' planes (makePlanes()'s double
/// arithmetic lane by lane, bit for bit, and setVaryingPlanes()' float differences of the
/// gathered varyings), a vector of survivors at once. Takes the triangles whose
/// vertices are all in front of the near plane and in the guard band and whose snapped box spans
/// under kLaneExtent grid units each way (so that every edge product fits 32 bits); leaves the
/// others to the scalar path.
using LaneSetupFn = void (*)(const LaneInput& in, std::size_t first, std::size_t end,
                             LaneChunk& out);

/// Grid units a triangle's snapped vertices may span, each way, to take the lanes (64 px):
/// coordinates relative to the box and their differences stay under 2^15, so the area's and the
/// edge functions' products of two stay under 2^30 and their sums fit 32 bits.
inline constexpr std::int32_t kLaneExtent = 1 << 14;

/// The lanes stage for the best SIMD target this CPU has (Highway's run-time choice, which tests
/// may restrict with hwy::SetSupportedTargetsForTest), chosen once per draw; null when turned
/// off (enableLaneSetup()).
LaneSetupFn laneSetup();

/// Turns the lanes stage off (every triangle takes the scalar front end, the reference it must
/// equal) or back on, for the whole process. Not for use while a draw runs.
void enableLaneSetup(bool enabled);

/// The sub-pixel grid a draw snaps to: settings.subPixelBits clamped to what the engine
/// supports (kMinSubPixelBits … kMaxSubPixelBits). The one place that clamps it.
inline int clampedSubPixelBits(const RenderSettings& settings) {
    return std::clamp(settings.subPixelBits, kMinSubPixelBits, kMaxSubPixelBits);
}

/// One draw as the front end sees it: the inputs that stay the same for all its triangles.
struct DrawJob {
    const DrawInput* in = nullptr;         ///< the vertex stage's output
    VaryingLayout layout;                  ///< the varyings the planes carry
    bool cull = false;                     ///< drop back faces
    int width = 0, height = 0;             ///< image size in pixels
    int subPixelBits = kSubPixelBits;      ///< coverage grid of 1/2^subPixelBits px
    int sampleReach = 0;                   ///< grid units boxes reach past centres (multisampling)
    const ScreenVertex* screen = nullptr;  ///< ScreenVertex of every clip position, or null
    LaneSetupFn lanes = nullptr;           ///< the lanes stage (with `screen` only), or null
};

/// The per-triangle rasterizer of a variant: covers `setup` and shades with `planes`; returns
/// the number of pixels covered (fragments before the depth test).
using RasterizeFn = std::size_t (*)(void* context, const CoverageSetup& setup,
                                    const Planes& planes);

/// Runs the front end over triangles [first, end) of the draw and calls `emit` for each part
/// that covers pixels, with the planes of the (whole, unclipped by the guard band) triangle.
/// Returns the sum of what `emit` returned. Coverage uses a grid of 1/2^subPixelBits px; boxes
/// reach `sampleReach` grid units past the pixel centres (multisampling, setupCoverage()).
/// `screen`, when given, holds ScreenSpace::vertex() of every clip position of the draw (same
/// size, near plane and grid); else the front end derives it per corner. The result is the same.
/// (The tile renderer calls the front end's loop, frontEnd() in front_end_loop.hpp, with its
/// binning inlined; this entry serves the debug probes, the inspector and the tests.)
std::size_t drawTriangles(const DrawInput& in, const VaryingLayout& layout, bool cull, int width,
                          int height, std::size_t first, std::size_t end, RasterizeFn emit,
                          void* context, RenderStats& stats, int subPixelBits = kSubPixelBits,
                          int sampleReach = 0, const ScreenVertex* screen = nullptr);

}  // namespace facet::detail
