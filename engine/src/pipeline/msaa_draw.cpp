#include "pipeline/msaa_draw.hpp"

#include "shading/msaa_loop.hpp"

namespace facet::detail {

void drawMsaaTriangles(TileRenderer& tiles, const VariantKey& key, const DrawInput& input,
                       const RenderSettings& settings, const DrawConstants& constants,
                       Framebuffer& samples, int count, int width, int height, int subdivision,
                       int threads, int subPixelBits, RenderStats& stats) {
    MsaaContext ctx = MsaaContext::make(samples, constants, subdivision, count);
    dispatch(key, [&](auto variant) {
        using V = decltype(variant);
        tiles.draw(input, V::kLayout, settings.cullBackFaces, width, height, &rasterizeMsaa<V>,
                   &ctx, threads, subPixelBits, stats, SamplePattern::kReach);
    });
}

}  // namespace facet::detail
