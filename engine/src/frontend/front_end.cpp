// The front end's entry for one rasterizer called through a pointer (see front_end.hpp); the loop
// itself is front_end_loop.hpp's.

#include "frontend/front_end.hpp"

#include "frontend/front_end_loop.hpp"

namespace facet::detail {

std::size_t drawTriangles(const DrawInput& in, const VaryingLayout& layout, bool cull, int width,
                          int height, std::size_t first, std::size_t end, RasterizeFn emit,
                          void* context, RenderStats& stats, int subPixelBits, int sampleReach,
                          const ScreenVertex* screen) {
    const DrawJob job{&in,         layout, cull,
                      width,       height, subPixelBits,
                      sampleReach, screen, screen ? laneSetup() : nullptr};
    return front::frontEnd(
        job, first, end,
        [&](const CoverageSetup& setup, const Planes& planes) {
            return emit(context, setup, planes);
        },
        stats);
}

}  // namespace facet::detail
