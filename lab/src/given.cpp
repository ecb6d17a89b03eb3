// The given part of the course's classes: what the framework hands students ready-made.

#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "lab/steps.hpp"

namespace lab {
namespace {

// One bit per step; a stub may run on a render thread while the checks read.
std::atomic<std::uint32_t> gNotStarted{0};

std::uint32_t bit(Step step) {
    return 1u << static_cast<unsigned>(step);
}

// Index of a pixel inside a width × height grid, or -1 outside it.
std::ptrdiff_t pixelIndex(int width, int height, glm::ivec2 p) {
    if (p.x < 0 || p.y < 0 || p.x >= width || p.y >= height) return -1;
    return static_cast<std::ptrdiff_t>(p.y) * width + p.x;
}

}  // namespace

std::string_view stepName(Step step) {
    static constexpr std::array<std::string_view, kStepCount> kNames{
        "setLookAt",
        "setProjection",
        "setCalibration",
        "projectPoints",
        "rasterizeFace",
        "DepthBuffer.testFragment/writeFragment",
        "computeNormals",
        "AmbientLight.getContribution",
        "PointLight.getContribution",
        "Texture.sample",
        "textureShade",
        "rasterizeFacePerspective",
    };
    return kNames[static_cast<std::size_t>(step)];
}

void markNotStarted(Step step) {
    gNotStarted.fetch_or(bit(step));
}

bool wasNotStarted(Step step) {
    return (gNotStarted.load() & bit(step)) != 0;
}

void clearNotStarted() {
    gNotStarted.store(0);
}

glm::ivec2 pixelOf(const Fragment& fragment) {
    // Far outside any image (or NaN) maps to a pixel no grid holds rather than overflowing int.
    const auto coord = [](double v) {
        return std::abs(v) < 1e9 ? static_cast<int>(std::floor(v)) : -1;
    };
    return {coord(fragment.position.x), coord(fragment.position.y)};
}

glm::dmat3 makeBarycentricCoordsMatrix(const Fragment& v1, const Fragment& v2, const Fragment& v3) {
    const double x1 = v1.position.x, y1 = v1.position.y;
    const double x2 = v2.position.x, y2 = v2.position.y;
    const double x3 = v3.position.x, y3 = v3.position.y;
    const double a = x2 * y3 - x3 * y2 + x3 * y1 - x1 * y3 + x1 * y2 - x2 * y1;
    if (a == 0.0 || !std::isfinite(a)) return glm::dmat3(0.0);
    // GLM lists columns: column 0 multiplies the 1, column 1 the x, column 2 the y.
    return glm::dmat3(glm::dvec3(x2 * y3 - x3 * y2, x3 * y1 - x1 * y3, x1 * y2 - x2 * y1) / a,
                      glm::dvec3(y2 - y3, y3 - y1, y1 - y2) / a,
                      glm::dvec3(x3 - x2, x1 - x3, x2 - x1) / a);
}

void DepthBuffer::clear(int newWidth, int newHeight) {
    width = newWidth;
    height = newHeight;
    depth.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height),
                 std::numeric_limits<double>::infinity());
}

glm::dvec3 Texture::at(int x, int y) const {
    return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)];
}

void Canvas::clear(int newWidth, int newHeight, const glm::dvec3& background) {
    width = newWidth;
    height = newHeight;
    color.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), background);
    depth.clear(newWidth, newHeight);
}

void simpleShade(Canvas& canvas, const Fragment& fragment) {
    const std::ptrdiff_t i = pixelIndex(canvas.width, canvas.height, pixelOf(fragment));
    if (i >= 0) canvas.color[static_cast<std::size_t>(i)] = fragment.color;
}

void painterShade(Canvas& canvas, const Fragment& fragment) {
    if (!canvas.depth.testFragment(fragment)) return;
    const std::ptrdiff_t i = pixelIndex(canvas.width, canvas.height, pixelOf(fragment));
    if (i < 0) return;
    canvas.color[static_cast<std::size_t>(i)] = fragment.color;
    canvas.depth.writeFragment(fragment);
}

}  // namespace lab
