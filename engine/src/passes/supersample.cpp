#include "passes/supersample.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace facet::detail {

void resolveSupersampled(const Framebuffer& big, int bx, int by, Framebuffer& out, int threads) {
    const int w = big.width / bx, h = big.height / by;
    out.resize(w, h);
    const std::uint32_t count = static_cast<std::uint32_t>(bx * by);
    const std::uint32_t half = count / 2;  // round to nearest
    // Every block but 3×3 has a power-of-two count: a shift, not a division per channel.
    const int shift = std::has_single_bit(count) ? std::countr_zero(count) : -1;
#pragma omp parallel for num_threads(threads) if (static_cast <long>(w) * h > 65536)
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            std::uint32_t sum[4] = {0, 0, 0, 0};
            float nearest = kEmptyDepth;
            for (int sy = 0; sy < by; ++sy) {
                const std::size_t row = big.index(x * bx, y * by + sy);
                for (int sx = 0; sx < bx; ++sx) {
                    const std::uint32_t c = big.color[row + static_cast<std::size_t>(sx)];
                    for (int k = 0; k < 4; ++k) sum[k] += (c >> (8 * k)) & 0xFFu;
                    nearest = std::min(nearest, big.depth[row + static_cast<std::size_t>(sx)]);
                }
            }
            std::uint32_t packed = 0;
            for (int k = 0; k < 4; ++k) {
                const std::uint32_t v = sum[k] + half;
                packed |= (shift >= 0 ? v >> shift : v / count) << (8 * k);
            }
            const std::size_t i = out.index(x, y);
            out.color[i] = packed;
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
