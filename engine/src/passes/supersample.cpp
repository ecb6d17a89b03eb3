#include "passes/supersample.hpp"

#include <algorithm>
#include <cstdint>

namespace facet::detail {

void resolveSupersampled(const Framebuffer& big, int n, Framebuffer& out, int threads) {
    const int w = big.width / n, h = big.height / n;
    out.resize(w, h);
    const std::uint32_t count = static_cast<std::uint32_t>(n * n);
#pragma omp parallel for num_threads(threads) if (static_cast <long>(w) * h > 65536)
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            RgbaSum sum;
            float nearest = kEmptyDepth;
            for (int sy = 0; sy < n; ++sy) {
                const std::size_t row = big.index(x * n, y * n + sy);
                for (int sx = 0; sx < n; ++sx) {
                    const std::uint32_t c = big.color[row + static_cast<std::size_t>(sx)];
                    sum.add(c);
                    nearest = std::min(nearest, big.depth[row + static_cast<std::size_t>(sx)]);
                }
            }
            const std::size_t i = out.index(x, y);
            out.color[i] = sum.mean(count);
            out.depth[i] = nearest;
        }
    }
}

}  // namespace facet::detail
