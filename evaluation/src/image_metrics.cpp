// Error metrics of an 8-bit image against a truth (image_metrics.hpp). Everything is in 8-bit
// steps (LSB): against a ground truth in linear float, a rounding error alone is at most half a
// step, so a perfect renderer scores RMSE about 0.29 and max 0.5, never 0.

#include "facet/evaluation/image_metrics.hpp"

#include "facet/evaluation/ground_truth.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace facet {
namespace {

/// The R, G, B bytes of a packed pixel.
std::array<double, 3> channels(std::uint32_t p) {
    return {static_cast<double>(p & 0xFF), static_cast<double>((p >> 8) & 0xFF),
            static_cast<double>((p >> 16) & 0xFF)};
}

/// A linear colour in 8-bit steps, unrounded.
std::array<double, 3> channels(const glm::vec3& c) {
    return {255.0 * static_cast<double>(c[0]), 255.0 * static_cast<double>(c[1]),
            255.0 * static_cast<double>(c[2])};
}

/// Sums over the pixels compared so far.
struct Totals {
    double sumSquares = 0.0;
    double sumAbs = 0.0;
    double maxError = 0.0;
    std::size_t over2 = 0;
    std::size_t pixels = 0;

    /// Adds one pixel; returns its sum of squared channel differences.
    double add(const std::array<double, 3>& got, const std::array<double, 3>& truth) {
        double squares = 0.0, worst = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double d = std::abs(got[c] - truth[c]);
            squares += d * d;
            sumAbs += d;
            worst = std::max(worst, d);
        }
        sumSquares += squares;
        maxError = std::max(maxError, worst);
        over2 += worst > 2.0 ? 1 : 0;
        ++pixels;
        return squares;
    }

    ImageError result() const {
        ImageError e;
        e.pixels = pixels;
        e.maxError = maxError;
        if (pixels == 0) return e;
        const double channelCount = 3.0 * static_cast<double>(pixels);
        e.rmse = std::sqrt(sumSquares / channelCount);
        e.meanError = sumAbs / channelCount;
        e.psnr = e.rmse > 0.0 ? 20.0 * std::log10(255.0 / e.rmse)
                              : std::numeric_limits<double>::infinity();
        e.over2Lsb = static_cast<double>(over2) / static_cast<double>(pixels);
        return e;
    }
};

}  // namespace

ImageError measureError(std::span<const std::uint32_t> rgba, std::span<const glm::vec3> truth) {
    if (rgba.size() != truth.size()) return {};
    Totals t;
    for (std::size_t i = 0; i < rgba.size(); ++i) t.add(channels(rgba[i]), channels(truth[i]));
    return t.result();
}

ImageError measureError(std::span<const std::uint32_t> rgba, std::span<const std::uint32_t> truth,
                        std::span<const std::uint8_t> include) {
    if (rgba.size() != truth.size() || (!include.empty() && include.size() != rgba.size()))
        return {};
    Totals t;
    for (std::size_t i = 0; i < rgba.size(); ++i)
        if (include.empty() || include[i]) t.add(channels(rgba[i]), channels(truth[i]));
    return t.result();
}

namespace {

bool sameSize(const Framebuffer& frame, const GroundTruth& truth) {
    return frame.width == truth.width && frame.height == truth.height &&
           frame.color.size() == truth.coverage.size() && frame.color.size() == truth.color.size();
}

}  // namespace

ImageError measureError(const Framebuffer& frame, const GroundTruth& truth) {
    if (!sameSize(frame, truth)) return {};
    ImageError e = measureError(frame.color, truth.color);
    const ImageError interior = interiorError(frame, truth);
    e.interiorPixels = interior.pixels;
    e.interiorRmse = interior.rmse;
    return e;
}

ImageError interiorError(const Framebuffer& frame, const GroundTruth& truth) {
    if (!sameSize(frame, truth)) return {};
    Totals t;
    for (std::size_t i = 0; i < frame.color.size(); ++i)
        if (!(truth.coverage[i] < 1.0f)) t.add(channels(frame.color[i]), channels(truth.color[i]));
    return t.result();
}

}  // namespace facet
