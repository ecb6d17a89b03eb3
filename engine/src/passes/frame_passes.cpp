// Clear and depth colours (see frame_passes.hpp).

#include "passes/frame_passes.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>

#include <glm/vec3.hpp>

#include "facet/colormap.hpp"
#include "shading/fragment.hpp"

namespace facet::detail {
namespace {

/// Pixels per thread below which whole-frame passes stay on one thread.
constexpr std::ptrdiff_t kParallelPixels = 1 << 16;

}  // namespace

// Split by rows over the threads: a 4K frame is 64 MB of stores.
void clearFrame(Framebuffer& fb, std::uint32_t rgba, int threads) {
    const auto n = static_cast<std::ptrdiff_t>(fb.color.size());
    const std::ptrdiff_t parts =
        std::max<std::ptrdiff_t>(1, std::min<std::ptrdiff_t>(threads, n / kParallelPixels));
#pragma omp parallel for num_threads(static_cast <int>(parts)) if (parts > 1)
    for (std::ptrdiff_t p = 0; p < parts; ++p)
        clearPixels(fb, rgba, static_cast<std::size_t>(n * p / parts),
                    static_cast<std::size_t>(n * (p + 1) / parts));
}

void clearPixels(Framebuffer& fb, std::uint32_t rgba, std::size_t begin, std::size_t end) {
    std::fill(fb.color.data() + begin, fb.color.data() + end, rgba);
    std::fill(fb.depth.data() + begin, fb.depth.data() + end, kEmptyDepth);
}

void resolveDepthColors(Framebuffer& fb, RenderStats& stats, int threads) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float d : fb.depth)
        if (d != kEmptyDepth) {
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    if (lo > hi) return;
    stats.depthNear = lo;
    stats.depthFar = hi;
    const auto n = static_cast<std::ptrdiff_t>(fb.depth.size());
#pragma omp parallel for num_threads(threads) if (n > kParallelPixels)
    for (std::ptrdiff_t i = 0; i < n; ++i)
        if (fb.depth[i] != kEmptyDepth) fb.color[i] = depthColor(fb.depth[i], lo, hi);
}

}  // namespace facet::detail
