// The fast path's draw: pick the pipeline variant once per draw (dispatch below), then run the
// shared front end and the variant's pixel loops (primitives.hpp). The per-pixel code has no
// branch on the settings, no virtual call and no allocation.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <type_traits>

#include "facet/camera.hpp"
#include "facet/colormap.hpp"
#include "facet/legend.hpp"
#include "facet/lighting.hpp"
#include "facet/normals.hpp"
#include "facet/render.hpp"
#include "fingerprint.hpp"
#include "primitives.hpp"
#include "supersample.hpp"
#include "tile_renderer.hpp"

namespace facet {

using namespace detail;

Renderer::Renderer() : tiles_(std::make_unique<TileRenderer>()) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

double resolveNearPlane(const RenderSettings& settings, const Mesh& mesh) {
    if (settings.nearPlane > 0.0) return settings.nearPlane;
    const double diagonal = computeBounds(mesh).diagonal();
    return diagonal > 0.0 ? 1e-3 * diagonal : 1e-3;
}

namespace detail {

std::size_t countTriangle(void* context, const CoverageSetup& setup, const Planes&) {
    const CoverageCounts& c = *static_cast<const CoverageCounts*>(context);
    std::size_t covered = 0;
    forEachCovered(setup, [&](int x, int y) {
        ++covered;
        std::uint16_t& n =
            c.counts[static_cast<std::size_t>(y) * static_cast<std::size_t>(c.width) +
                     static_cast<std::size_t>(x)];
        if (n != std::numeric_limits<std::uint16_t>::max()) ++n;
    });
    return covered;
}

std::string_view VaryingLayout::names() const {
    // One literal per layout: the names live as long as the program.
    static constexpr std::string_view kNames[8] = {"1/w",        "1/w rgb",       "1/w uv",
                                                   "1/w rgb uv", "1/w n p",       "1/w rgb n p",
                                                   "1/w uv n p", "1/w rgb uv n p"};
    return kNames[(color ? 1 : 0) + (uv ? 2 : 0) + (phong ? 4 : 0)];
}

}  // namespace detail

namespace {

/// Below this many vertices the per-vertex loops stay on one thread: waking the others costs
/// more than the work.
constexpr std::ptrdiff_t kParallelVertices = 16384;
/// Pixels per thread below which whole-frame passes stay on one thread.
constexpr std::ptrdiff_t kParallelPixels = 1 << 16;

/// Fills colour and depth, split by rows over the threads (a 4K frame is 64 MB of stores).
void clearFrame(Framebuffer& fb, std::uint32_t rgba, int threads) {
    const auto n = static_cast<std::ptrdiff_t>(fb.color.size());
    const std::ptrdiff_t parts =
        std::max<std::ptrdiff_t>(1, std::min<std::ptrdiff_t>(threads, n / kParallelPixels));
#pragma omp parallel for num_threads(static_cast <int>(parts)) if (parts > 1)
    for (std::ptrdiff_t p = 0; p < parts; ++p) {
        const std::ptrdiff_t b = n * p / parts, e = n * (p + 1) / parts;
        std::fill(fb.color.begin() + b, fb.color.begin() + e, rgba);
        std::fill(fb.depth.begin() + b, fb.depth.begin() + e, kEmptyDepth);
    }
}

/// The depth shader's second pass: visible depth range mapped through viridis.
void resolveDepthColors(Framebuffer& fb, RenderStats& stats, int threads) {
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
    const auto n = static_cast<std::ptrdiff_t>(fb.depth.size());
#pragma omp parallel for num_threads(threads) if (n > kParallelPixels)
    for (std::ptrdiff_t i = 0; i < n; ++i)
        if (fb.depth[i] != kEmptyDepth)
            fb.color[i] =
                packColor(glm::vec3(viridis((fb.depth[i] - static_cast<double>(lo)) / range)));
}

/// The runtime description of a variant, reduced to what matters for the shader so that
/// settings that change nothing map to the same instantiation.
struct VariantKey {
    ShaderKind shader;
    Interp interp;
    VaryingLayout layout;
    TextureFilter filter;
    bool combine;
};

/// Whether vertex colour (and so lighting) shows: not in a depth image or a bare texel.
bool usesColor(const RenderSettings& s) {
    return s.shader != ShaderKind::Depth && (s.shader != ShaderKind::Texture || s.combine);
}

VariantKey variantKey(const RenderSettings& s, const DrawInput& in) {
    const bool texture = s.shader == ShaderKind::Texture;
    VariantKey k{
        s.shader, s.interp, {}, texture ? s.filter : TextureFilter::Nearest, texture && s.combine};
    k.layout.color = usesColor(s) && !in.colors.empty();
    k.layout.uv = texture;
    k.layout.phong = usesColor(s) && s.lighting == Lighting::Phong && !in.normals.empty();
    return k;
}

template <class E, E... Values, class Fn>
void withEnum(E value, Fn&& fn) {
    ((value == Values ? (fn(std::integral_constant<E, Values>{}), 0) : 0), ...);
}

template <class Fn>
void withBool(bool value, Fn&& fn) {
    if (value)
        fn(std::true_type{});
    else
        fn(std::false_type{});
}

/// Calls fn with the Variant type for `key`; only meaningful combinations are instantiated.
template <class Fn>
void dispatch(const VariantKey& key, Fn&& fn) {
    withEnum<Interp, Interp::Affine, Interp::Subdivided,
             Interp::Perspective>(key.interp, [&](auto interp) {
        constexpr Interp I = decltype(interp)::value;
        constexpr TextureFilter N = TextureFilter::Nearest;
        auto colored = [&](auto shader) {
            constexpr ShaderKind S = decltype(shader)::value;
            withBool(key.layout.color, [&](auto c) {
                withBool(key.layout.phong, [&](auto ph) {
                    fn(Variant<S, I, decltype(c)::value, false, decltype(ph)::value, N, false>{});
                });
            });
        };
        switch (key.shader) {
            case ShaderKind::Simple:
                colored(std::integral_constant<ShaderKind, ShaderKind::Simple>{});
                break;
            case ShaderKind::Painter:
                colored(std::integral_constant<ShaderKind, ShaderKind::Painter>{});
                break;
            case ShaderKind::Depth:
                fn(Variant<ShaderKind::Depth, I, false, false, false, N, false>{});
                break;
            case ShaderKind::Texture:
                withEnum<TextureFilter, TextureFilter::Nearest, TextureFilter::Bilinear,
                         TextureFilter::Trilinear>(key.filter, [&](auto filter) {
                    constexpr TextureFilter F = decltype(filter)::value;
                    constexpr ShaderKind T = ShaderKind::Texture;
                    if (!key.combine) {
                        fn(Variant<T, I, false, true, false, F, false>{});
                        return;
                    }
                    withBool(key.layout.color, [&](auto c) {
                        withBool(key.layout.phong, [&](auto ph) {
                            fn(Variant<T, I, decltype(c)::value, true, decltype(ph)::value, F,
                                       true>{});
                        });
                    });
                });
                break;
        }
    });
}

/// Bytes per vertex the draw reads or derives, for --stats.
std::size_t vertexBytes(const RenderSettings& s, const Mesh& mesh, const VariantKey& key) {
    std::size_t bytes = sizeof(glm::vec3) + sizeof(glm::vec4);  // position, clip position
    if (key.layout.color && mesh.hasColors()) bytes += sizeof(glm::vec3);
    if (key.layout.color && s.lighting == Lighting::Gouraud) bytes += 2 * sizeof(glm::vec3);
    if (key.layout.phong || s.showNormals) bytes += sizeof(glm::vec3);  // normals
    if (key.layout.uv && mesh.hasUvs()) bytes += sizeof(glm::vec2);
    return bytes;
}

using Clock = std::chrono::steady_clock;

/// A world point in clip space, computed in double and rounded once: the fast path's clip
/// coordinates are then the reference's, to float rounding. A float matrix product lost the
/// camera-space depth to cancellation when the eye was a near distance or two from a surface
/// far from the world origin (a surface crossed the near plane a pixel off), and its per-vertex
/// rounding bent tiny silhouette triangles by more than the 1/256 px the rules allow.
glm::vec4 clipPoint(const glm::dmat4& clipFromWorld, const glm::vec3& p) {
    return glm::vec4(clipFromWorld * glm::dvec4(glm::dvec3(p), 1.0));
}

double msSince(Clock::time_point& t) {
    const Clock::time_point now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - t).count();
    t = now;
    return ms;
}

const Texture& whiteTexture() {
    static const Texture white;
    return white;
}

}  // namespace

RenderStats Renderer::draw(const DrawInput& input, const RenderSettings& settings,
                           Framebuffer& frame) {
    RenderStats stats;
    if (frame.width <= 0 || frame.height <= 0) return stats;
    const VariantKey key = variantKey(settings, input);
    stats.varyings = 1 + key.layout.count();
    stats.varyingNames = key.layout.names();
    const DrawConstants constants{input.texture ? input.texture : &whiteTexture(), input.lighting,
                                  input.eye, glm::vec3(1.0f)};
    const int subdivision = std::clamp(settings.subdivision, kMinSubdivision, kMaxSubdivision);
    const int threads = resolveThreads(settings.threads);
    const int subPixelBits = std::clamp(settings.subPixelBits, kMinSubPixelBits, kMaxSubPixelBits);
    dispatch(key, [&](auto variant) {
        using V = decltype(variant);
        switch (settings.mode) {
            case DrawMode::Solid: {
                RasterContext ctx{&frame, &constants, subdivision};
                tiles_->draw(input, V::kLayout, settings.cullBackFaces, frame.width, frame.height,
                             &rasterizeTriangle<V>, &ctx, threads, subPixelBits, stats);
                break;
            }
            case DrawMode::Wireframe:
                updateEdges(input.indices);
                drawLines<V>(input, edges_, frame, constants, stats);
                break;
            case DrawMode::Vertices:
                drawPoints<V>(input, settings.pointSize, frame, constants, stats);
                break;
        }
    });
    if (settings.shader == ShaderKind::Depth) resolveDepthColors(frame, stats, threads);
    return stats;
}

void Renderer::updateEdges(std::span<const std::uint32_t> indices) {
    // The edge list is rebuilt (a sort) only when the indices change.
    const std::uint64_t h = fingerprint(indices);
    if (h == edgesFingerprint_ && !edges_.empty()) return;
    uniqueEdges(indices, edges_, edgeKeys_);
    edgesFingerprint_ = h;
}

void Renderer::countCoverage(const DrawInput& input, const RenderSettings& settings, int width,
                             int height, std::vector<std::uint16_t>& counts) {
    counts.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
    if (width <= 0 || height <= 0) return;
    RenderStats stats;
    CoverageCounts ctx{counts.data(), width};
    tiles_->draw(input, VaryingLayout{}, settings.cullBackFaces, width, height, &countTriangle,
                 &ctx, resolveThreads(settings.threads),
                 std::clamp(settings.subPixelBits, kMinSubPixelBits, kMaxSubPixelBits), stats);
}

RenderStats Renderer::render(const Scene& scene, const RenderSettings& settings,
                             Framebuffer& frame) {
    const int n = std::clamp(settings.supersample, 1, detail::kMaxSupersample);
    if (n == 1 || settings.mode != DrawMode::Solid)
        return renderView(scene, scene.camera, settings, frame);
    // The legend is drawn on the final frame, at its size, so it stays legible.
    RenderSettings big = settings;
    big.depthLegend = false;
    RenderStats stats =
        renderView(scene, detail::supersampledCamera(scene.camera, n), big, supersampled_);
    Clock::time_point t = Clock::now();
    detail::resolveSupersampled(supersampled_, n, frame, resolveThreads(settings.threads));
    if (settings.shader == ShaderKind::Depth && settings.depthLegend && stats.depthFar > 0.0f)
        drawDepthLegend(frame, stats.depthNear, stats.depthFar);
    stats.postMs += msSince(t);
    return stats;
}

RenderStats Renderer::renderView(const Scene& scene, const Camera& cam,
                                 const RenderSettings& settings, Framebuffer& frame) {
    Clock::time_point t = Clock::now();
    frame.resize(cam.width, cam.height);
    const int threads = resolveThreads(settings.threads);
    clearFrame(frame, rgbaFromHex(settings.background), threads);
    const double clearMs = msSince(t);
    const glm::dmat4 clipFromWorldD = clipFromWorld(cam);
    const Mesh& mesh = scene.mesh;
    const auto& positions = mesh.positions;
    clip_.resize(positions.size());
    const auto vertexCount = static_cast<std::ptrdiff_t>(positions.size());
#pragma omp parallel for num_threads(threads) if (vertexCount > kParallelVertices)
    for (std::ptrdiff_t i = 0; i < vertexCount; ++i)
        clip_[i] = clipPoint(clipFromWorldD, positions[i]);

    DrawInput input{.clip = clip_,
                    .colors = mesh.colors,
                    .indices = mesh.indices,
                    .nearPlane = static_cast<float>(resolveNearPlane(settings, mesh)),
                    .texture = scene.texture.get(),
                    .lighting = prepareLighting(lightingParams(scene)),
                    .eye = glm::vec3(cam.eye)};
    // Lighting only changes colour: a depth image or a bare texel needs no normals.
    const bool lit = settings.lighting != Lighting::Off && usesColor(settings);
    if (lit || settings.showNormals) {
        // Normals depend on the mesh alone: recomputed only when its positions or indices change.
        const std::uint64_t h =
            fingerprint(std::span(mesh.indices), fingerprint(std::span(mesh.positions)));
        if (h != normalsFingerprint_ || normals_.size() != positions.size()) {
            computeVertexNormals(mesh, normals_, normalSums_);
            normalsFingerprint_ = h;
        }
    }
    if (lit && settings.lighting == Lighting::Gouraud) {
        // Gouraud: the formula once per vertex in world space; the rasterizer then
        // interpolates the lit colour like any other vertex colour.
        litColors_.resize(positions.size());
#pragma omp parallel for num_threads(threads) if (vertexCount > kParallelVertices)
        for (std::ptrdiff_t i = 0; i < vertexCount; ++i) {
            const glm::vec3 rgb = mesh.hasColors() ? mesh.colors[i] : glm::vec3(1.0f);
            litColors_[i] =
                shade(rgb, lightIntensity(positions[i], normals_[i], input.eye, input.lighting));
        }
        input.colors = litColors_;
    }
    if (lit && settings.lighting == Lighting::Phong) {
        input.normals = normals_;
        input.positions = positions;
    }
    if (settings.shader == ShaderKind::Texture) input.uvs = mesh.uvs;

    const double vertexMs = msSince(t);
    RenderStats stats = draw(input, settings, frame);
    stats.clearMs = clearMs;
    stats.vertexMs = vertexMs;
    stats.rasterMs = msSince(t);
    stats.vertexBytes = vertexBytes(settings, mesh, variantKey(settings, input));
    if (settings.showNormals) drawNormals(scene, cam, settings, input.nearPlane, frame, stats);
    // Last, so neither the normals nor the depth colours cover it.
    if (settings.shader == ShaderKind::Depth && settings.depthLegend && stats.depthFar > 0.0f)
        drawDepthLegend(frame, stats.depthNear, stats.depthFar);
    stats.postMs = msSince(t);
    return stats;
}

void Renderer::drawNormals(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                           float nearPlane, Framebuffer& frame, RenderStats& stats) {
    const Mesh& mesh = scene.mesh;
    const float length = settings.normalLength > 0.0 ? static_cast<float>(settings.normalLength)
                                                     : normalDisplayLength(mesh);
    const glm::dmat4 clipFromWorldD = clipFromWorld(camera);
    normalClip_.clear();
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        if (normals_[i] == glm::vec3(0.0f)) continue;  // no face: no direction to show
        const glm::vec3 p = mesh.positions[i];
        normalClip_.push_back(clipPoint(clipFromWorldD, p));
        normalClip_.push_back(clipPoint(clipFromWorldD, p + length * normals_[i]));
    }
    normalEdges_.resize(normalClip_.size());
    for (std::size_t i = 0; i < normalEdges_.size(); ++i)
        normalEdges_[i] = static_cast<std::uint32_t>(i);
    const DrawInput segments{.clip = normalClip_, .nearPlane = nearPlane};
    const DrawConstants red{&whiteTexture(), {}, glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
    // Simple overwrites; every other shader keeps the depth test, so hidden normals stay hidden.
    constexpr Interp P = Interp::Perspective;
    constexpr TextureFilter N = TextureFilter::Nearest;
    RenderStats lines;
    if (settings.shader == ShaderKind::Simple)
        drawLines<Variant<ShaderKind::Simple, P, false, false, false, N, false>>(
            segments, normalEdges_, frame, red, lines);
    else
        drawLines<Variant<ShaderKind::Painter, P, false, false, false, N, false>>(
            segments, normalEdges_, frame, red, lines);
    stats.normalsDrawn = lines.linesDrawn;
    stats.fragments += lines.fragments;
}

}  // namespace facet
