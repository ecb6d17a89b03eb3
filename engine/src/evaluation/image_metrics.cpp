// Error metrics of an 8-bit image against a ground truth in linear float (ground_truth.hpp).
// Everything is in 8-bit steps (LSB): a rounding error alone is at most half a step, so a
// perfect renderer scores RMSE about 0.29 and max 0.5, never 0.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "facet/ground_truth.hpp"

namespace facet {
namespace {

// Sum of the squared channel differences of one pixel, in 8-bit steps; `worst` gets the largest.
double squaredError(std::uint32_t p, const glm::vec3& truth, double& worst) {
    const std::array<double, 3> got{static_cast<double>(p & 0xFF),
                                    static_cast<double>((p >> 8) & 0xFF),
                                    static_cast<double>((p >> 16) & 0xFF)};
    double sum = 0.0;
    worst = 0.0;
    for (int c = 0; c < 3; ++c) {
        const double d = std::abs(got[c] - 255.0 * static_cast<double>(truth[c]));
        sum += d * d;
        worst = std::max(worst, d);
    }
    return sum;
}

}  // namespace

ImageError measureError(std::span<const std::uint32_t> rgba, std::span<const glm::vec3> truth) {
    ImageError e;
    if (rgba.size() != truth.size()) return e;
    double sumSquares = 0.0;
    std::size_t over = 0;
    for (std::size_t i = 0; i < rgba.size(); ++i) {
        double worst = 0.0;
        sumSquares += squaredError(rgba[i], truth[i], worst);
        e.maxError = std::max(e.maxError, worst);
        over += worst > 2.0 ? 1 : 0;
    }
    e.pixels = rgba.size();
    if (e.pixels == 0) return e;
    e.rmse = std::sqrt(sumSquares / (3.0 * static_cast<double>(e.pixels)));
    e.psnr =
        e.rmse > 0.0 ? 20.0 * std::log10(255.0 / e.rmse) : std::numeric_limits<double>::infinity();
    e.over2Lsb = static_cast<double>(over) / static_cast<double>(e.pixels);
    return e;
}

ImageError measureError(const Framebuffer& frame, const GroundTruth& truth) {
    if (frame.width != truth.width || frame.height != truth.height ||
        frame.color.size() != truth.coverage.size())
        return {};
    ImageError e = measureError(frame.color, truth.color);
    double sumSquares = 0.0;
    for (std::size_t i = 0; i < frame.color.size(); ++i) {
        if (truth.coverage[i] < 1.0f) continue;
        double worst = 0.0;
        sumSquares += squaredError(frame.color[i], truth.color[i], worst);
        ++e.interiorPixels;
    }
    if (e.interiorPixels > 0)
        e.interiorRmse = std::sqrt(sumSquares / (3.0 * static_cast<double>(e.interiorPixels)));
    return e;
}

}  // namespace facet
