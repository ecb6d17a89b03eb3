#pragma once
// Building test geometry in pixels: the world point a camera sees at a given pixel and depth, and
// jittered planes of such points.

#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "facet/camera.hpp"

namespace facet::test {

/// The world point that projects to pixel position (px, py) at camera depth z (spec §4).
inline glm::vec3 worldAt(const Camera& cam, double px, double py, double z) {
    const glm::dvec3 zAxis = glm::normalize(cam.look - cam.eye);
    const glm::dvec3 xAxis = glm::normalize(glm::cross(cam.up, zAxis));
    const glm::dvec3 yAxis = glm::cross(zAxis, xAxis);
    const double x = (px - cam.width / 2.0) / cam.focal * z;
    const double y = (py - cam.height / 2.0) / cam.focal * z;
    return glm::vec3(cam.eye + x * xAxis + y * yAxis + z * zAxis);
}

/// A (cols + 1) × (rows + 1) grid of world points spanning the camera's image and `margin`
/// pixels beyond each side, row by row, at camera depth depth(i, j); the inner points moved by
/// up to ±amplitude/2 pixels in x and in y (a fixed generator from `seed`), so its triangles
/// share every edge and no edge lies on the pixel grid.
template <class Depth>
std::vector<glm::vec3> jitteredGrid(const Camera& cam, int cols, int rows, double margin,
                                    double amplitude, std::uint32_t seed, Depth depth) {
    auto jitter = [&seed, amplitude]() {
        seed = seed * 1664525u + 1013904223u;
        return (static_cast<double>(seed >> 8) / 16777216.0 - 0.5) * amplitude;
    };
    std::vector<glm::vec3> grid;
    for (int j = 0; j <= rows; ++j) {
        for (int i = 0; i <= cols; ++i) {
            double x = -margin + (cam.width + 2.0 * margin) * i / cols,
                   y = -margin + (cam.height + 2.0 * margin) * j / rows;
            if (i > 0 && i < cols && j > 0 && j < rows) {
                x += jitter();
                y += jitter();
            }
            grid.push_back(worldAt(cam, x, y, depth(i, j)));
        }
    }
    return grid;
}

/// Two triangles per cell of a jitteredGrid whose first point is vertex `base`.
inline void appendGridTriangles(std::vector<std::uint32_t>& indices, int cols, int rows,
                                std::uint32_t base = 0) {
    const auto c = static_cast<std::uint32_t>(cols + 1);
    for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < cols; ++i) {
            const auto v = base + static_cast<std::uint32_t>(j) * c + static_cast<std::uint32_t>(i);
            indices.insert(indices.end(), {v, v + 1, v + c, v + 1, v + c + 1, v + c});
        }
    }
}

}  // namespace facet::test
