#pragma once
// Supersampling (RenderSettings::supersample): the frame rendered at N×N the size and averaged
// down, so coverage, texture and lighting are sampled N² times per pixel. Costs about N² times a
// frame; it is the engine's answer to silhouette aliasing, and a point on `facet accuracy`'s chart.
//
// The big image's camera is resizedCamera() to n times the size: width, height and focal times n.
// The principal point is half the image (spec §4), so big pixel (I + ½, J + ½) lands at
// ((I + ½)/n, (J + ½)/n) in the frame's pixels: an even n×n grid of sample centres in each pixel.

#include <bit>
#include <cstdint>

#include "facet/framebuffer.hpp"

namespace facet::detail {

/// Largest accepted samples per axis (16 per pixel).
inline constexpr int kMaxSupersample = 4;

/// The sum of packed RGBA pixels, channel by channel, and their rounded mean. The channels are
/// summed two to a word in 16-bit fields (R and B, G and A): up to 256 pixels of 255 fit, and
/// the sums are one mask and add per pixel instead of four.
struct RgbaSum {
    static constexpr std::uint32_t kFields = 0x00FF00FFu;  ///< bytes 0 and 2
    std::uint32_t rb = 0, ga = 0;  ///< sums of R (bits 0-15) and B (16-31); of G and A

    /// Adds one packed pixel.
    void add(std::uint32_t c) {
        rb += c & kFields;
        ga += (c >> 8) & kFields;
    }
    /// The mean of `count` (1 to 256) pixels, each channel rounded to nearest, packed.
    std::uint32_t mean(std::uint32_t count) const {
        const std::uint32_t half = count / 2 * 0x00010001u;
        // Every block but 3×3 has a power-of-two count: one shift for two fields (a field's
        // mean fits its low byte; what the shift brings down from the field above is masked).
        if (std::has_single_bit(count)) {
            const int shift = std::countr_zero(count);
            return ((rb + half) >> shift & kFields) | ((ga + half) >> shift & kFields) << 8;
        }
        auto fields = [count](std::uint32_t v) {
            return ((v & 0xFFFFu) / count) | ((v >> 16) / count) << 16;
        };
        return fields(rb + half) | fields(ga + half) << 8;
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
