#pragma once
// The shading half of the reference path (raster.cpp and lines_points.cpp are the geometry half:
// clipping, coverage, lines, points). Here: what a vertex carries, how a fragment's
// interpolation weights are formed in each Interp mode, and how a fragment becomes a colour and
// lands in the image. Rules 5, 8(b), 8(d) and 11 to 14 of raster.cpp.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/reference.hpp"
#include "facet/settings.hpp"

namespace facet::reference::detail {

/// A vertex with every varying of rule 10.
struct Vertex {
    glm::dvec4 clip{0.0};
    glm::dvec3 color{1.0};   ///< rgb (lit already for Gouraud)
    glm::dvec2 uv{0.0};      ///< texture coordinates
    glm::dvec3 normal{0.0};  ///< world-space normal, unit or zero
    glm::dvec3 world{0.0};   ///< world-space position
};

/// a + t·(b − a) for the position and every varying (near clipping).
Vertex lerp(const Vertex& a, const Vertex& b, double t);

/// E_ab(p): twice the signed area of (a, b, p); positive on the inside of a triangle with A > 0.
inline double edgeFunction(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

/// A triangle on screen (after the divide by w) with area > 0: its barycentrics are linear
/// functions of the screen point, defined (extrapolated) everywhere, not only inside.
struct ScreenTriangle {
    std::array<glm::dvec2, 3> s{};  ///< screen positions
    std::array<double, 3> w{};      ///< clip.w of each vertex (≥ near > 0)
    double area = 1.0;              ///< E_{s0 s1}(s2) > 0

    /// λ_i(p) = E_i(p) / area, E_i being the edge opposite vertex i.
    std::array<double, 3> barycentric(const glm::dvec2& p) const;
    /// q(p) = Σ λ_i(p) / w_i, the interpolated 1/w; depth is 1/q.
    double inverseW(const glm::dvec2& p) const;
    /// λ'_i(p) = (λ_i(p) / w_i) / q(p).
    std::array<double, 3> perspective(const glm::dvec2& p) const;
};

/// Rule 11: the weights of pixel (x, y) for the settings' interpolation.
std::array<double, 3> triangleWeights(const ScreenTriangle& tri, const RenderSettings& settings,
                                      int x, int y);

/// Rule 11: the weights at t = k/n along the segment a-b.
std::array<double, 2> lineWeights(double t, double wa, double wb, Interp interp);

/// Rule 13: (du/dx, dv/dx) and (du/dy, dv/dy) at screen point p of the interpolation `interp`
/// uses (Affine: the constant gradient; Perspective and Subdivided: the analytic derivative of
/// the perspective-correct uv).
std::array<glm::dvec2, 2> uvDerivatives(const ScreenTriangle& tri, const std::array<Vertex, 3>& v,
                                        Interp interp, const glm::dvec2& p);

/// True when fragments need a level of detail (Texture shader, Trilinear, a texture).
bool needsLod(const RenderSettings& settings, const Input& input);

/// What the fragments of one pass become: the main pass shades them (rules 12, 13), the
/// normals display paints them red (rule 14).
struct Pass {
    const RenderSettings& settings;
    const Input& input;
    bool normals = false;
};

/// Index of pixel (x, y), which must be in the image.
inline std::size_t pixelIndex(const Image& img, std::int64_t x, std::int64_t y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) +
           static_cast<std::size_t>(x);
}

/// One fragment at pixel (x, y) of a primitive with vertices v (1 to 3) and interpolation
/// weights w (rule 11): its colour (rules 12, 13), the depth rule (rule 5) and the ambiguity
/// flags 8(b) and 8(d). `lod` is the Trilinear level of detail (0 for lines and points).
void fragment(Image& img, const Pass& pass, std::int64_t x, std::int64_t y, double depth,
              std::span<const Vertex> v, std::span<const double> w, double lod);

/// Rule 5, Depth shader: every drawn pixel's depth to viridis over [dmin, dmax].
void mapDepthToColor(Image& img);

}  // namespace facet::reference::detail
