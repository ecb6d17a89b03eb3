#include "pipeline/msaa_draw.hpp"

#include "pipeline/span_targets.hpp"
#include "shading/msaa_loop.hpp"

namespace facet::detail {

void drawMsaaTriangles(TileRenderer& tiles, const VariantKey& key, const DrawInput& input,
                       const RenderSettings& settings, const DrawConstants& constants,
                       Framebuffer& samples, int count, int width, int height, int subdivision,
                       int threads, int subPixelBits, RenderStats& stats) {
    // The SIMD target, chosen once per draw.
    const MsaaContext ctx =
        MsaaContext::make(samples, constants, subdivision, count, msaaSpanLoop(key));
    dispatch(key, [&](auto variant) {
        using V = decltype(variant);
        DrawJob job = drawJob(input, V::kLayout, settings, width, height);
        job.subPixelBits = subPixelBits;
        job.sampleReach = SamplePattern::kReach;
        tiles.draw(job, MsaaRaster<V>{ctx}, threads, stats);
    });
}

}  // namespace facet::detail
