#include "pipeline/msaa_draw.hpp"

#include "pipeline/span_targets.hpp"
#include "shading/msaa_loop.hpp"

namespace facet::detail {

void drawMsaaTriangles(TileRenderer& tiles, const VariantKey& key, const DrawInput& input,
                       const RenderSettings& settings, const DrawConstants& constants,
                       Framebuffer& samples, int count, int width, int height, int subdivision,
                       int threads, int subPixelBits, RenderStats& stats) {
    // The SIMD target, chosen once per draw.
    MsaaContext ctx = MsaaContext::make(samples, constants, subdivision, count, msaaSpanLoop(key));
    dispatch(key, [&](auto variant) {
        using V = decltype(variant);
        tiles.draw(input, V::kLayout, settings.cullBackFaces, width, height,
                   &rasterizeMsaaTriangle<V>, &ctx, threads, subPixelBits, stats,
                   SamplePattern::kReach);
    });
}

}  // namespace facet::detail
