// The reference samplers (spec §7 in double precision, no shortcuts).

#include "reference/samplers.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace facet::reference {

double wrapCoord(double t) {
    if (!std::isfinite(t)) return 0.0;
    return t - std::floor(t);
}

glm::dvec3 texelColor(const MipLevel& level, int x, int y) {
    const std::uint32_t p = level.at(x, y);
    return glm::dvec3(p & 0xFFu, (p >> 8) & 0xFFu, (p >> 16) & 0xFFu) / 255.0;
}

glm::dvec3 sampleNearest(const Texture& tex, glm::dvec2 uv) {
    const MipLevel& l = tex.level(0);
    const double x = std::floor(wrapCoord(uv.x) * l.width);
    const double y = std::floor(wrapCoord(uv.y) * l.height);
    return reference::texelColor(l, static_cast<int>(std::min(x, l.width - 1.0)),
                                 static_cast<int>(std::min(y, l.height - 1.0)));
}

glm::dvec3 sampleBilinear(const Texture& tex, glm::dvec2 uv, int level) {
    const MipLevel& l = tex.level(std::clamp(level, 0, tex.levelCount() - 1));
    // Continuous texel coordinates with texel i's centre at i.
    const double x = wrapCoord(uv.x) * l.width - 0.5;
    const double y = wrapCoord(uv.y) * l.height - 0.5;
    const double x0 = std::floor(x);
    const double y0 = std::floor(y);
    const double fx = x - x0;
    const double fy = y - y0;
    const auto wrapIndex = [](double i, int n) {
        const int k = static_cast<int>(i) % n;
        return k < 0 ? k + n : k;
    };
    const int i0 = wrapIndex(x0, l.width);
    const int i1 = wrapIndex(x0 + 1.0, l.width);
    const int j0 = wrapIndex(y0, l.height);
    const int j1 = wrapIndex(y0 + 1.0, l.height);
    return (1.0 - fx) * (1.0 - fy) * reference::texelColor(l, i0, j0) +
           fx * (1.0 - fy) * reference::texelColor(l, i1, j0) +
           (1.0 - fx) * fy * reference::texelColor(l, i0, j1) +
           fx * fy * reference::texelColor(l, i1, j1);
}

double mipLevel(const Texture& tex, glm::dvec2 duvDx, glm::dvec2 duvDy) {
    if (std::isnan(duvDx.x) || std::isnan(duvDx.y) || std::isnan(duvDy.x) || std::isnan(duvDy.y))
        return 0.0;
    const double w = tex.width();
    const double h = tex.height();
    const double rho =
        std::max(std::hypot(duvDx.x * w, duvDx.y * h), std::hypot(duvDy.x * w, duvDy.y * h));
    const double lod = std::log2(rho);
    if (lod <= 0.0) return 0.0;
    return std::min(lod, tex.levelCount() - 1.0);
}

glm::dvec3 sampleTrilinear(const Texture& tex, glm::dvec2 uv, double lod) {
    const double l = std::isnan(lod) ? 0.0 : std::clamp(lod, 0.0, tex.levelCount() - 1.0);
    const double l0 = std::floor(l);
    const double f = l - l0;
    const int level = static_cast<int>(l0);
    if (f == 0.0) return reference::sampleBilinear(tex, uv, level);
    return (1.0 - f) * reference::sampleBilinear(tex, uv, level) +
           f * reference::sampleBilinear(tex, uv, level + 1);
}

}  // namespace facet::reference
