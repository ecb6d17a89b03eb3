#pragma once
// How far an 8-bit image is from another or from a ground truth (ground_truth.hpp): RMSE, PSNR,
// the largest error and the share of pixels off by more than 2 LSB.

#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/vec3.hpp>

#include "facet/framebuffer.hpp"

namespace facet {

struct GroundTruth;  // ground_truth.hpp

/// How far an 8-bit image is from a truth, in 8-bit steps (1 LSB = 1/255).
struct ImageError {
    double rmse = 0.0;       ///< root mean square over every channel of every pixel
    double psnr = 0.0;       ///< 20·log10(255 / rmse) in dB; +inf when rmse is 0
    double maxError = 0.0;   ///< largest channel difference
    double over2Lsb = 0.0;   ///< share (0…1) of pixels with some channel more than 2 LSB off
    double meanError = 0.0;  ///< mean absolute difference over every channel of every pixel
    std::size_t pixels = 0;  ///< pixels compared
    /// RMSE over the pixels the ground truth covers fully (coverage 1) only, so without the
    /// silhouette aliasing that every one-sample-per-pixel method shares; measureError(Framebuffer,
    /// GroundTruth) fills it, the span overloads leave 0.
    double interiorRmse = 0.0;
    std::size_t interiorPixels = 0;  ///< pixels in interiorRmse
};

/// Compares packed RGBA8 pixels (alpha ignored) with linear colours in [0,1], pixel by pixel;
/// the spans must have the same length.
ImageError measureError(std::span<const std::uint32_t> rgba, std::span<const glm::vec3> truth);

/// Compares two packed RGBA8 images (alpha ignored) over the pixels whose `include` byte is
/// non-zero (every pixel when `include` is empty); the spans must have the same length.
ImageError measureError(std::span<const std::uint32_t> rgba, std::span<const std::uint32_t> truth,
                        std::span<const std::uint8_t> include = {});

/// Compares a rendered frame with the ground truth of the same size (an empty result, pixels
/// = 0, when the sizes differ).
ImageError measureError(const Framebuffer& frame, const GroundTruth& truth);

/// Compares a rendered frame with the ground truth of the same size over the pixels the truth
/// covers fully (coverage 1) only: every field as measureError's, interiorRmse left 0.
ImageError interiorError(const Framebuffer& frame, const GroundTruth& truth);

}  // namespace facet
