#include "facet/colormap.hpp"

#include <array>
#include <cmath>

namespace facet {
namespace {

// Viridis sampled at t = k/16 (8-bit sRGB values of the published map). Seventeen samples keep
// the linear interpolation within about one 8-bit step of the full 256-entry table.
constexpr std::array<std::array<unsigned char, 3>, 17> kViridis{{
    {68, 1, 84},
    {72, 26, 108},
    {71, 47, 125},
    {65, 68, 135},
    {59, 82, 139},
    {52, 97, 141},
    {44, 113, 142},
    {38, 130, 142},
    {33, 145, 140},
    {31, 160, 136},
    {40, 174, 128},
    {63, 188, 115},
    {94, 201, 98},
    {132, 212, 75},
    {173, 220, 48},
    {216, 226, 25},
    {253, 231, 37},
}};

glm::dvec3 sample(std::size_t k) {
    return glm::dvec3(kViridis[k][0], kViridis[k][1], kViridis[k][2]) / 255.0;
}

}  // namespace

glm::dvec3 viridis(double t) {
    if (!(t > 0.0)) return sample(0);  // also catches NaN
    if (t >= 1.0) return sample(kViridis.size() - 1);
    const double x = t * static_cast<double>(kViridis.size() - 1);
    const double k = std::floor(x);
    const auto i = static_cast<std::size_t>(k);
    const double f = x - k;
    return sample(i) * (1.0 - f) + sample(i + 1) * f;
}

}  // namespace facet
