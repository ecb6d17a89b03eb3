#include "facet/procedural.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

namespace facet {
namespace {

constexpr float kTau = 2.0f * std::numbers::pi_v<float>;

/// Hue in [0,1) to a saturated RGB colour, for colour ramps.
glm::vec3 hue(float h) {
    const glm::vec3 k(0.0f, 2.0f / 3.0f, 1.0f / 3.0f);
    glm::vec3 c;
    for (int i = 0; i < 3; ++i) {
        const float x = std::abs(std::fmod(h + k[i], 1.0f) * 6.0f - 3.0f) - 1.0f;
        c[i] = std::clamp(x, 0.0f, 1.0f);
    }
    return 0.15f + 0.8f * c;  // soften so lighting later has headroom
}

/// Indices of a (cols+1) × (rows+1) vertex lattice, wrapped in u when `wrapU`.
void latticeTriangles(Mesh& m, int cols, int rows, bool wrapU, bool flip) {
    const int stride = wrapU ? cols : cols + 1;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const auto at = [&](int rr, int cc) {
                return static_cast<std::uint32_t>(rr * stride + (wrapU ? cc % cols : cc));
            };
            const std::uint32_t a = at(r, c), b = at(r, c + 1), d = at(r + 1, c),
                                e = at(r + 1, c + 1);
            if (flip)
                m.indices.insert(m.indices.end(), {a, d, b, b, d, e});
            else
                m.indices.insert(m.indices.end(), {a, b, d, b, e, d});
        }
}

/// Small deterministic generator (xorshift32), so tests and assets never depend on <random>'s
/// implementation-defined distributions.
float nextUnit(std::uint32_t& s) {
    s ^= s << 13;
    s ^= s >> 17;
    s ^= s << 5;
    return static_cast<float>(s >> 8) / static_cast<float>(1u << 24);
}

}  // namespace

Mesh makeTorusKnot(int p, int q, int segments, int sides, float tubeRadius) {
    Mesh m;
    const auto curve = [&](float t) {
        const float r = 0.6f + 0.3f * std::cos(static_cast<float>(q) * t);
        return glm::vec3(r * std::cos(static_cast<float>(p) * t),
                         0.3f * std::sin(static_cast<float>(q) * t),
                         r * std::sin(static_cast<float>(p) * t));
    };
    for (int i = 0; i <= segments; ++i) {
        const float t = kTau * static_cast<float>(i % segments) / static_cast<float>(segments);
        const glm::vec3 c = curve(t);
        const glm::vec3 tangent = glm::normalize(curve(t + 1e-3f) - curve(t - 1e-3f));
        // A frame from the curve's centre direction keeps the tube from twisting abruptly.
        glm::vec3 n = glm::normalize(glm::cross(tangent, glm::vec3(0.0f, 1.0f, 0.0f)));
        const glm::vec3 b = glm::cross(tangent, n);
        n = glm::cross(b, tangent);
        for (int j = 0; j < sides; ++j) {
            const float a = kTau * static_cast<float>(j) / static_cast<float>(sides);
            m.positions.push_back(c + tubeRadius * (std::cos(a) * n + std::sin(a) * b));
            const float shade = 0.85f + 0.15f * std::cos(a);
            m.colors.push_back(hue(static_cast<float>(i) / static_cast<float>(segments)) * shade);
        }
    }
    // Rows are the knot segments, columns the tube sides (wrapping).
    latticeTriangles(m, sides, segments, true, false);
    return m;
}

Mesh makeUvSphere(int rings, int sectors) {
    Mesh m;
    for (int r = 0; r <= rings; ++r) {
        const float v = static_cast<float>(r) / static_cast<float>(rings);
        const float theta = std::numbers::pi_v<float> * v;
        for (int s = 0; s <= sectors; ++s) {
            const float u = static_cast<float>(s) / static_cast<float>(sectors);
            const float phi = kTau * u;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            m.positions.push_back(n);
            m.colors.push_back(0.5f * n + 0.5f);
            m.uvs.emplace_back(u, v);
        }
    }
    latticeTriangles(m, sectors, rings, false, false);
    return m;
}

Mesh makeJitteredGrid(int cols, int rows, float jitter, std::uint32_t seed) {
    Mesh m;
    std::uint32_t state = seed ? seed : 1u;
    for (int r = 0; r <= rows; ++r)
        for (int c = 0; c <= cols; ++c) {
            float x = static_cast<float>(c) / static_cast<float>(cols);
            float y = static_cast<float>(r) / static_cast<float>(rows);
            if (c > 0 && c < cols && r > 0 && r < rows) {
                x += (nextUnit(state) - 0.5f) * 2.0f * jitter / static_cast<float>(cols);
                y += (nextUnit(state) - 0.5f) * 2.0f * jitter / static_cast<float>(rows);
            }
            m.positions.emplace_back(x, y, 0.0f);
            m.colors.emplace_back(x, y, 0.5f);
        }
    latticeTriangles(m, cols, rows, false, false);
    return m;
}

Mesh colouredByPosition(Mesh mesh) {
    const Bounds b = computeBounds(mesh);
    const glm::vec3 size = glm::max(b.max - b.min, glm::vec3(1e-30f));  // a flat axis gives 0
    mesh.colors.clear();
    for (const auto& p : mesh.positions) mesh.colors.push_back((p - b.min) / size);
    return mesh;
}

}  // namespace facet
