// The shading half of the reference path: interpolation weights (rule 11), lighting (rule 12),
// texturing (rule 13) and the depth rule (rule 5), written the obvious way in double. See the
// RULES in raster.cpp.

#include "reference/shading.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "facet/colormap.hpp"
#include "facet/framebuffer.hpp"
#include "facet/lighting.hpp"
#include "facet/normals.hpp"
#include "facet/texture.hpp"
#include "reference/samplers.hpp"

namespace facet::reference::detail {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The fast path keeps float depths; LESS between nearly equal depths is a coin toss there.
constexpr double kDepthMargin = 1e-5;
// The fast path interpolates uv in float; a Nearest lookup this close to a texel border may pick
// the neighbour there (rule 8(d)).
constexpr double kTexelMargin = 1.0 / 256.0;
// The colour of the normals display (rule 14).
constexpr glm::dvec3 kNormalColor{1.0, 0.0, 0.0};

// The varyings of one fragment: Σ weight_i · varying_i.
struct Varyings {
    glm::dvec3 color{0.0};
    glm::dvec2 uv{0.0};
    glm::dvec3 normal{0.0};
    glm::dvec3 world{0.0};
};

Varyings interpolate(std::span<const Vertex> v, std::span<const double> weights) {
    Varyings f;
    for (std::size_t i = 0; i < v.size(); ++i) {
        f.color += weights[i] * v[i].color;
        f.uv += weights[i] * v[i].uv;
        f.normal += weights[i] * v[i].normal;
        f.world += weights[i] * v[i].world;
    }
    return f;
}

}  // namespace

Vertex lerp(const Vertex& a, const Vertex& b, double t) {
    return {a.clip + t * (b.clip - a.clip), a.color + t * (b.color - a.color),
            a.uv + t * (b.uv - a.uv), a.normal + t * (b.normal - a.normal),
            a.world + t * (b.world - a.world)};
}

std::array<double, 3> ScreenTriangle::barycentric(const glm::dvec2& p) const {
    // E_i is the edge opposite vertex i.
    return {edgeFunction(s[1], s[2], p) / area, edgeFunction(s[2], s[0], p) / area,
            edgeFunction(s[0], s[1], p) / area};
}

double ScreenTriangle::inverseW(const glm::dvec2& p) const {
    const std::array<double, 3> lambda = barycentric(p);
    double q = 0.0;
    for (std::size_t i = 0; i < 3; ++i) q += lambda[i] / w[i];
    return q;
}

std::array<double, 3> ScreenTriangle::perspective(const glm::dvec2& p) const {
    const std::array<double, 3> lambda = barycentric(p);
    const double q = inverseW(p);
    std::array<double, 3> weights{};
    for (std::size_t i = 0; i < 3; ++i) weights[i] = (lambda[i] / w[i]) / q;
    return weights;
}

std::array<double, 3> triangleWeights(const ScreenTriangle& tri, const RenderSettings& settings,
                                      int x, int y) {
    const glm::dvec2 p{x + 0.5, y + 0.5};
    switch (settings.interp) {
        case Interp::Affine:
            return tri.barycentric(p);
        case Interp::Perspective:
            return tri.perspective(p);
        case Interp::Subdivided:
            break;
    }
    // Exact (perspective) at the pixel columns x0 = N·floor(x/N) and x1 = x0 + N of this row,
    // extrapolated from the triangle's planes where those centres lie outside it, and linear in
    // between. Where q is not a positive finite number at either end (the columns reach past
    // the horizon of the triangle's plane) the pixel gets its exact weights instead.
    const int n = std::clamp(settings.subdivision, kMinSubdivision, kMaxSubdivision);
    const int x0 = n * static_cast<int>(std::floor(static_cast<double>(x) / n));
    const int x1 = x0 + n;
    const glm::dvec2 a{x0 + 0.5, y + 0.5};
    const glm::dvec2 b{x1 + 0.5, y + 0.5};
    const double qa = tri.inverseW(a);
    const double qb = tri.inverseW(b);
    if (!(qa > 0.0 && std::isfinite(qa)) || !(qb > 0.0 && std::isfinite(qb))) {
        return tri.perspective(p);
    }
    const double t = static_cast<double>(x - x0) / n;
    const std::array<double, 3> wa = tri.perspective(a);
    const std::array<double, 3> wb = tri.perspective(b);
    std::array<double, 3> weights{};
    for (std::size_t i = 0; i < 3; ++i) weights[i] = (1.0 - t) * wa[i] + t * wb[i];
    return weights;
}

std::array<double, 2> lineWeights(double t, double wa, double wb, Interp interp) {
    if (interp == Interp::Affine) return {1.0 - t, t};
    // Perspective, and Subdivided (which lines treat as Perspective).
    const double q = (1.0 - t) / wa + t / wb;
    return {(1.0 - t) / wa / q, t / wb / q};
}

std::array<glm::dvec2, 2> uvDerivatives(const ScreenTriangle& tri, const std::array<Vertex, 3>& v,
                                        Interp interp, const glm::dvec2& p) {
    // The barycentrics are linear: dλ_i = ∇E_i / area with E_i = E_ab, a = s[i+1], b = s[i+2],
    // ∂E_ab/∂x = a.y − b.y and ∂E_ab/∂y = b.x − a.x.
    std::array<glm::dvec2, 3> grad{};
    for (std::size_t i = 0; i < 3; ++i) {
        const glm::dvec2& a = tri.s[(i + 1) % 3];
        const glm::dvec2& b = tri.s[(i + 2) % 3];
        grad[i] = glm::dvec2(a.y - b.y, b.x - a.x) / tri.area;
    }
    glm::dvec2 duvDx{0.0};
    glm::dvec2 duvDy{0.0};
    if (interp == Interp::Affine) {
        // uv = Σ λ_i uv_i: a plane, the same gradient everywhere.
        for (std::size_t i = 0; i < 3; ++i) {
            duvDx += grad[i].x * v[i].uv;
            duvDy += grad[i].y * v[i].uv;
        }
        return {duvDx, duvDy};
    }
    // Perspective and Subdivided: uv = A / q with A = Σ λ_i uv_i / w_i and q = Σ λ_i / w_i, so
    // d(uv) = (dA − uv·dq) / q.
    const std::array<double, 3> lambda = tri.barycentric(p);
    double q = 0.0;
    glm::dvec2 a{0.0};
    glm::dvec2 dq{0.0};
    glm::dvec2 dAdx{0.0};
    glm::dvec2 dAdy{0.0};
    for (std::size_t i = 0; i < 3; ++i) {
        q += lambda[i] / tri.w[i];
        a += (lambda[i] / tri.w[i]) * v[i].uv;
        dq += grad[i] / tri.w[i];
        dAdx += (grad[i].x / tri.w[i]) * v[i].uv;
        dAdy += (grad[i].y / tri.w[i]) * v[i].uv;
    }
    const glm::dvec2 uv = a / q;
    return {(dAdx - uv * dq.x) / q, (dAdy - uv * dq.y) / q};
}

namespace {

// Rule 12: the fragment's colour before texturing. `own`: the varyings are one vertex's own
// values (a point), whose normal is used as it is, exactly as Gouraud lighting uses it.
glm::dvec3 litColor(const Varyings& f, const RenderSettings& settings, const Input& input,
                    bool own) {
    // Off: the vertex colours; Gouraud: they were lit per vertex already.
    if (settings.lighting != Lighting::Phong) return f.color;
    // Phong: renormalise the interpolated normal; a zero one stays zero (ambient only).
    const double length = glm::length(f.normal);
    const glm::dvec3 n = own ? f.normal : length > 0.0 ? f.normal / length : glm::dvec3(0.0);
    return facet::shade(f.color, lightIntensity(f.world, n, input.eye, input.lighting));
}

// Rule 13: the texel under the fragment; a missing texture is white.
glm::dvec3 texel(const Varyings& f, const RenderSettings& settings, const Input& input,
                 double lod) {
    if (input.texture == nullptr) return glm::dvec3(1.0);
    switch (settings.filter) {
        case TextureFilter::Nearest:
            return reference::sampleNearest(*input.texture, f.uv);
        case TextureFilter::Bilinear:
            return reference::sampleBilinear(*input.texture, f.uv, 0);
        case TextureFilter::Trilinear:
            return reference::sampleTrilinear(*input.texture, f.uv, lod);
    }
    return glm::dvec3(1.0);
}

// Rules 12 and 13: the colour of a fragment from its varyings.
glm::dvec3 fragmentColor(const Varyings& f, const RenderSettings& settings, const Input& input,
                         double lod, bool own) {
    if (settings.shader != ShaderKind::Texture) return litColor(f, settings, input, own);
    const glm::dvec3 t = texel(f, settings, input, lod);
    return settings.combine ? t * litColor(f, settings, input, own) : t;
}

// Rule 8(d): a Nearest lookup of the texture within 1/256 texel of a texel border.
bool nearTexelBorder(const Varyings& f, const RenderSettings& settings, const Input& input) {
    if (settings.shader != ShaderKind::Texture || settings.filter != TextureFilter::Nearest ||
        input.texture == nullptr) {
        return false;
    }
    const double x = reference::wrapCoord(f.uv.x) * input.texture->width();
    const double y = reference::wrapCoord(f.uv.y) * input.texture->height();
    return std::abs(x - std::round(x)) <= kTexelMargin ||
           std::abs(y - std::round(y)) <= kTexelMargin;
}

// Rule 5: without a depth test the colour is overwritten (last wins), with one LESS decides and
// depth is written too. Returns whether the fragment was written.
bool writeFragment(Image& img, bool depthTest, std::int64_t x, std::int64_t y, double depth,
                   const glm::dvec3& color) {
    const std::size_t i = pixelIndex(img, x, y);
    if (!depthTest) {
        img.color[i] = color;
        return true;
    }
    const double old = img.depth[i];
    // Rule 8(b): a float depth test may order two nearly equal depths the other way.
    if (std::isfinite(old) && std::abs(depth - old) <= kDepthMargin * std::max(depth, old)) {
        img.ambiguous[i] = 1;
    }
    if (!(depth < old)) return false;  // LESS: on a tie the first drawn stays
    img.color[i] = color;
    img.depth[i] = depth;
    return true;
}

}  // namespace

bool needsLod(const RenderSettings& settings, const Input& input) {
    return settings.shader == ShaderKind::Texture && settings.filter == TextureFilter::Trilinear &&
           input.texture != nullptr;
}

void fragment(Image& img, const Pass& pass, std::int64_t x, std::int64_t y, double depth,
              std::span<const Vertex> v, std::span<const double> w, double lod) {
    const bool depthTest = pass.settings.shader != ShaderKind::Simple;
    if (pass.normals) {
        writeFragment(img, depthTest, x, y, depth, kNormalColor);
        return;
    }
    const Varyings f = interpolate(v, w);
    const bool own = v.size() == 1;  // a point: the vertex's own values (rule 11)
    const glm::dvec3 color = fragmentColor(f, pass.settings, pass.input, lod, own);
    if (writeFragment(img, depthTest, x, y, depth, color) &&
        nearTexelBorder(f, pass.settings, pass.input)) {
        img.ambiguous[pixelIndex(img, x, y)] = 1;  // rule 8(d)
    }
}

void mapDepthToColor(Image& img) {
    double dmin = kInf;
    double dmax = -kInf;
    for (const double d : img.depth) {
        if (!std::isfinite(d)) continue;
        dmin = std::min(dmin, d);
        dmax = std::max(dmax, d);
    }
    for (std::size_t i = 0; i < img.depth.size(); ++i) {
        const double d = img.depth[i];
        if (!std::isfinite(d)) continue;
        const double t = dmax > dmin ? (d - dmin) / (dmax - dmin) : 0.0;
        img.color[i] = viridis(t);
    }
}

}  // namespace facet::reference::detail
