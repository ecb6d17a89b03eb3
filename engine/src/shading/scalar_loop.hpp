#pragma once
// The triangle pixel loops of the fast path, after the shared front end: the scalar loop (every
// variant, one pixel at a time) and the choice between it and the vector span loop
// (span_loop-inl.hpp). Each is a template over a Variant (fragment.hpp), instantiated once per
// pipeline state by the dispatcher (pipeline/variants.hpp).

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "frontend/front_end.hpp"
#include "shading/fragment.hpp"
#include "shading/span_loop.hpp"

namespace facet::detail {

/// Perspective-correct weights of vertices 1 and 2 at (dx, dy); false where 1/w is not positive
/// and finite (possible only when extrapolating outside the triangle).
inline bool perspectiveWeights(const Planes& p, float dx, float dy, float& m1, float& m2) {
    const float q = Planes::eval(p.q, dx, dy);
    if (!(q > 0.0f) || !std::isfinite(q)) return false;
    const float r = 1.0f / q;
    m1 = Planes::eval(p.u1, dx, dy) * r;
    m2 = Planes::eval(p.u2, dx, dy) * r;
    return true;
}

/// The mip level trilinear filtering samples at (dx, dy), whose depth is `depth`: from the
/// derivatives of the weights of interpolation I (constant when affine, the analytic derivative
/// of the perspective-correct weights otherwise) applied to the uv varying at `uv`.
template <Interp I>
inline float uvLevelOfDetail(const Planes& p, float dx, float dy, float depth, int uv,
                             const Texture& texture) {
    float w1x = p.l1[1], w1y = p.l1[2], w2x = p.l2[1], w2y = p.l2[2];
    if constexpr (I != Interp::Affine) {
        const float pm1 = Planes::eval(p.u1, dx, dy) * depth;
        const float pm2 = Planes::eval(p.u2, dx, dy) * depth;
        w1x = (p.u1[1] - pm1 * p.q[1]) * depth;
        w1y = (p.u1[2] - pm1 * p.q[2]) * depth;
        w2x = (p.u2[1] - pm2 * p.q[1]) * depth;
        w2y = (p.u2[2] - pm2 * p.q[2]) * depth;
    }
    const auto u = static_cast<std::size_t>(uv);
    const glm::vec2 d1(p.d1[u], p.d1[u + 1]), d2(p.d2[u], p.d2[u + 1]);
    return mipLevel(texture, d1 * w1x + d2 * w2x, d1 * w1y + d2 * w2y);
}

/// Interp::Subdivided: the exact weights at the two ends of the current N-pixel span, kept
/// while a row is walked left to right through it. A fresh one gives the same weights.
struct SubdividedSpan {
    int y = INT_MIN, x0 = INT_MIN;
    bool exact = false;  ///< the span's ends are unusable: exact at each pixel instead
    float s1a = 0.0f, s2a = 0.0f, s1b = 0.0f, s2b = 0.0f;
};

/// The interpolation weights (m1, m2) of vertices 1 and 2 at pixel (x, y), (dx, dy) from the
/// base pixel, in variant V's interpolation mode; `n` is the subdivision, `invN` its inverse.
template <class V>
inline void fragmentWeights(const Planes& p, int x, int y, float dx, float dy, float depth, int n,
                            float invN, SubdividedSpan& span, float& m1, float& m2) {
    if constexpr (V::kInterp == Interp::Affine) {
        m1 = Planes::eval(p.l1, dx, dy);
        m2 = Planes::eval(p.l2, dx, dy);
    } else if constexpr (V::kInterp == Interp::Perspective) {
        m1 = Planes::eval(p.u1, dx, dy) * depth;
        m2 = Planes::eval(p.u2, dx, dy) * depth;
    } else {
        const int x0 = x / n * n;  // x >= 0: division is floor
        if (y != span.y || x0 != span.x0) {
            span.y = y;
            span.x0 = x0;
            const auto ex = static_cast<float>(x0 - p.baseX);
            span.exact = !perspectiveWeights(p, ex, dy, span.s1a, span.s2a) ||
                         !perspectiveWeights(p, ex + static_cast<float>(n), dy, span.s1b, span.s2b);
        }
        if (span.exact) {
            m1 = Planes::eval(p.u1, dx, dy) * depth;
            m2 = Planes::eval(p.u2, dx, dy) * depth;
        } else {
            const float t = static_cast<float>(x - x0) * invN;
            m1 = span.s1a + (span.s1b - span.s1a) * t;
            m2 = span.s2a + (span.s2b - span.s2a) * t;
        }
    }
}

/// Every varying of V at weights (m1, m2), into a[0 … V::kCount).
template <class V>
inline void interpolateVaryings(const Planes& p, float m1, float m2, float* a) {
    for (int j = 0; j < V::kCount; ++j) a[j] = p.a0[j] + m1 * p.d1[j] + m2 * p.d2[j];
}

/// The trilinear level of detail of variant V at (dx, dy); 0 for variants without derivatives.
template <class V>
inline float fragmentLod(const Planes& p, const Texture& texture, float dx, float dy, float depth) {
    if constexpr (V::kDerivatives)
        return uvLevelOfDetail<V::kInterp>(p, dx, dy, depth, V::kLayout.uvAt(), texture);
    return 0.0f;
}

/// Variant V's interpolation weights pixel by pixel (fragmentWeights() with its span state):
/// what a pixel loop that is not the scalar one (multisampling's) keeps per triangle.
template <class V>
struct PixelWeights {
    SubdividedSpan span;
    int n = 16;  ///< N of Interp::Subdivided
    float invN = 1.0f / 16.0f;

    explicit PixelWeights(int subdivision)
        : n(subdivision), invN(1.0f / static_cast<float>(subdivision)) {}

    /// The weights (m1, m2) at pixel (x, y), (dx, dy) from the planes' base, `depth` = 1/q there.
    void at(const Planes& p, int x, int y, float dx, float dy, float depth, float& m1, float& m2) {
        fragmentWeights<V>(p, x, y, dx, dy, depth, n, invN, span, m1, m2);
    }
};

/// The colour of variant V's fragment at (dx, dy) from the planes' base, `depth` = 1/q there,
/// weights (m1, m2) from fragmentWeights() (or exact ones off the pixel grid): the varyings, the
/// texture level of detail, then fragmentColor().
template <class V>
inline glm::vec3 shadeAt(const Planes& p, const DrawConstants& k, float dx, float dy, float depth,
                         float m1, float m2) {
    float a[V::kCount > 0 ? V::kCount : 1];
    interpolateVaryings<V>(p, m1, m2, a);
    return fragmentColor<V>(a, k, fragmentLod<V>(p, *k.texture, dx, dy, depth));
}

/// The scalar triangle pixel loop of variant V: every variant, one pixel at a time.
template <class V>
[[gnu::noinline]] std::size_t rasterizeScalar(const RasterContext& ctx, const CoverageSetup& setup,
                                              const Planes& p, const PixelTarget& target) {
    PixelTarget fb = target;  // a copy: stores to pixels cannot change it
    const DrawConstants& k = *ctx.constants;
    SubdividedSpan span;
    const int n = ctx.subdivision;
    const float invN = 1.0f / static_cast<float>(n);
    std::size_t fragments = 0;

    forEachCovered(setup, [&](int x, int y) {
        ++fragments;
        const auto dx = static_cast<float>(x - p.baseX);
        const auto dy = static_cast<float>(y - p.baseY);
        const float depth = p.depthAt(dx, dy);
        const std::size_t i = fb.index(x, y);
        if (!passesDepth<V::kShader>(fb, i, depth)) return;
        float m1 = 0.0f, m2 = 0.0f;
        fragmentWeights<V>(p, x, y, dx, dy, depth, n, invN, span, m1, m2);
        storeFragment<V::kShader>(fb, i, depth, shadeAt<V>(p, k, dx, dy, depth, m1, m2));
    });
    return fragments;
}

/// The triangle rasterizer of variant V: affine or perspective triangles take a vector loop of
/// the draw's SIMD target, the span loop for wide boxes (RasterContext::spans) and the block loop
/// for narrow ones (RasterContext::blocks) when not tiny and its 32-bit edge values suffice; the
/// rest take the scalar loop. Each loop is kept out of line so that it is optimised (and its
/// shading inlined) on its own; this choice is inlined into the tile loop (GCC 12 kept it out of
/// line otherwise: one more call per triangle).
template <class V>
[[gnu::always_inline]] inline std::size_t rasterizeTriangle(const RasterContext& ctx,
                                                            const CoverageSetup& setup,
                                                            const Planes& p,
                                                            const PixelTarget& target) {
    if constexpr (kHasSpanLoop<V>) {
        if (setup.box.x1 - setup.box.x0 >= kNarrowBox) {
            if (ctx.spans) return ctx.spans(ctx, setup, p, target);
        } else if (ctx.blocks &&
                   setup.box.x1 - setup.box.x0 + setup.box.y1 - setup.box.y0 + 2 >= kTinyBox &&
                   fitsBlockLoop(setup)) {
            return ctx.blocks(ctx, setup, p, target);
        }
    }
    return rasterizeScalar<V>(ctx, setup, p, target);
}

/// rasterizeTriangle() into the whole frame ctx.fb.
template <class V>
inline std::size_t rasterizeTriangle(const RasterContext& ctx, const CoverageSetup& setup,
                                     const Planes& p) {
    return rasterizeTriangle<V>(ctx, setup, p, PixelTarget::frame(*ctx.fb));
}

/// Variant V's rasterizer as the tile renderer takes it (TileRenderer::draw): the draw's state
/// by value and a call per triangle that the tile loop inlines. With a depth test, a triangle
/// part wholly behind the tile's far bound or its blocks' (hierarchical depth, target.bound) is
/// rejected before its pixels are visited; one that draws marks its blocks stale, and one that
/// covers the whole tile lowers the tile's bound.
template <class V>
struct TriangleRaster {
    RasterContext ctx;

    std::size_t operator()(const CoverageSetup& setup, const Planes& p,
                           const PixelTarget& target) const {
        if constexpr (depthTested(V::kShader)) {
            TileDepth* bound = target.bound;
            if (!bound) return rasterizeTriangle<V>(ctx, setup, p, target);
            const std::uint64_t blocks = bound->blocks ? blockMask(setup.box, target.tile) : 0;
            if (hiddenBehind(p, setup.box, blocks, target, *bound)) {
                ++bound->rejected;
                return 0;
            }
            const std::size_t covered = rasterizeTriangle<V>(ctx, setup, p, target);
            if (covered != 0) bound->stale |= blocks;
            // Only wide boxes may cover a tile (a partial tile narrower than kNarrowBox keeps no
            // tile bound, only its blocks').
            if (setup.box.x1 - setup.box.x0 >= kNarrowBox)
                lowerBound(setup, p, target.tile, *bound);
            return covered;
        } else {
            return rasterizeTriangle<V>(ctx, setup, p, target);
        }
    }
};

}  // namespace facet::detail
