#pragma once
// Supersampling (RenderSettings::supersample): the frame rendered at N×N the size and averaged
// down, so coverage, texture and lighting are sampled N² times per pixel. Costs about N² times a
// frame; it is the engine's answer to silhouette aliasing, and a point on `facet accuracy`'s chart.
//
// The big image's camera is resizedCamera() to n times the size: width, height and focal times n.
// The principal point is half the image (conventions §4), so big pixel (I + ½, J + ½) lands at
// ((I + ½)/n, (J + ½)/n) in the frame's pixels: an even n×n grid of sample centres in each pixel.

#include <bit>
#include <cstdint>

#include "facet/framebuffer.hpp"

namespace facet::detail {

/// Largest accepted samples per axis (16 per pixel).
inline constexpr int kMaxSupersample = 4;

/// The sum of packed RGBA pixels, channel by channel, and their rounded mean.
struct RgbaSum {
    std::uint32_t sum[4] = {0, 0, 0, 0};

    /// Adds one packed pixel.
    void add(std::uint32_t c) {
        for (int k = 0; k < 4; ++k) sum[k] += (c >> (8 * k)) & 0xFFu;
    }
    /// The mean of `count` pixels, each channel rounded to nearest, packed.
    std::uint32_t mean(std::uint32_t count) const {
        // Every block but 3×3 has a power-of-two count: a shift, not a division per channel.
        const int shift = std::has_single_bit(count) ? std::countr_zero(count) : -1;
        std::uint32_t packed = 0;
        for (int k = 0; k < 4; ++k) {
            const std::uint32_t v = sum[k] + count / 2;
            packed |= (shift >= 0 ? v >> shift : v / count) << (8 * k);
        }
        return packed;
    }
};

/// Averages each bx×by block of `big` into one pixel of `out` (resized to big / block): each
/// channel the rounded mean of the 8-bit values (alpha too), depth the nearest of the block
/// (empty only if all are). The box filter of supersampling (n×n blocks) and of multisampling's
/// resolve (SampleBlock, facet/multisample.hpp).
void resolveSupersampled(const Framebuffer& big, int bx, int by, Framebuffer& out, int threads);

/// Multisampling's start: `samples` resized to `frame` times the block and every sample set to
/// its pixel's colour and depth, so a draw continues what is in the frame.
void expandToSamples(const Framebuffer& frame, int bx, int by, Framebuffer& samples, int threads);

}  // namespace facet::detail
