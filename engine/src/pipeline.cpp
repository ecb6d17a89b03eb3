// The fast path's draw loop: vertex transform, clipping, coverage and shading. Shader and
// interpolation are template parameters resolved once per draw (dispatchVariant), so the
// per-pixel code has no branches on settings, no virtual calls and no allocation.

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "clip.hpp"
#include "facet/camera.hpp"
#include "facet/colormap.hpp"
#include "facet/lighting.hpp"
#include "facet/normals.hpp"
#include "facet/render.hpp"
#include "line_raster.hpp"
#include "triangle_raster.hpp"

namespace facet {

using namespace detail;

double resolveNearPlane(const RenderSettings& settings, const Mesh& mesh) {
    if (settings.nearPlane > 0.0) return settings.nearPlane;
    const double diagonal = computeBounds(mesh).diagonal();
    return diagonal > 0.0 ? 1e-3 * diagonal : 1e-3;
}

namespace {

/// Pixels beyond each image border inside which triangles are rasterized without 2D clipping.
/// Keeps snapped coordinates below 2^24 grid units, so edge products stay far below 2^63.
constexpr double kGuardBand = 32768.0;

/// Screen coordinates beyond this are not drawn as lines (their integer maths would overflow).
constexpr double kLineLimit = 1099511627776.0;  // 2^40

/// Rounds a colour to 8 bits per channel as the conventions say; NaN becomes 0.
inline std::uint32_t toByte(float c) {
    const float v = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
    return static_cast<std::uint32_t>(v * 255.0f + 0.5f);
}
inline std::uint32_t packColor(const glm::vec3& c) {
    return packRgba(toByte(c.r), toByte(c.g), toByte(c.b));
}

/// A vertex's clip position and colour (white when the draw has no colours).
inline ClipVertex fetchVertex(const DrawInput& in, std::size_t i) {
    return {in.clip[i], in.colors.empty() ? glm::vec3(1.0f) : in.colors[i]};
}

/// Twice the signed area of a screen triangle; positive means back-facing (y-down pixels).
inline double signedArea2(const glm::dvec2 (&s)[3]) {
    return (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[1].y - s[0].y) * (s[2].x - s[0].x);
}

/// Linear functions of the pixel position for one triangle, relative to a base pixel so that
/// float keeps its precision far from the origin: value = v[0] + v[1]·dx + v[2]·dy.
struct Planes {
    int baseX = 0, baseY = 0;
    float l1[3], l2[3];        // screen-linear barycentrics of vertices 1 and 2
    float u1[3], u2[3], q[3];  // λ1/w1, λ2/w2 and Σλi/wi, for perspective and depth
    glm::vec3 c0, d1, d2;      // colour at vertex 0 and differences to vertices 1 and 2

    float eval(const float (&p)[3], float dx, float dy) const {
        return p[0] + p[1] * dx + p[2] * dy;
    }
};

/// Builds the planes from unsnapped screen positions (double) so that interpolation does not
/// inherit the snapping error; returns false for a degenerate triangle.
bool makePlanes(const glm::dvec2 (&s)[3], const ClipVertex (&v)[3], int baseX, int baseY,
                Planes& p) {
    const double area = signedArea2(s);
    if (!(area != 0.0) || !std::isfinite(area)) return false;
    const double bx = baseX + 0.5, by = baseY + 0.5;
    const double l1 =
        ((s[0].x - s[2].x) * (by - s[2].y) - (s[0].y - s[2].y) * (bx - s[2].x)) / area;
    const double l2 =
        ((s[1].x - s[0].x) * (by - s[0].y) - (s[1].y - s[0].y) * (bx - s[0].x)) / area;
    const double l1x = -(s[0].y - s[2].y) / area, l1y = (s[0].x - s[2].x) / area;
    const double l2x = -(s[1].y - s[0].y) / area, l2y = (s[1].x - s[0].x) / area;
    const double r0 = 1.0 / v[0].pos.w, r1 = 1.0 / v[1].pos.w, r2 = 1.0 / v[2].pos.w;
    auto set = [](float(&dst)[3], double c, double a, double b) {
        dst[0] = static_cast<float>(c);
        dst[1] = static_cast<float>(a);
        dst[2] = static_cast<float>(b);
    };
    p.baseX = baseX;
    p.baseY = baseY;
    set(p.l1, l1, l1x, l1y);
    set(p.l2, l2, l2x, l2y);
    set(p.u1, l1 * r1, l1x * r1, l1y * r1);
    set(p.u2, l2 * r2, l2x * r2, l2y * r2);
    set(p.q, r0 + l1 * (r1 - r0) + l2 * (r2 - r0), l1x * (r1 - r0) + l2x * (r2 - r0),
        l1y * (r1 - r0) + l2y * (r2 - r0));
    p.c0 = v[0].color;
    p.d1 = v[1].color - v[0].color;
    p.d2 = v[2].color - v[0].color;
    return true;
}

/// Writes one fragment through the shader S: Simple overwrites, Painter and Depth test LESS.
template <ShaderKind S>
inline void writeFragment(Framebuffer& fb, int x, int y, float depth, const glm::vec3& color) {
    const std::size_t i = fb.index(x, y);
    if constexpr (S != ShaderKind::Simple) {
        if (!(depth < fb.depth[i])) return;
        fb.depth[i] = depth;
    }
    if constexpr (S != ShaderKind::Depth) fb.color[i] = packColor(color);
}

/// Per-pixel work of a triangle for one pipeline variant.
template <ShaderKind S, Interp I>
struct TriangleShader {
    Framebuffer& fb;
    std::size_t& fragments;
    const Planes* p = nullptr;

    void operator()(int x, int y) const {
        ++fragments;
        const auto dx = static_cast<float>(x - p->baseX);
        const auto dy = static_cast<float>(y - p->baseY);
        const float q = p->eval(p->q, dx, dy);
        const float depth = 1.0f / q;
        float m1, m2;
        if constexpr (I == Interp::Perspective) {
            m1 = p->eval(p->u1, dx, dy) * depth;
            m2 = p->eval(p->u2, dx, dy) * depth;
        } else {
            m1 = p->eval(p->l1, dx, dy);
            m2 = p->eval(p->l2, dx, dy);
        }
        writeFragment<S>(fb, x, y, depth, p->c0 + m1 * p->d1 + m2 * p->d2);
    }
};

/// Counts coverage instead of shading (fill-rule tests and overdraw views).
struct CoverageCounter {
    std::uint16_t* counts;
    int width;
    const Planes* p = nullptr;
    void operator()(int x, int y) const {
        std::uint16_t& c = counts[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                  static_cast<std::size_t>(x)];
        if (c != std::numeric_limits<std::uint16_t>::max()) ++c;
    }
};

/// The triangle front end shared by every variant: fetch, reject, clip, snap, cull, then hand
/// covered pixels to `sink` (which sees the current triangle's planes through sink.p).
template <class Sink>
void drawTriangles(const DrawInput& in, bool cull, int width, int height, Sink& sink,
                   RenderStats& stats) {
    const PixelRect screen{0, 0, width - 1, height - 1};
    const glm::dvec2 guardLo(-kGuardBand, -kGuardBand);
    const glm::dvec2 guardHi(width + kGuardBand, height + kGuardBand);
    const float W = static_cast<float>(width), H = static_cast<float>(height);
    const std::size_t nv = in.clip.size();
    Planes planes;
    sink.p = &planes;

    for (std::size_t t = 0; t + 2 < in.indices.size(); t += 3) {
        const std::uint32_t idx[3] = {in.indices[t], in.indices[t + 1], in.indices[t + 2]};
        if (idx[0] >= nv || idx[1] >= nv || idx[2] >= nv) continue;
        ++stats.trianglesIn;
        ClipVertex v[3];
        bool finite = true, allFront = true, anyFront = false;
        for (int k = 0; k < 3; ++k) {
            v[k] = fetchVertex(in, idx[k]);
            const glm::vec4& p = v[k].pos;
            finite = finite && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.w);
            allFront = allFront && p.w >= in.nearPlane;
            anyFront = anyFront || p.w >= in.nearPlane;
        }
        if (!finite || !anyFront) continue;
        if (allFront) {  // whole triangle off one side of the image: nothing to do
            auto all = [&](auto pred) {
                return pred(v[0].pos) && pred(v[1].pos) && pred(v[2].pos);
            };
            if (all([](const glm::vec4& p) { return p.x < 0.0f; }) ||
                all([&](const glm::vec4& p) { return p.x > W * p.w; }) ||
                all([](const glm::vec4& p) { return p.y < 0.0f; }) ||
                all([&](const glm::vec4& p) { return p.y > H * p.w; }))
                continue;
        }
        const NearPolygon poly =
            allFront ? NearPolygon{{v[0], v[1], v[2]}, 3} : clipNear(v, in.nearPlane);
        bool clipped = !allFront, culled = false, drawn = false;

        for (std::size_t k = 1; k + 1 < poly.size; ++k) {
            const ClipVertex tri[3] = {poly.v[0], poly.v[k], poly.v[k + 1]};
            glm::dvec2 s[3];
            bool inGuard = true;
            for (int j = 0; j < 3; ++j) {
                s[j] = glm::dvec2(tri[j].pos.x, tri[j].pos.y) / static_cast<double>(tri[j].pos.w);
                inGuard = inGuard && s[j].x >= guardLo.x && s[j].x <= guardHi.x &&
                          s[j].y >= guardLo.y && s[j].y <= guardHi.y;
            }
            const double minX = std::min({s[0].x, s[1].x, s[2].x});
            const double minY = std::min({s[0].y, s[1].y, s[2].y});
            const int baseX = static_cast<int>(std::clamp(std::floor(minX), 0.0, W - 1.0));
            const int baseY = static_cast<int>(std::clamp(std::floor(minY), 0.0, H - 1.0));
            if (!makePlanes(s, tri, baseX, baseY, planes)) continue;

            if (inGuard) {
                const std::int64_t xs[3] = {snap(s[0].x), snap(s[1].x), snap(s[2].x)};
                const std::int64_t ys[3] = {snap(s[0].y), snap(s[1].y), snap(s[2].y)};
                CoverageSetup setup;
                const Facing facing = setupCoverage(xs, ys, screen, setup);
                if (facing == Facing::Degenerate) continue;
                if (cull && facing == Facing::Back) {
                    culled = true;
                    continue;
                }
                drawn = true;
                if (!setup.box.empty()) forEachCovered(setup, sink);
                continue;
            }
            // Beyond the guard band: clip the screen triangle to it for coverage only; the
            // planes above still describe the whole triangle, so interpolation is unchanged.
            clipped = true;
            if (cull && signedArea2(s) > 0.0) {
                culled = true;
                continue;
            }
            const ScreenPolygon cover = clipToRect(s, guardLo, guardHi);
            for (std::size_t j = 1; j + 1 < cover.size; ++j) {
                const std::int64_t xs[3] = {snap(cover.v[0].x), snap(cover.v[j].x),
                                            snap(cover.v[j + 1].x)};
                const std::int64_t ys[3] = {snap(cover.v[0].y), snap(cover.v[j].y),
                                            snap(cover.v[j + 1].y)};
                CoverageSetup setup;
                if (setupCoverage(xs, ys, screen, setup) == Facing::Degenerate) continue;
                drawn = true;
                if (!setup.box.empty()) forEachCovered(setup, sink);
            }
        }
        stats.trianglesClipped += clipped ? 1 : 0;
        stats.trianglesCulled += (culled && !drawn) ? 1 : 0;
        stats.trianglesRasterized += drawn ? 1 : 0;
    }
}

/// Wireframe: each unique edge once, near-clipped, Bresenham with interpolated attributes.
template <ShaderKind S, Interp I>
void drawLines(const DrawInput& in, std::span<const std::uint32_t> edges, Framebuffer& fb,
               RenderStats& stats) {
    for (std::size_t e = 0; e + 1 < edges.size(); e += 2) {
        if (edges[e] >= in.clip.size() || edges[e + 1] >= in.clip.size()) continue;
        ClipVertex a = fetchVertex(in, edges[e]);
        ClipVertex b = fetchVertex(in, edges[e + 1]);
        if (!clipSegmentNear(a, b, in.nearPlane)) continue;
        const double ax = static_cast<double>(a.pos.x) / a.pos.w,
                     ay = static_cast<double>(a.pos.y) / a.pos.w;
        const double bx = static_cast<double>(b.pos.x) / b.pos.w,
                     by = static_cast<double>(b.pos.y) / b.pos.w;
        if (!(std::abs(ax) < kLineLimit && std::abs(ay) < kLineLimit && std::abs(bx) < kLineLimit &&
              std::abs(by) < kLineLimit))
            continue;
        ++stats.linesDrawn;
        const float ra = 1.0f / a.pos.w, rb = 1.0f / b.pos.w;
        forEachLinePixel(
            static_cast<std::int64_t>(std::floor(ax)), static_cast<std::int64_t>(std::floor(ay)),
            static_cast<std::int64_t>(std::floor(bx)), static_cast<std::int64_t>(std::floor(by)),
            fb.width, fb.height, [&](int x, int y, std::int64_t k, std::int64_t n) {
                ++stats.fragments;
                const float t = n > 0 ? static_cast<float>(k) / static_cast<float>(n) : 0.0f;
                const float wa = (1.0f - t) * ra, wb = t * rb;
                const float depth = 1.0f / (wa + wb);
                glm::vec3 c;
                if constexpr (I == Interp::Perspective)
                    c = (wa * a.color + wb * b.color) * depth;
                else
                    c = a.color + t * (b.color - a.color);
                writeFragment<S>(fb, x, y, depth, c);
            });
    }
}

/// Vertices: a pointSize square around the pixel holding each vertex in front of the near plane.
template <ShaderKind S>
void drawPoints(const DrawInput& in, int pointSize, Framebuffer& fb, RenderStats& stats) {
    const int lo = -(pointSize - 1) / 2, hi = lo + pointSize - 1;
    for (std::size_t i = 0; i < in.clip.size(); ++i) {
        const glm::vec4& p = in.clip[i];
        if (!(p.w >= in.nearPlane) || !std::isfinite(p.x) || !std::isfinite(p.y)) continue;
        const double x = std::floor(static_cast<double>(p.x) / p.w),
                     y = std::floor(static_cast<double>(p.y) / p.w);
        if (x + hi < 0 || y + hi < 0 || x + lo >= fb.width || y + lo >= fb.height) continue;
        ++stats.pointsDrawn;
        const glm::vec3 color = fetchVertex(in, i).color;
        const int px = static_cast<int>(x), py = static_cast<int>(y);
        for (int yy = std::max(0, py + lo); yy <= std::min(fb.height - 1, py + hi); ++yy)
            for (int xx = std::max(0, px + lo); xx <= std::min(fb.width - 1, px + hi); ++xx) {
                ++stats.fragments;
                writeFragment<S>(fb, xx, yy, p.w, color);
            }
    }
}

/// The depth shader's second pass: visible depth range mapped through viridis.
void resolveDepthColors(Framebuffer& fb, RenderStats& stats) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float d : fb.depth)
        if (d != kEmptyDepth) {
            lo = std::min(lo, d);
            hi = std::max(hi, d);
        }
    if (lo > hi) return;
    stats.depthNear = lo;
    stats.depthFar = hi;
    const double range = hi > lo ? static_cast<double>(hi) - lo : 1.0;
    for (std::size_t i = 0; i < fb.depth.size(); ++i)
        if (fb.depth[i] != kEmptyDepth)
            fb.color[i] =
                packColor(glm::vec3(viridis((fb.depth[i] - static_cast<double>(lo)) / range)));
}

/// Calls fn with the shader and interpolation as compile-time constants.
template <class Fn>
void dispatchVariant(ShaderKind shader, Interp interp, Fn&& fn) {
    auto withInterp = [&](auto s) {
        if (interp == Interp::Perspective)
            fn(s, std::integral_constant<Interp, Interp::Perspective>{});
        else
            fn(s, std::integral_constant<Interp, Interp::Affine>{});
    };
    switch (shader) {
        case ShaderKind::Simple:
            withInterp(std::integral_constant<ShaderKind, ShaderKind::Simple>{});
            break;
        case ShaderKind::Painter:
        case ShaderKind::Texture:
            withInterp(std::integral_constant<ShaderKind, ShaderKind::Painter>{});
            break;
        case ShaderKind::Depth:
            withInterp(std::integral_constant<ShaderKind, ShaderKind::Depth>{});
            break;
    }
}

}  // namespace

RenderStats Renderer::draw(const DrawInput& input, const RenderSettings& settings,
                           Framebuffer& frame) {
    RenderStats stats;
    if (frame.width <= 0 || frame.height <= 0) return stats;
    dispatchVariant(settings.shader, settings.interp, [&](auto shader, auto interp) {
        constexpr ShaderKind S = decltype(shader)::value;
        constexpr Interp I = decltype(interp)::value;
        switch (settings.mode) {
            case DrawMode::Solid: {
                TriangleShader<S, I> sink{frame, stats.fragments};
                drawTriangles(input, settings.cullBackFaces, frame.width, frame.height, sink,
                              stats);
                break;
            }
            case DrawMode::Wireframe:
                uniqueEdges(input.indices, edges_);
                drawLines<S, I>(input, edges_, frame, stats);
                break;
            case DrawMode::Vertices:
                drawPoints<S>(input, settings.pointSize, frame, stats);
                break;
        }
    });
    if (settings.shader == ShaderKind::Depth) resolveDepthColors(frame, stats);
    return stats;
}

void Renderer::countCoverage(const DrawInput& input, const RenderSettings& settings, int width,
                             int height, std::vector<std::uint16_t>& counts) {
    counts.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
    if (width <= 0 || height <= 0) return;
    RenderStats stats;
    CoverageCounter sink{counts.data(), width};
    drawTriangles(input, settings.cullBackFaces, width, height, sink, stats);
}

RenderStats Renderer::render(const Scene& scene, const RenderSettings& settings,
                             Framebuffer& frame) {
    const Camera& cam = scene.camera;
    frame.resize(cam.width, cam.height);
    frame.clear(rgbaFromHex(settings.background));
    // The transform is built in double and applied in float: one matrix, no per-vertex doubles.
    const glm::mat4 clipFromWorldF(clipFromWorld(cam));
    const auto& positions = scene.mesh.positions;
    clip_.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i)
        clip_[i] = clipFromWorldF * glm::vec4(positions[i], 1.0f);
    std::span<const glm::vec3> colors = scene.mesh.colors;
    if (settings.lighting == Lighting::Gouraud) {
        // Gouraud: the formula once per vertex in world space; the rasterizer then
        // interpolates the lit colour like any other vertex colour.
        const std::vector<glm::vec3> normals = computeVertexNormals(scene.mesh);
        const FastLighting lighting = prepareLighting(lightingParams(scene));
        const glm::vec3 eye(cam.eye);
        litColors_.resize(positions.size());
        for (std::size_t i = 0; i < positions.size(); ++i) {
            const glm::vec3 rgb = scene.mesh.hasColors() ? scene.mesh.colors[i] : glm::vec3(1.0f);
            litColors_[i] = shade(rgb, lightIntensity(positions[i], normals[i], eye, lighting));
        }
        colors = litColors_;
    }
    DrawInput input{.clip = clip_,
                    .colors = colors,
                    .indices = scene.mesh.indices,
                    .nearPlane = static_cast<float>(resolveNearPlane(settings, scene.mesh))};
    return draw(input, settings, frame);
}

}  // namespace facet
