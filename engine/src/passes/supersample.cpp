#include "passes/supersample.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace facet::detail {

namespace {

/// resolveSupersampled() for blocks of BX × BY, or of bx × by when they are 0: the common
/// multisampling blocks get loops of known length (unrolled, no per-pixel trip count).
template <int BX, int BY>
void resolveBlocks(const Framebuffer& big, int bx, int by, Framebuffer& out, int threads) {
    if constexpr (BX > 0) bx = BX, by = BY;
    const int w = out.width, h = out.height;
    const auto count = static_cast<std::uint32_t>(bx * by);
#pragma omp parallel for num_threads(threads) if (static_cast <long>(w) * h > 65536)
    for (int y = 0; y < h; ++y) {
        const std::uint32_t* colors[kMaxSupersample];
        const float* depths[kMaxSupersample];
        for (int sy = 0; sy < by; ++sy) {
            const std::size_t row = big.index(0, y * by + sy);
            colors[sy] = big.color.data() + row;
            depths[sy] = big.depth.data() + row;
        }
        const std::size_t first = out.index(0, y);
        for (int x = 0; x < w; ++x) {
            RgbaSum sum;
            float nearest = kEmptyDepth;
            for (int sy = 0; sy < by; ++sy) {
                const auto at = static_cast<std::size_t>(x * bx);
                for (int sx = 0; sx < bx; ++sx) {
                    sum.add(colors[sy][at + static_cast<std::size_t>(sx)]);
                    nearest = std::min(nearest, depths[sy][at + static_cast<std::size_t>(sx)]);
                }
            }
            out.color[first + static_cast<std::size_t>(x)] = sum.mean(count);
            out.depth[first + static_cast<std::size_t>(x)] = nearest;
        }
    }
}

/// expandToSamples() for blocks BX wide, or bx when BX is 0: each pixel's first row of samples,
/// then the block's other rows copied from it.
template <int BX>
void expandBlocks(const Framebuffer& frame, int bx, int by, Framebuffer& samples, int threads) {
    if constexpr (BX > 0) bx = BX;
    const int w = frame.width, h = frame.height;
    const auto rowLength = static_cast<std::size_t>(w * bx);
#pragma omp parallel for num_threads(threads) if (static_cast <long>(w) * h > 65536)
    for (int y = 0; y < h; ++y) {
        const std::size_t from = frame.index(0, y), row = samples.index(0, y * by);
        std::uint32_t* colors = samples.color.data() + row;
        float* depths = samples.depth.data() + row;
        for (int x = 0; x < w; ++x) {
            const std::uint32_t c = frame.color[from + static_cast<std::size_t>(x)];
            const float z = frame.depth[from + static_cast<std::size_t>(x)];
            for (int sx = 0; sx < bx; ++sx) {
                colors[static_cast<std::size_t>(x * bx + sx)] = c;
                depths[static_cast<std::size_t>(x * bx + sx)] = z;
            }
        }
        for (int sy = 1; sy < by; ++sy) {
            const std::size_t to = samples.index(0, y * by + sy);
            std::copy_n(colors, rowLength, samples.color.data() + to);
            std::copy_n(depths, rowLength, samples.depth.data() + to);
        }
    }
}

}  // namespace

void resolveSupersampled(const Framebuffer& big, int bx, int by, Framebuffer& out, int threads) {
    out.resize(big.width / bx, big.height / by);
    if (bx == 2 && by == 1)
        resolveBlocks<2, 1>(big, bx, by, out, threads);
    else if (bx == 2 && by == 2)
        resolveBlocks<2, 2>(big, bx, by, out, threads);
    else if (bx == 4 && by == 2)
        resolveBlocks<4, 2>(big, bx, by, out, threads);
    else
        resolveBlocks<0, 0>(big, bx, by, out, threads);
}

void expandToSamples(const Framebuffer& frame, int bx, int by, Framebuffer& samples, int threads) {
    samples.resize(frame.width * bx, frame.height * by);
    if (bx == 2)
        expandBlocks<2>(frame, bx, by, samples, threads);
    else if (bx == 4)
        expandBlocks<4>(frame, bx, by, samples, threads);
    else
        expandBlocks<0>(frame, bx, by, samples, threads);
}

}  // namespace facet::detail
