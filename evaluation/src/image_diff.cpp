// Frame against frame (image_diff.hpp).

#include "facet/evaluation/image_diff.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <numeric>

#include "facet/colormap.hpp"

namespace facet {

int pixelError(std::uint32_t a, std::uint32_t b) {
    int worst = 0;
    for (int shift = 0; shift < 24; shift += 8) {
        const int ca = static_cast<int>((a >> shift) & 0xFFu);
        const int cb = static_cast<int>((b >> shift) & 0xFFu);
        worst = std::max(worst, std::abs(ca - cb));
    }
    return worst;
}

ImageDiff diffImages(const Framebuffer& a, const Framebuffer& b, Framebuffer* heat, int scale,
                     DiffPixels over) {
    ImageDiff d;
    if (a.width != b.width || a.height != b.height || a.color.size() != b.color.size()) {
        d.sameSize = false;
        if (heat) {
            heat->resize(a.width, a.height);
            heat->clear(0);
        }
        return d;
    }
    const std::size_t n = a.color.size();
    const bool everyPixel = over == DiffPixels::all || a.depth.size() != n || b.depth.size() != n;
    // First pass: the error of each pixel, kept in the heat frame's colour plane (or nowhere)
    // so the second pass can colour it once the largest error is known.
    std::uint32_t* errors = nullptr;
    if (heat) {
        heat->resize(a.width, a.height);
        errors = heat->color.data();
    }
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const int e = pixelError(a.color[i], b.color[i]);
        d.pixels += everyPixel || e > 0 || a.depth[i] != kEmptyDepth || b.depth[i] != kEmptyDepth;
        sum += static_cast<std::uint64_t>(e);
        d.pixelsDiffering += e > 0;
        d.maxError = std::max(d.maxError, e);
        if (errors) errors[i] = static_cast<std::uint32_t>(e);
    }
    d.meanError = d.pixels ? static_cast<double>(sum) / static_cast<double>(d.pixels) : 0.0;
    if (!heat) return d;

    // A 256-entry table: one viridis evaluation per error value, not per pixel.
    const int top = scale > 0 ? scale : std::max(1, d.maxError);
    std::array<std::uint32_t, 256> lut{};
    lut[0] = packRgba(0, 0, 0);
    for (int e = 1; e < 256; ++e) {
        const glm::dvec3 c = viridis(static_cast<double>(e) / static_cast<double>(top));
        lut[static_cast<std::size_t>(e)] = packRgba(toByte(c.r), toByte(c.g), toByte(c.b));
    }
    for (std::size_t i = 0; i < n; ++i) errors[i] = lut[errors[i]];
    return d;
}

void DiffHistogram::add(int error) {
    ++count[static_cast<std::size_t>(std::clamp(error, 0, 255))];
    ++total;
}

int DiffHistogram::percentile(double fraction) const {
    const auto target = static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(total)));
    std::size_t seen = 0;
    for (int e = 0; e < 256; ++e) {
        seen += count[static_cast<std::size_t>(e)];
        if (seen >= target && seen > 0) return e;
    }
    return 0;
}

int DiffHistogram::max() const {
    for (int e = 255; e > 0; --e)
        if (count[static_cast<std::size_t>(e)] > 0) return e;
    return 0;
}

std::size_t DiffHistogram::above(int error) const {
    const std::size_t from = static_cast<std::size_t>(std::clamp(error + 1, 0, 256));
    return std::accumulate(count.begin() + static_cast<std::ptrdiff_t>(from), count.end(),
                           std::size_t{0});
}

double DiffHistogram::shareAbove(int error) const {
    return static_cast<double>(above(error)) / static_cast<double>(std::max<std::size_t>(1, total));
}

}  // namespace facet
