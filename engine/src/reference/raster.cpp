// The reference path: the executable specification of a correct image (spec §4 to §8).
//
// Everything is double precision and written the obvious way: per triangle, every pixel of its
// bounding box is tested; per line, every pixel is computed from a closed formula. It is slow on
// purpose and must stay readable: the fast path (engine/src/pipeline and the stages it calls)
// implements exactly the rules below with fixed point, tiles and templates, and is tested
// against this folder.
//
// This folder: raster.cpp (these rules, clipping, triangle coverage and draw()), lines_points.cpp
// (rules 6, 7), projection.cpp (rule 1), render.cpp (the vertex streams of a scene, rules 3, 10,
// 14), shading.cpp (weights, lighting, texturing and the depth rule per fragment), samplers.cpp
// and lighting.cpp (spec §7 and §6 in double).
//
// THE RULES (numbered as in the tests and the fast path)
//  1. Projection (spec §4): camera frame z = normalize(look - eye), x = normalize(up × z),
//     y = z × x; p_c = R (p - eye) with R's rows x, y, z. Clip space is homogeneous pixel space:
//     (f·X + w/2·Z, f·Y + h/2·Z, Z, Z), so pixel = clip.xy / clip.w and clip.w is the depth Z.
//  2. The image starts as the background (0xRRGGBB, byte/255 per channel), depth +inf.
//  3. Vertex colours are the mesh colours, or white when there are none; for Gouraud lighting
//     they are replaced by the lit colours shade(rgb, I(p_i, n_i)) (spec §6).
//  4. Solid: triangles in index order (one with a NaN or infinite x, y or w has no position and
//     draws nothing, as in the fast path), clipped against w >= near (Sutherland–Hodgman, new
//     vertices computed from the inside vertex), fanned (v0, vk, vk+1), then rasterized with the
//     top-left rule at pixel centres; depth is always 1/q, perspective-correct (q = Σ λ_i/w_i),
//     the varyings use the weights of rule 11.
//     Multisampling (settings.msaa 2, 4 or 8, Solid only): coverage (top-left rule) and depth
//     (1/q, the LESS test) at each standard sample position (facet/multisample.hpp) instead of
//     the centre, into an image of samples (SampleBlock layout); the fragment of a pixel is
//     shaded once, at the pixel centre when the centre is inside by the same rule, else at the
//     centroid (mean) of its covered samples, with the weights of rule 11 there (Subdivided:
//     Perspective at a centroid), and that colour goes to every covered sample passing its
//     depth test. The Depth shader maps the samples' depths (rule 5); then each pixel is the
//     box-filter resolve of its samples in 8 bits: per channel the rounded mean of the samples'
//     rule-9 bytes, depth the nearest. The normals display (rule 14) is drawn on the resolved
//     image, one sample per pixel. Rule 8(a) applies per sample, and to the centre's inside
//     test: one ambiguous point flags all the pixel's samples, since it may move the
//     shading point; a resolved pixel is ambiguous when any of its samples is.
//  5. Shaders: Simple writes colour only (last wins); Painter tests LESS and writes colour and
//     depth; Depth is Painter, then maps every drawn pixel's depth to viridis over [dmin, dmax];
//     Texture is Painter with the colour of rule 13.
//  6. Wireframe: sorted unique edges, clipped against w >= near, Bresenham as a closed formula,
//     endpoints included, attributes interpolated by the major-axis step: t = k/n, weights of
//     rule 11; depth perspective-correct along the segment.
//  7. Vertices: squares of pointSize pixels around floor(pixel position) of each vertex in front
//     of the near plane, every pixel with the vertex's own depth and varyings.
//  8. Ambiguity: pixels where a correct fast path (1/256 px snapping, float arithmetic) may
//     legitimately differ are flagged in Image::ambiguous: (a) pixel centres within 1/256 px of
//     a drawn triangle's edge and not clearly outside it; (b) depth tests between depths within
//     a relative 1e-5; (c) for a line endpoint or point within 1/256 px of a pixel border, every
//     pixel the line or square would cover with either rounding of that coordinate; (d) with
//     the Texture shader, the Nearest filter and a texture, a written fragment whose wrapped
//     texel coordinate u'·W or v'·H is within 1/256 texel of an integer (a texel border,
//     0 and W included). The Subdivided fallback of rule 11 is deterministic, not flagged.
//  9. toRgba: clamp, round to nearest, pack like facet::packRgba.
// 10. Varyings, per vertex: rgb (rule 3), uv (the mesh's, else (0, 0)), world normal n (from
//     computeVertexNormals, unit or zero), world position p. Near clipping interpolates all of
//     them with the position's t, from the inside vertex.
// 11. Interpolation weights, computed once per fragment and applied to every varying (never to
//     depth):
//     - triangles, Affine: the screen-space barycentrics λ at the pixel centre;
//     - triangles, Perspective: λ'_i = (λ_i / w_i) / q, q = Σ λ_j / w_j;
//     - triangles, Subdivided N (settings.subdivision clamped to 2…256): for pixel (x, y),
//       x0 = N·floor(x/N), x1 = x0 + N, t = (x − x0)/N; weights = (1−t)·λ'(x0+½, y+½) +
//       t·λ'(x1+½, y+½), both λ' from the triangle's plane equations even outside it. If q at
//       either of those centres is not a finite number > 0, the pixel's own λ' instead;
//     - lines at t = k/n: Affine (1−t, t); Perspective and Subdivided ((1−t)/w_a, t/w_b) / q
//       with q = (1−t)/w_a + t/w_b;
//     - points: the vertex's own values.
// 12. Colour before texturing, c: Lighting Off or Gouraud: the interpolated rgb. Phong: n' =
//     the interpolated n normalised (|n| = 0 stays 0, never NaN), I = lightIntensity(p, n',
//     eye, params) with the interpolated p, c = shade(rgb, I). Points use their vertex's own
//     p and n as they are (no renormalisation), so Phong equals Gouraud there exactly.
// 13. Texture shader: texel = the texture at the interpolated uv (a null texture is white):
//     Nearest: reference::sampleNearest; Bilinear: reference::sampleBilinear on level 0;
//     Trilinear: reference::sampleTrilinear at lod = reference::mipLevel(du/dx, dv/dx, du/dy,
//     dv/dy). Triangles use the exact screen-space derivatives at the pixel centre: Affine, the
//     constant gradient of the affine uv; Perspective and Subdivided, the derivative of the
//     perspective-correct uv, d(uv) = (d(Σ λ_i uv_i / w_i) − uv_p·dq) / q with uv_p the
//     perspective-correct uv at the centre. Lines and points use lod 0. The colour is the
//     texel, or texel × c (rule 12) with settings.combine.
// 14. Normals display (settings.showNormals), after the main pass and after the Depth shader's
//     mapping, in every draw mode: for each vertex with a non-zero normal, the segment p_i to
//     p_i + L·n_i (L = settings.normalLength if > 0, else normalDisplayLength(mesh); n_i and
//     that length are the float values widened, the sum is formed in double), both ends
//     projected by rule 1, drawn by rule 6 (with 8(b) and 8(c)) in pure red (1, 0, 0). Depth
//     rule: the Simple shader overwrites, every other shader tests LESS and writes depth.

#include "facet/reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "facet/framebuffer.hpp"
#include "facet/multisample.hpp"
#include "facet/texture.hpp"
#include "reference/geometry.hpp"
#include "reference/samplers.hpp"

namespace facet::reference {
namespace {

using detail::drawPoint;
using detail::drawSegment;
using detail::edgeFunction;
using detail::fragment;
using detail::inImage;
using detail::intersectNear;
using detail::kSnap;
using detail::mapDepthToColor;
using detail::Pass;
using detail::pixelIndex;
using detail::ScreenTriangle;
using detail::Tracker;
using detail::Vertex;

constexpr double kInf = std::numeric_limits<double>::infinity();

// A triangle clipped by one plane has at most four vertices.
struct Polygon {
    std::array<Vertex, 4> v;
    std::size_t count = 0;
};

// Entry i of a per-vertex stream, or the default when the stream is empty or too short.
template <typename T>
T streamAt(std::span<const T> stream, std::size_t i, const T& fallback) {
    return i < stream.size() ? stream[i] : fallback;
}

// Sutherland–Hodgman against w >= near, walking edges v0→v1, v1→v2, v2→v0: an inside start
// vertex is kept, a crossing edge adds its intersection. The fan that follows starts at the
// first output vertex, so this order decides how a clipped quad is split (it matters for affine
// colours) and the fast path must walk the edges the same way.
Polygon clipNear(const std::array<Vertex, 3>& tri, double nearPlane) {
    Polygon poly;
    for (std::size_t i = 0; i < 3; ++i) {
        const Vertex& a = tri[i];
        const Vertex& b = tri[(i + 1) % 3];
        const double da = a.clip.w - nearPlane;
        const double db = b.clip.w - nearPlane;
        const bool aIn = da >= 0.0;
        const bool bIn = db >= 0.0;
        if (aIn) poly.v[poly.count++] = a;
        if (aIn != bIn) {
            poly.v[poly.count++] = aIn ? intersectNear(a, da, b, db) : intersectNear(b, db, a, da);
        }
    }
    return poly;
}

// Top-left rule for A > 0 on a y-down screen: a top edge runs exactly horizontal towards +x, a
// left edge goes up (towards -y). Pixel centres exactly on such an edge belong to the triangle,
// so two triangles sharing an edge cover each centre on it exactly once.
bool isTopLeft(const glm::dvec2& a, const glm::dvec2& b) {
    const double dy = b.y - a.y;
    const double dx = b.x - a.x;
    return dy < 0.0 || (dy == 0.0 && dx > 0.0);
}

// x, y and w finite (z is never read: depth is w): w = +inf would otherwise project to pixel
// (0, 0) and draw.
bool finiteClip(const glm::dvec4& c) {
    return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.w);
}

// Pixels whose centres lie in [lo, hi] along one axis, clamped to [0, size-1]; first > last when
// empty. Computed in double so absurd coordinates (or NaN) never overflow an int.
std::pair<int, int> pixelSpan(double lo, double hi, int size) {
    const double first = std::max(std::ceil(lo - 0.5), 0.0);
    const double last = std::min(std::floor(hi - 0.5), static_cast<double>(size - 1));
    if (!(first <= last)) return {0, -1};
    return {static_cast<int>(first), static_cast<int>(last)};
}

// Where one pixel's samples are: one at the centre, or multisampling's standard positions,
// stored in the image of samples as a block (facet/multisample.hpp).
struct SampleGrid {
    int count = 1;
    SampleBlock block;
    std::array<glm::dvec2, 8> offset{};  ///< from the pixel centre, in px

    static SampleGrid of(int samples) {
        SampleGrid g;
        g.count = msaaSamples(samples);
        g.block = sampleBlock(g.count);
        const std::span<const SampleOffset> pos = samplePositions(g.count);
        for (std::size_t k = 0; k < pos.size(); ++k)
            g.offset[k] = {pos[k].x / 16.0, pos[k].y / 16.0};
        return g;
    }
    // How far a sample may lie from its pixel's centre.
    double reach() const { return count > 1 ? 0.5 : 0.0; }
    // Sample k of pixel (x, y) in the image of samples.
    std::int64_t sx(int x, int k) const { return std::int64_t{x} * block.x + k % block.x; }
    std::int64_t sy(int y, int k) const { return std::int64_t{y} * block.y + k / block.x; }
};

// Rule 8(a): the snapped edges of the fast path lie within 1/256 px of ours, so sample points
// that close to an edge (and not clearly outside) may be covered by this triangle or its
// neighbour. With several samples the shading point (centre or centroid) hangs on the centre's
// and every sample's inside test, so one ambiguous point flags all the pixel's samples.
void markEdgeAmbiguity(Image& img, const std::array<glm::dvec2, 3>& s, const SampleGrid& grid,
                       int width, int height) {
    std::array<double, 3> len{};
    for (std::size_t k = 0; k < 3; ++k) len[k] = glm::length(s[(k + 1) % 3] - s[k]);
    const double r = 1.0 + grid.reach();
    const auto [x0, x1] = pixelSpan(std::min({s[0].x, s[1].x, s[2].x}) - r,
                                    std::max({s[0].x, s[1].x, s[2].x}) + r, width);
    const auto [y0, y1] = pixelSpan(std::min({s[0].y, s[1].y, s[2].y}) - r,
                                    std::max({s[0].y, s[1].y, s[2].y}) + r, height);
    auto ambiguousAt = [&](const glm::dvec2& p) {
        double nearest = kInf;
        bool inGrown = true;
        for (std::size_t k = 0; k < 3; ++k) {
            const double dist = edgeFunction(s[k], s[(k + 1) % 3], p) / len[k];
            inGrown = inGrown && dist >= -kSnap;
            nearest = std::min(nearest, std::abs(dist));
        }
        return inGrown && nearest <= kSnap;
    };
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::dvec2 c{x + 0.5, y + 0.5};
            if (grid.count == 1) {
                if (ambiguousAt(c)) img.ambiguous[pixelIndex(img, x, y)] = 1;
                continue;
            }
            // The shading point depends on the centre's and every sample's inside test, so
            // one ambiguous decision may change the colour of all the pixel's samples.
            bool any = ambiguousAt(c);
            for (int k = 0; k < grid.count && !any; ++k)
                any = ambiguousAt(c + grid.offset[static_cast<std::size_t>(k)]);
            if (!any) continue;
            for (int k = 0; k < grid.count; ++k)
                img.ambiguous[pixelIndex(img, grid.sx(x, k), grid.sy(y, k))] = 1;
        }
    }
}

// Rule 11 at a point off the pixel grid (a multisampled pixel's centroid): Affine the
// barycentrics there, Perspective and Subdivided the perspective-correct weights.
std::array<double, 3> weightsAt(const ScreenTriangle& tri, Interp interp, const glm::dvec2& p) {
    return interp == Interp::Affine ? tri.barycentric(p) : tri.perspective(p);
}

// Rule 4 for one fan triangle in clip space into `img`, an image of the grid's samples of a
// width × height frame; each finished row counts towards the progress.
void rasterizeTriangle(Image& img, const Pass& pass, std::array<Vertex, 3> v,
                       const SampleGrid& grid, int width, int height, Tracker& progress) {
    const RenderSettings& settings = pass.settings;
    std::array<glm::dvec2, 3> s{};
    for (std::size_t i = 0; i < 3; ++i) s[i] = glm::dvec2(v[i].clip) / v[i].clip.w;
    double area = edgeFunction(s[0], s[1], s[2]);
    if (area == 0.0 || !std::isfinite(area)) return;
    // Mesh triangles are counter-clockwise seen from outside; on a y-down screen that is A < 0.
    if (settings.cullBackFaces && area > 0.0) return;
    if (area < 0.0) {
        std::swap(v[1], v[2]);
        std::swap(s[1], s[2]);
        area = -area;
    }
    markEdgeAmbiguity(img, s, grid, width, height);
    const ScreenTriangle tri{s, {v[0].clip.w, v[1].clip.w, v[2].clip.w}, area};
    const bool withLod = detail::needsLod(settings, pass.input);

    const std::array<bool, 3> topLeft{isTopLeft(s[1], s[2]), isTopLeft(s[2], s[0]),
                                      isTopLeft(s[0], s[1])};
    auto inside = [&](const glm::dvec2& p) {
        // e[i] is the edge opposite vertex i, so e[i] / area is vertex i's barycentric.
        const std::array<double, 3> e{edgeFunction(s[1], s[2], p), edgeFunction(s[2], s[0], p),
                                      edgeFunction(s[0], s[1], p)};
        bool covered = true;
        for (std::size_t k = 0; k < 3; ++k) {
            covered = covered && (e[k] > 0.0 || (e[k] == 0.0 && topLeft[k]));
        }
        return covered;
    };
    const double r = grid.reach();
    const auto [x0, x1] = pixelSpan(std::min({s[0].x, s[1].x, s[2].x}) - r,
                                    std::max({s[0].x, s[1].x, s[2].x}) + r, width);
    const auto [y0, y1] = pixelSpan(std::min({s[0].y, s[1].y, s[2].y}) - r,
                                    std::max({s[0].y, s[1].y, s[2].y}) + r, height);
    for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
            const glm::dvec2 c{x + 0.5, y + 0.5};
            unsigned covered = 0;
            glm::dvec2 sum{0.0};
            int n = 0;
            for (int k = 0; k < grid.count; ++k) {
                if (!inside(c + grid.offset[static_cast<std::size_t>(k)])) continue;
                covered |= 1u << k;
                sum += grid.offset[static_cast<std::size_t>(k)];
                ++n;
            }
            if (covered == 0) continue;

            // One shading per pixel: at the centre, or the covered samples' centroid.
            const bool atCentre = grid.count == 1 || inside(c);
            const glm::dvec2 p = atCentre ? c : c + sum / static_cast<double>(n);
            const std::array<double, 3> weights = atCentre
                                                      ? detail::triangleWeights(tri, settings, x, y)
                                                      : weightsAt(tri, settings.interp, p);
            double lod = 0.0;
            if (withLod) {
                const auto [dx, dy] = detail::uvDerivatives(tri, v, settings.interp, p);
                lod = reference::mipLevel(*pass.input.texture, dx, dy);
            }
            for (int k = 0; k < grid.count; ++k) {
                if (!(covered & (1u << k))) continue;
                // Depth is always perspective-correct, at the sample.
                const double depth =
                    1.0 / tri.inverseW(c + grid.offset[static_cast<std::size_t>(k)]);
                fragment(img, pass, grid.sx(x, k), grid.sy(y, k), depth, v, weights, lod);
            }
        }
        if (!progress.add(x1 - x0 + 1)) return;
    }
}

// The pixel work of one triangle for the progress: its bounding box in the image (plus one, for
// the set-up of triangles off screen), the whole image when the near plane clips it.
double triangleWork(int width, int height, const std::array<glm::dvec4, 3>& clip,
                    double nearPlane) {
    std::array<glm::dvec2, 3> s{};
    for (std::size_t i = 0; i < 3; ++i) {
        if (!(clip[i].w >= nearPlane)) return static_cast<double>(width) * height + 1.0;
        s[i] = glm::dvec2(clip[i]) / clip[i].w;
    }
    const auto [x0, x1] =
        pixelSpan(std::min({s[0].x, s[1].x, s[2].x}), std::max({s[0].x, s[1].x, s[2].x}), width);
    const auto [y0, y1] =
        pixelSpan(std::min({s[0].y, s[1].y, s[2].y}), std::max({s[0].y, s[1].y, s[2].y}), height);
    if (x0 > x1 || y0 > y1) return 1.0;
    return static_cast<double>(x1 - x0 + 1) * (y1 - y0 + 1) + 1.0;
}

// Rule 2: the background and empty depth, at `width` × `height` (an image of samples too).
Image blankImage(const RenderSettings& settings, int width, int height) {
    Image img;
    img.width = std::max(width, 0);
    img.height = std::max(height, 0);
    const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
    const glm::dvec3 background{((settings.background >> 16) & 0xFF) / 255.0,
                                ((settings.background >> 8) & 0xFF) / 255.0,
                                (settings.background & 0xFF) / 255.0};
    img.color.assign(pixels, background);
    img.depth.assign(pixels, kInf);
    img.ambiguous.assign(pixels, 0);
    return img;
}

// Rules 4, 6 and 7 into `img`: the frame of width × height itself, or with multisampling its
// image of samples; marks `img` cancelled when the progress stops it.
void drawPrimitives(Image& img, const Input& input, const RenderSettings& settings,
                    const SampleGrid& grid, int width, int height, const Progress& progress) {
    const std::size_t vertexCount = input.clip.size();
    auto vertex = [&](std::uint32_t i) {  // rule 10
        Vertex v;
        v.clip = input.clip[i];
        v.color = streamAt(input.colors, i, glm::dvec3(1.0));
        v.uv = streamAt(input.uvs, i, glm::dvec2(0.0));
        v.normal = streamAt(input.normals, i, glm::dvec3(0.0));
        v.world = streamAt(input.positions, i, glm::dvec3(0.0));
        return v;
    };
    // Indices past the vertex array are ignored rather than read out of bounds.
    auto valid = [&](std::uint32_t i) { return i < vertexCount; };

    const Pass pass{settings, input, false};
    // The progress counts triangles by their pixels, lines and points one each.
    double work = 0.0;
    if (progress) {
        if (settings.mode != DrawMode::Solid) work = static_cast<double>(input.indices.size());
        for (std::size_t t = 0; settings.mode == DrawMode::Solid && t + 2 < input.indices.size();
             t += 3) {
            const std::uint32_t i0 = input.indices[t];
            const std::uint32_t i1 = input.indices[t + 1];
            const std::uint32_t i2 = input.indices[t + 2];
            if (!valid(i0) || !valid(i1) || !valid(i2)) continue;
            work += triangleWork(width, height, {input.clip[i0], input.clip[i1], input.clip[i2]},
                                 input.nearPlane);
        }
    }
    Tracker tracker(progress, work);
    switch (settings.mode) {
        case DrawMode::Solid:
            for (std::size_t t = 0; t + 2 < input.indices.size() && !tracker.stopped(); t += 3) {
                const std::uint32_t i0 = input.indices[t];
                const std::uint32_t i1 = input.indices[t + 1];
                const std::uint32_t i2 = input.indices[t + 2];
                if (!valid(i0) || !valid(i1) || !valid(i2)) continue;
                if (!finiteClip(input.clip[i0]) || !finiteClip(input.clip[i1]) ||
                    !finiteClip(input.clip[i2])) {
                    tracker.add(1.0);
                    continue;
                }
                const Polygon poly =
                    clipNear({vertex(i0), vertex(i1), vertex(i2)}, input.nearPlane);
                for (std::size_t k = 1; k + 1 < poly.count; ++k) {
                    rasterizeTriangle(img, pass, {poly.v[0], poly.v[k], poly.v[k + 1]}, grid, width,
                                      height, tracker);
                }
                tracker.add(1.0);
            }
            break;
        case DrawMode::Wireframe: {
            // The same list as facet::uniqueEdges: each undirected edge once as (low, high),
            // sorted, so every edge is drawn once and in a fixed order.
            std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
            for (std::size_t t = 0; t + 2 < input.indices.size(); t += 3) {
                for (std::size_t k = 0; k < 3; ++k) {
                    const std::uint32_t a = input.indices[t + k];
                    const std::uint32_t b = input.indices[t + (k + 1) % 3];
                    if (a != b) edges.emplace_back(std::min(a, b), std::max(a, b));
                }
            }
            std::sort(edges.begin(), edges.end());
            edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
            for (const auto& [a, b] : edges) {
                if (!tracker.add(2.0)) break;  // each edge is in about two triangles
                if (!valid(a) || !valid(b)) continue;
                drawSegment(img, pass, vertex(a), vertex(b), input.nearPlane);
            }
            break;
        }
        case DrawMode::Vertices:
            for (std::uint32_t i = 0; i < vertexCount; ++i) {
                if (!tracker.add(static_cast<double>(input.indices.size()) /
                                 std::max<double>(1.0, static_cast<double>(vertexCount))))
                    break;
                drawPoint(img, pass, vertex(i), input.nearPlane);
            }
            break;
    }
    if (tracker.active()) tracker.finish();
    img.cancelled = tracker.stopped();
}

}  // namespace

Image resolveSamples(const Image& samples, int msaa) {
    const SampleBlock b = sampleBlock(msaa);
    Image img;
    img.width = samples.width / b.x;
    img.height = samples.height / b.y;
    img.cancelled = samples.cancelled;
    const std::size_t pixels = static_cast<std::size_t>(img.width) * img.height;
    img.color.assign(pixels, glm::dvec3(0.0));
    img.depth.assign(pixels, kInf);
    img.ambiguous.assign(pixels, 0);
    const std::vector<std::uint32_t> bytes = samples.toRgba();  // rule 9 per sample
    const double count = static_cast<double>(b.x * b.y);
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            glm::dvec3 sum{0.0};
            const std::size_t i = pixelIndex(img, x, y);
            for (int sy = 0; sy < b.y; ++sy) {
                for (int sx = 0; sx < b.x; ++sx) {
                    const std::size_t j =
                        pixelIndex(samples, std::int64_t{x} * b.x + sx, std::int64_t{y} * b.y + sy);
                    for (int c = 0; c < 3; ++c) sum[c] += (bytes[j] >> (8 * c)) & 0xFFu;
                    img.depth[i] = std::min(img.depth[i], samples.depth[j]);
                    if (samples.ambiguous[j] != 0) img.ambiguous[i] = 1;
                }
            }
            // The rounded mean of the bytes, as a value rule 9 turns back into that byte.
            for (int c = 0; c < 3; ++c) img.color[i][c] = std::floor(sum[c] / count + 0.5) / 255.0;
        }
    }
    return img;
}

Image drawSamples(const Input& input, const RenderSettings& settings, int width, int height,
                  const Progress& progress) {
    const SampleGrid grid = SampleGrid::of(settings.mode == DrawMode::Solid ? settings.msaa : 1);
    Image img =
        blankImage(settings, std::max(width, 0) * grid.block.x, std::max(height, 0) * grid.block.y);
    drawPrimitives(img, input, settings, grid, std::max(width, 0), std::max(height, 0), progress);
    if (!img.cancelled && settings.shader == ShaderKind::Depth) mapDepthToColor(img);
    return img;
}

Image draw(const Input& input, const RenderSettings& settings, int width, int height,
           const Progress& progress) {
    const int samples = settings.mode == DrawMode::Solid ? msaaSamples(settings.msaa) : 1;
    Image img = drawSamples(input, settings, width, height, progress);
    if (samples > 1) img = resolveSamples(img, samples);
    if (img.cancelled) return img;

    // Rule 14: the normals display, over the finished image.
    if (settings.showNormals) {
        const Pass normalsPass{settings, input, true};
        for (std::size_t i = 0; i + 1 < input.normalSegments.size(); i += 2) {
            Vertex a;
            Vertex b;
            a.clip = input.normalSegments[i];
            b.clip = input.normalSegments[i + 1];
            drawSegment(img, normalsPass, a, b, input.nearPlane);
        }
    }
    return img;
}

}  // namespace facet::reference