#pragma once
// The multisampled triangle pixel loop (RenderSettings::msaa > 1), a variant of its own picked
// once per draw (pipeline/renderer.cpp), so the one-sample loops (scalar_loop.hpp,
// span_loop-inl.hpp) are untouched by it. This scalar loop is the rule; wide affine and
// perspective triangles take its vector twin (msaa_loop-inl.hpp), equal to it bit for bit.
//
// Per pixel: coverage at each standard sample position (facet/multisample.hpp) with the same
// exact integer edge functions and top-left rule as the pixel centres (coverage.hpp), depth
// (1/q) and the depth test per sample, and one shading per pixel and triangle, written to every
// sample that passed. Shading happens at the pixel centre when the centre is inside the
// triangle, so interior pixels get exactly the one-sample colour, and at the centroid of the
// covered samples when it is not: GL's `centroid` rule. The centre of an edge pixel may lie
// outside the triangle, where perspective weights extrapolate (past the horizon they blow up)
// and uv runs off the texture's mapped region; the mean of covered samples lies in their convex
// hull, hence inside the triangle, so an edge pixel never shows a colour the triangle does not
// have. Subdivided interpolation at a centroid uses the exact (perspective) weights there.

#include <cstddef>
#include <cstdint>
#include <span>

#include "coverage/coverage.hpp"
#include "facet/multisample.hpp"
#include "shading/scalar_loop.hpp"

namespace facet::detail {

/// Most samples per pixel.
inline constexpr int kMaxMsaa = 8;

/// A sample count's positions in the forms the loops use.
struct SamplePattern {
    int count = 1;      ///< samples per pixel
    SampleBlock block;  ///< how a pixel's samples sit in the per-sample buffer
    std::int64_t ox[kMaxMsaa] = {}, oy[kMaxMsaa] = {};  ///< offsets in grid units (1/256 px)
    float fx[kMaxMsaa] = {}, fy[kMaxMsaa] = {};         ///< the same in pixels

    /// How far (grid units) a sample may lie from its pixel's centre: the coverage box's reach.
    static constexpr int kReach = static_cast<int>(kSubPixel / 2);

    /// The pattern of `count` samples (normalised by msaaSamples()).
    static SamplePattern of(int count) {
        SamplePattern c;
        c.count = msaaSamples(count);
        c.block = sampleBlock(c.count);
        const std::span<const SampleOffset> pos = samplePositions(c.count);
        for (int k = 0; k < c.count; ++k) {
            const SampleOffset o = pos[static_cast<std::size_t>(k)];
            // 1/16 px is 16 grid units of 1/256 px: exact whatever RenderSettings::subPixelBits
            // snaps the vertices to (the samples themselves are not snapped).
            constexpr int kUnitsPer16th = static_cast<int>(kSubPixel / 16);
            c.ox[k] = o.x * kUnitsPer16th;
            c.oy[k] = o.y * kUnitsPer16th;
            c.fx[k] = static_cast<float>(o.x) / 16.0f;
            c.fy[k] = static_cast<float>(o.y) / 16.0f;
        }
        return c;
    }

    /// Sample k's index from its pixel's first sample in a per-sample buffer `width` wide.
    std::size_t at(int k, int width) const {
        return static_cast<std::size_t>(k / block.x) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(k % block.x);
    }
};

/// off[i][j]: edge i's value at sample j minus its value at the pixel's centre, the same for
/// every pixel. E moves by −dy·ox + dx·oy, and the steps per pixel are −dy·256 and dx·256, so
/// the division is exact.
inline void sampleEdgeOffsets(const CoverageSetup& s, const SamplePattern& pattern,
                              std::int64_t (&off)[3][kMaxMsaa]) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < pattern.count; ++j)
            off[i][j] = (s.stepX[i] * pattern.ox[j] + s.stepY[i] * pattern.oy[j]) / kSubPixel;
}

/// Calls visit(x, y, e, covered) for every pixel of the box with a covered sample, row by row,
/// left to right: e the edge values at its centre, bit j of `covered` set when sample j is
/// inside by the top-left rule (the exact integer test of coverage.hpp, at the sample).
template <class Visit>
inline void forEachCoveredSamples(const CoverageSetup& s, const SamplePattern& pattern,
                                  Visit&& visit) {
    const int n = pattern.count;
    std::int64_t off[3][kMaxMsaa];
    sampleEdgeOffsets(s, pattern, off);
    std::int64_t row[3] = {s.e0[0], s.e0[1], s.e0[2]};
    for (int y = s.box.y0; y <= s.box.y1; ++y) {
        std::int64_t e[3] = {row[0], row[1], row[2]};
        for (int x = s.box.x0; x <= s.box.x1; ++x) {
            unsigned covered = 0;
            for (int j = 0; j < n; ++j)
                if (((e[0] + off[0][j]) | (e[1] + off[1][j]) | (e[2] + off[2][j])) >= 0)
                    covered |= 1u << j;
            if (covered != 0) visit(x, y, e, covered);
            e[0] += s.stepX[0];
            e[1] += s.stepX[1];
            e[2] += s.stepX[2];
        }
        row[0] += s.stepY[0];
        row[1] += s.stepY[1];
        row[2] += s.stepY[2];
    }
}

struct MsaaContext;

/// The vector multisampled loop of one variant and SIMD target (msaa_loop-inl.hpp); returns
/// the pixels with a covered sample. Picked once per draw.
using MsaaLoopFn = std::size_t (*)(const MsaaContext& ctx, const CoverageSetup& setup,
                                   const Planes& planes);

/// What the multisampled loop needs besides the triangle; shared, read-only, by the threads.
struct MsaaContext {
    Framebuffer* samples = nullptr;  ///< the per-sample buffer, SampleBlock layout
    const DrawConstants* constants = nullptr;
    int subdivision = 16;  ///< N of Interp::Subdivided
    SamplePattern pattern;
    std::size_t at[kMaxMsaa] = {};  ///< SamplePattern::at() for this buffer
    /// The vector loop (msaa_loop-inl.hpp) of the draw's variant and SIMD target, or null.
    MsaaLoopFn spans = nullptr;

    /// The context of `count` samples drawing into `samples` (already sized).
    static MsaaContext make(Framebuffer& samples, const DrawConstants& constants, int subdivision,
                            int count, MsaaLoopFn spans) {
        MsaaContext c{&samples, &constants, subdivision, SamplePattern::of(count), {}, spans};
        for (int k = 0; k < c.pattern.count; ++k) c.at[k] = c.pattern.at(k, samples.width);
        return c;
    }
};

/// The multisampled pixel loop of variant V; returns the pixels with a covered sample.
template <class V>
[[gnu::noinline]] std::size_t rasterizeMsaa(const MsaaContext& ctx, const CoverageSetup& setup,
                                            const Planes& p) {
    const SamplePattern& sp = ctx.pattern;
    Framebuffer& fb = *ctx.samples;
    const DrawConstants& k = *ctx.constants;
    const int n = sp.count;
    PixelWeights<V> weights(ctx.subdivision);
    std::size_t fragments = 0;
    forEachCoveredSamples(
        setup, sp, [&](int x, int y, const std::int64_t(&e)[3], unsigned covered) {
            ++fragments;
            const auto dx = static_cast<float>(x - p.baseX);
            const auto dy = static_cast<float>(y - p.baseY);
            const std::size_t first = fb.index(x * sp.block.x, y * sp.block.y);
            float depth[kMaxMsaa];
            unsigned passed = 0;
            for (int j = 0; j < n; ++j) {
                if (!(covered & (1u << j))) continue;
                depth[j] = 1.0f / Planes::eval(p.q, dx + sp.fx[j], dy + sp.fy[j]);
                if (passesDepth<V::kShader>(fb, first + ctx.at[j], depth[j])) passed |= 1u << j;
            }
            if (passed == 0) return;
            glm::vec3 color;
            float m1 = 0.0f, m2 = 0.0f;
            if ((e[0] | e[1] | e[2]) >= 0) {  // centre inside: the one-sample path's colour
                const float d = 1.0f / Planes::eval(p.q, dx, dy);
                weights.at(p, x, y, dx, dy, d, m1, m2);
                color = shadeAt<V>(p, k, dx, dy, d, m1, m2);
            } else {  // the centroid of the covered samples
                float cx = 0.0f, cy = 0.0f, m = 0.0f;
                for (int j = 0; j < n; ++j) {
                    if (!(covered & (1u << j))) continue;
                    cx += sp.fx[j];
                    cy += sp.fy[j];
                    m += 1.0f;
                }
                const float sx = dx + cx / m, sy = dy + cy / m;
                const float d = 1.0f / Planes::eval(p.q, sx, sy);
                if constexpr (V::kInterp == Interp::Affine) {
                    m1 = Planes::eval(p.l1, sx, sy);
                    m2 = Planes::eval(p.l2, sx, sy);
                } else {
                    m1 = Planes::eval(p.u1, sx, sy) * d;
                    m2 = Planes::eval(p.u2, sx, sy) * d;
                }
                color = shadeAt<V>(p, k, sx, sy, d, m1, m2);
            }
            // storeFragment() per sample, with the colour packed once per pixel.
            const std::uint32_t packed = packColor(color);
            for (int j = 0; j < n; ++j) {
                if (!(passed & (1u << j))) continue;
                const std::size_t i = first + ctx.at[j];
                if constexpr (depthTested(V::kShader)) fb.depth[i] = depth[j];
                if constexpr (V::kShader != ShaderKind::Depth) fb.color[i] = packed;
            }
        });
    return fragments;
}

/// The multisampled rasterizer of variant V: wide affine or perspective triangles take the
/// vector loop of the draw's SIMD target (MsaaContext::spans), the rest the scalar one above,
/// by the same rule as the one-sample loops (rasterizeTriangle in scalar_loop.hpp).
template <class V>
[[gnu::always_inline]] inline std::size_t rasterizeMsaaTriangle(const MsaaContext& ctx,
                                                                const CoverageSetup& setup,
                                                                const Planes& p) {
    if constexpr (kHasSpanLoop<V>) {
        if (ctx.spans && setup.box.x1 - setup.box.x0 >= kNarrowBox) return ctx.spans(ctx, setup, p);
    }
    return rasterizeMsaa<V>(ctx, setup, p);
}

/// Variant V's multisampled rasterizer as the tile renderer takes it (TileRenderer::draw).
template <class V>
struct MsaaRaster {
    MsaaContext ctx;

    std::size_t operator()(const CoverageSetup& setup, const Planes& p,
                           const PixelTarget&) const {  // writes the per-sample buffer
        return rasterizeMsaaTriangle<V>(ctx, setup, p);
    }
};

}  // namespace facet::detail
