#include "passes/supersample.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace facet::detail {

void resolveSupersampled(const Framebuffer& big, int bx, int by, Framebuffer& out, int threads) {
    const int w = big.width / bx, h = big.height / by;
    out.resize(w, h);
    const std::uint32_t count = static_cast<std::uint32_t>(bx * by);
#pragma omp parallel for num_threads(threads) if (static_cast <long>(w) * h > 65536)
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            RgbaSum sum;
            float nearest = kEmptyDepth;
            for (int sy = 0; sy < by; ++sy) {
                const std::size_t row = big.index(x * bx, y * by + sy);
                for (int sx = 0; sx < bx; ++sx) {
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

void expandToSamples(const Framebuffer& frame, int bx, int by, Framebuffer& samples, int threads) {
    samples.resize(frame.width * bx, frame.height * by);
    const int w = frame.width, h = frame.height;
#pragma omp parallel for num_threads(threads) if (static_cast <long>(w) * h > 65536)
    for (int y = 0; y < h; ++y) {
        for (int sy = 0; sy < by; ++sy) {
            const std::size_t row = samples.index(0, y * by + sy);
            for (int x = 0; x < w; ++x) {
                const std::size_t i = frame.index(x, y);
                for (int sx = 0; sx < bx; ++sx) {
                    const std::size_t j = row + static_cast<std::size_t>(x * bx + sx);
                    samples.color[j] = frame.color[i];
                    samples.depth[j] = frame.depth[i];
                }
            }
        }
    }
}

}  // namespace facet::detail
