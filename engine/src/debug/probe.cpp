// The instrumented draws (see probe.hpp).

#include "debug/probe.hpp"

#include <algorithm>
#include <cmath>

#include "coverage/coverage.hpp"
#include "frontend/front_end.hpp"
#include "shading/fragment.hpp"
#include "shading/scalar_loop.hpp"

namespace facet::detail {
namespace {

/// What probeTriangle() writes to; `triangle` is set before each triangle's front end runs.
struct ProbeContext {
    DrawProbe* probe;
    const Texture* texture;
    std::uint32_t triangle;
};

/// The counting rasterizer: shader S's depth rule (every depth-tested shader shares one), and
/// for the fragment that wins, the mip level under interpolation I when `Lod`.
template <ShaderKind S, Interp I, bool Lod>
std::size_t probeTriangle(void* context, const CoverageSetup& setup, const Planes& p) {
    ProbeContext& c = *static_cast<ProbeContext*>(context);
    DrawProbe& probe = *c.probe;
    Framebuffer& fb = probe.depth;
    std::size_t covered = 0;
    forEachCovered(setup, [&](int x, int y) {
        ++covered;
        const auto dx = static_cast<float>(x - p.baseX);
        const auto dy = static_cast<float>(y - p.baseY);
        const float depth = p.depthAt(dx, dy);
        const std::size_t i = fb.index(x, y);
        ++probe.fragments[i];
        if (!passesDepth<S>(fb, i, depth)) {
            ++probe.failures[i];
            return;
        }
        if constexpr (depthTested(S)) fb.depth[i] = depth;
        probe.winner[i] = c.triangle;
        if constexpr (Lod)
            probe.lod[i] = uvLevelOfDetail<I>(p, dx, dy, depth,
                                              VaryingLayout{false, true, false}.uvAt(), *c.texture);
    });
    probe.trianglePixels[c.triangle] += static_cast<std::uint32_t>(covered);
    return covered;
}

template <ShaderKind S, bool Lod>
RasterizeFn pickProbe(Interp interp) {
    switch (interp) {
        case Interp::Affine:
            return &probeTriangle<S, Interp::Affine, Lod>;
        case Interp::Subdivided:
            return &probeTriangle<S, Interp::Subdivided, Lod>;
        case Interp::Perspective:
            break;
    }
    return &probeTriangle<S, Interp::Perspective, Lod>;
}

/// Counts the tile renderer's calls per tile: it calls its rasterizer once per binned triangle
/// and tile, with the setup clipped to that tile.
struct BinCounter {
    std::uint32_t* perTile;
    int tilesX;

    std::size_t operator()(const CoverageSetup& setup, const Planes&, const PixelTarget&) const {
        const int tile = setup.box.y0 / kTileSize * tilesX + setup.box.x0 / kTileSize;
        ++perTile[tile];  // one thread owns a tile: no race
        return 0;
    }
};

}  // namespace

void DrawProbe::run(const DrawInput& in, const RenderSettings& settings, int width, int height,
                    bool withLod, RenderStats& stats) {
    depth.resize(width, height);
    depth.clear(0);
    const std::size_t pixels = depth.depth.size();
    fragments.assign(pixels, 0);
    failures.assign(pixels, 0);
    winner.assign(pixels, kNoTriangle);
    lod.assign(withLod ? pixels : 0, 0.0f);
    const std::size_t triangles = in.indices.size() / 3;
    trianglePixels.assign(triangles, 0);
    if (width <= 0 || height <= 0) return;

    const bool tested = depthTested(settings.shader);
    // The rasterizer is picked once per draw, like the real one.
    RasterizeFn fn = nullptr;
    if (withLod)
        fn = tested ? pickProbe<ShaderKind::Painter, true>(settings.interp)
                    : pickProbe<ShaderKind::Simple, true>(settings.interp);
    else
        fn = tested ? pickProbe<ShaderKind::Painter, false>(settings.interp)
                    : pickProbe<ShaderKind::Simple, false>(settings.interp);
    const VaryingLayout layout{false, withLod, false};
    ProbeContext context{this, in.texture ? in.texture : &whiteTexture(), 0};
    for (std::size_t t = 0; t < triangles; ++t) {
        context.triangle = static_cast<std::uint32_t>(t);
        drawTriangles(in, layout, settings.cullBackFaces, width, height, t, t + 1, fn, &context,
                      stats, clampedSubPixelBits(settings));
    }
}

void countBinLoad(TileRenderer& tiles, const DrawInput& in, const RenderSettings& settings,
                  int width, int height, std::vector<std::uint32_t>& perTile) {
    const int tilesX = (width + kTileSize - 1) / kTileSize;
    const int tilesY = (height + kTileSize - 1) / kTileSize;
    perTile.assign(static_cast<std::size_t>(std::max(0, tilesX * tilesY)), 0);
    if (width <= 0 || height <= 0) return;
    RenderStats stats;
    tiles.draw(drawJob(in, VaryingLayout{}, settings, width, height),
               BinCounter{perTile.data(), tilesX}, resolveThreads(settings.threads), stats);
}

}  // namespace facet::detail
