// The fast path's frame, stage by stage: clear (passes/), vertex stage (vertex_stage.hpp), the
// draw (the variant picked once, variants.hpp; then the front end, binning, coverage and the
// pixel loops for triangles, or lines and points), and the passes after it (depth colours,
// normals, legend, supersample resolve). The per-pixel code has no branch on the settings, no
// virtual call and no allocation.

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>

#include "binning/tiles.hpp"
#include "debug/debug_maps.hpp"
#include "debug/probe.hpp"
#include "facet/advanced/draw.hpp"
#include "facet/camera.hpp"
#include "facet/debug_view.hpp"
#include "facet/legend.hpp"
#include "facet/multisample.hpp"
#include "facet/render.hpp"
#include "lines/lines_points.hpp"
#include "passes/frame_passes.hpp"
#include "passes/normals_overlay.hpp"
#include "passes/supersample.hpp"
#include "pipeline/msaa_draw.hpp"
#include "pipeline/span_targets.hpp"
#include "pipeline/variants.hpp"
#include "pipeline/vertex_stage.hpp"
#include "scene/fingerprint.hpp"
#include "scene/scratch.hpp"
#include "shading/msaa_loop.hpp"
#include "shading/scalar_loop.hpp"

namespace facet {

using namespace detail;

/// What a Renderer keeps between frames, so a steady frame allocates nothing.
struct Renderer::Impl {
    VertexStage vertices;
    /// The wireframe's unique edges, rebuilt when the indices' fingerprint changes.
    std::vector<std::uint32_t> edges;
    std::vector<std::uint64_t> edgeKeys;
    std::uint64_t edgesFingerprint = 0;
    NormalsOverlay normalsOverlay;
    TileRenderer tiles;                  // bins kept between frames
    Framebuffer supersampled;            // the N×N-size image of a supersampled frame
    Framebuffer samples;                 // the per-sample buffer of a multisampled draw
    DrawProbe probe;                     // the debug views' instrumented draw
    Framebuffer affine;                  // the interpolation-error view's second frame
    std::vector<std::uint32_t> binLoad;  // the bin-load view's counts per tile

    void updateEdges(std::span<const std::uint32_t> indices) {
        // The edge list is rebuilt (a sort) only when the indices change.
        const std::uint64_t h = fingerprint(indices);
        if (h == edgesFingerprint && !edges.empty()) return;
        uniqueEdges(indices, edges, edgeKeys);
        edgesFingerprint = h;
    }

    /// One frame at the camera's size; `input`, when given, receives the draw's input (valid
    /// until the next frame). The camera and size are already checked (checkFrame).
    RenderStats renderView(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                           Framebuffer& frame, DrawInput* input = nullptr);

    /// draw() (facet/advanced/draw.hpp) on a frame already checked; with `clear`, the frame is
    /// first cleared to that colour (depth kEmptyDepth): by the tile renderer in each tile when
    /// it can (TileFrame), else in a pass.
    RenderStats draw(const DrawInput& input, const RenderSettings& settings, Framebuffer& frame,
                     const std::uint32_t* clear = nullptr);
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

namespace {

/// Counts coverage instead of shading (fill-rule tests and overdraw views).
struct CoverageCounts {
    std::uint16_t* counts;
    int width;

    std::size_t operator()(const CoverageSetup& setup, const Planes&, const PixelTarget&) const {
        std::size_t covered = 0;
        forEachCovered(setup, [&](int x, int y) {
            ++covered;
            std::uint16_t& n =
                counts[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                       static_cast<std::size_t>(x)];
            if (n != std::numeric_limits<std::uint16_t>::max()) ++n;
        });
        return covered;
    }
};

/// Counts covered samples instead (multisampling): `counts` in the per-sample buffer's layout.
struct SampleCounts {
    std::uint16_t* counts;
    int width;  ///< of the per-sample buffer
    SamplePattern pattern;

    std::size_t operator()(const CoverageSetup& setup, const Planes&, const PixelTarget&) const {
        const SamplePattern& sp = pattern;
        std::size_t covered = 0;
        forEachCoveredSamples(
            setup, sp, [&](int x, int y, const std::int64_t(&)[3], unsigned mask) {
                ++covered;
                const std::size_t first =
                    static_cast<std::size_t>(y * sp.block.y) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(x * sp.block.x);
                for (int j = 0; j < sp.count; ++j) {
                    if (!(mask & (1u << j))) continue;
                    std::uint16_t& n = counts[first + sp.at(j, width)];
                    if (n != std::numeric_limits<std::uint16_t>::max()) ++n;
                }
            });
        return covered;
    }
};

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

double msSince(Clock::time_point& t) {
    const Clock::time_point now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - t).count();
    t = now;
    return ms;
}

/// A frame draw() may draw into: a size checkImageSize accepts, and both planes that size.
Status checkFramebuffer(const Framebuffer& frame, const RenderSettings& settings) {
    if (Status st = checkImageSize(frame.width, frame.height, 1, settings.msaa); !st) return st;
    const std::size_t pixels =
        static_cast<std::size_t>(frame.width) * static_cast<std::size_t>(frame.height);
    if (frame.color.size() != pixels || frame.depth.size() != pixels)
        return Error{{},
                     "the frame's colour and depth planes are not " + std::to_string(frame.width) +
                         "x" + std::to_string(frame.height) +
                         " pixels (size it with Framebuffer::resize)"};
    return {};
}

}  // namespace

RenderStats Renderer::Impl::draw(const DrawInput& input, const RenderSettings& settings,
                                 Framebuffer& frame, const std::uint32_t* clear) {
    RenderStats stats;
    if (frame.width <= 0 || frame.height <= 0) return stats;
    const VariantKey key = variantKey(settings, input);
    stats.varyings = 1 + key.layout.count();
    stats.varyingNames = key.layout.names();
    const DrawConstants constants{input.texture ? input.texture : &whiteTexture(), input.lighting,
                                  input.eye, glm::vec3(1.0f)};
    const int subdivision = std::clamp(settings.subdivision, kMinSubdivision, kMaxSubdivision);
    const int threads = resolveThreads(settings.threads);
    const PixelLoopFn spans = spanLoop(key);  // the SIMD target, chosen once per draw
    const PixelLoopFn blocks = blockLoop(key);
    // Multisampling draws triangles into the per-sample buffer, which starts as the frame's
    // pixels and is resolved back into it; lines and points stay one sample (spec §11).
    const int sampleCount = settings.mode == DrawMode::Solid ? msaaSamples(settings.msaa) : 1;
    const SampleBlock block = sampleBlock(sampleCount);
    Framebuffer& target = sampleCount > 1 ? samples : frame;
    // The tile renderer clears a one-sample solid draw (TileFrame); the others clear here.
    const bool tileClear = settings.mode == DrawMode::Solid && sampleCount == 1;
    if (clear && !tileClear) {
        Clock::time_point t = Clock::now();
        clearFrame(frame, *clear, threads);
        stats.clearMs += msSince(t);
    }
    if (sampleCount > 1) {  // Solid mode: triangles only
        expandToSamples(frame, block.x, block.y, samples, threads);
        drawMsaaTriangles(tiles, key, input, settings, constants, samples, sampleCount, frame.width,
                          frame.height, subdivision, threads, clampedSubPixelBits(settings), stats);
    } else {
        dispatch(key, [&](auto variant) {
            using V = decltype(variant);
            switch (settings.mode) {
                case DrawMode::Solid: {
                    const TriangleRaster<V> raster{
                        {&frame, &constants, subdivision, spans, blocks}};
                    const TileFrame pixels{&frame, clear != nullptr, clear ? *clear : 0u,
                                           depthTested(V::kShader)};
                    tiles.draw(drawJob(input, V::kLayout, settings, frame.width, frame.height),
                               raster, threads, stats, pixels);
                    break;
                }
                case DrawMode::Wireframe:
                    updateEdges(input.indices);
                    drawLines<V>(input, edges, frame, constants, stats);
                    break;
                case DrawMode::Vertices:
                    drawPoints<V>(input, settings.pointSize, frame, constants, stats);
                    break;
            }
        });
    }
    if (settings.shader == ShaderKind::Depth) resolveDepthColors(target, stats, threads);
    if (sampleCount > 1) resolveSupersampled(samples, block.x, block.y, frame, threads);
    return stats;
}

/// The advanced API's way into a Renderer's scratch buffers (a friend of Renderer).
struct detail::RendererAccess {
    /// The renderer's kept state.
    static Renderer::Impl& impl(Renderer& renderer) { return *renderer.impl_; }
    /// The same, read-only.
    static const Renderer::Impl& impl(const Renderer& renderer) { return *renderer.impl_; }
};

Result<RenderStats> draw(Renderer& renderer, const DrawInput& input, const RenderSettings& settings,
                         Framebuffer& frame) {
    if (Status st = checkFramebuffer(frame, settings); !st) return st.error();
    return RendererAccess::impl(renderer).draw(input, settings, frame);
}

const Framebuffer& sampleBuffer(const Renderer& renderer) {
    return RendererAccess::impl(renderer).samples;
}

Status countCoverage(Renderer& renderer, const DrawInput& input, const RenderSettings& settings,
                     int width, int height, std::vector<std::uint16_t>& counts) {
    auto& impl = RendererAccess::impl(renderer);
    if (Status st = checkImageSize(width, height, 1, settings.msaa); !st) return st;
    const int samples = msaaSamples(settings.msaa);
    counts.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) *
                      static_cast<std::size_t>(samples),
                  0);
    RenderStats stats;
    if (samples > 1) {
        DrawJob job = drawJob(input, VaryingLayout{}, settings, width, height);
        job.sampleReach = SamplePattern::kReach;
        impl.tiles.draw(
            job,
            SampleCounts{counts.data(), width * sampleBlock(samples).x, SamplePattern::of(samples)},
            resolveThreads(settings.threads), stats);
        return {};
    }
    impl.tiles.draw(drawJob(input, VaryingLayout{}, settings, width, height),
                    CoverageCounts{counts.data(), width}, resolveThreads(settings.threads), stats);
    return {};
}

Result<RenderStats> Renderer::render(const Scene& scene, const RenderSettings& settings,
                                     Framebuffer& frame) {
    if (settings.view != DebugView::None) {
        DebugMap map;
        Result<RenderStats> stats = renderDebugView(scene, settings, frame, map);
        if (!stats) return stats;
        Clock::time_point t = Clock::now();
        paintDebugView(map, frame);
        stats.value().postMs += msSince(t);
        return stats;
    }
    if (Status st = checkFrame(scene.camera, settings); !st) return st.error();
    const int n = std::clamp(settings.supersample, 1, kMaxSupersample);
    if (n == 1 || settings.mode != DrawMode::Solid)
        return impl_->renderView(scene, scene.camera, settings, frame);
    // The legend is drawn on the final frame, at its size, so it stays legible.
    RenderSettings big = settings;
    big.depthLegend = false;
    const Camera& cam = scene.camera;
    RenderStats stats = impl_->renderView(scene, resizedCamera(cam, cam.width * n, cam.height * n),
                                          big, impl_->supersampled);
    Clock::time_point t = Clock::now();
    resolveSupersampled(impl_->supersampled, n, n, frame, resolveThreads(settings.threads));
    if (settings.shader == ShaderKind::Depth && settings.depthLegend && stats.depthFar > 0.0f)
        drawDepthLegend(frame, stats.depthNear, stats.depthFar);
    stats.postMs += msSince(t);
    return stats;
}

Result<RenderStats> Renderer::renderDebugView(const Scene& scene, const RenderSettings& settings,
                                              Framebuffer& frame, DebugMap& map) {
    const RenderSettings base = debugViewBase(settings);
    if (Status st = checkFrame(scene.camera, base); !st) return st.error();
    DrawInput input;
    RenderStats stats = impl_->renderView(scene, scene.camera, base, frame, &input);
    Clock::time_point t = Clock::now();
    switch (settings.view) {
        case DebugView::BinLoad:
            countBinLoad(impl_->tiles, input, base, frame.width, frame.height, impl_->binLoad);
            fillBinLoad(impl_->binLoad, frame.width, frame.height, map);
            break;
        case DebugView::InterpError: {
            RenderSettings affine = base;
            affine.interp = Interp::Affine;
            RenderSettings perspective = base;
            perspective.interp = Interp::Perspective;
            if (base.interp != Interp::Perspective)
                stats = impl_->renderView(scene, scene.camera, perspective, frame);
            impl_->renderView(scene, scene.camera, affine, impl_->affine);
            fillInterpError(frame, impl_->affine, map);
            break;
        }
        case DebugView::None:
            map = DebugMap{};
            break;
        default: {
            const bool lod = settings.view == DebugView::TextureLod;
            RenderStats probeStats;
            impl_->probe.run(input, base, frame.width, frame.height, lod, probeStats);
            const Texture& texture = input.texture ? *input.texture : whiteTexture();
            fillFromProbe(settings.view, impl_->probe, texture.levelCount(), map);
            break;
        }
    }
    stats.postMs += msSince(t);
    return stats;
}

RenderStats Renderer::Impl::renderView(const Scene& scene, const Camera& cam,
                                       const RenderSettings& settings, Framebuffer& frame,
                                       DrawInput* inputOut) {
    // Clear.
    Clock::time_point t = Clock::now();
    (void)frame.resize(cam.width, cam.height);  // within the limits: checked by checkFrame
    const int threads = resolveThreads(settings.threads);
    const std::uint32_t background = rgbaFromHex(settings.background);
    // The clear is the draw's (draw() below): the tile renderer clears a one-sample solid draw,
    // in its tile buffers where the draw is tile-resident, else in a pass after binning; the
    // other draws clear the frame in a pass first.
    const double clearMs = msSince(t);

    // Vertex stage: only the streams the settings need.
    const Mesh& mesh = *scene.mesh;
    std::span<const glm::vec3> vertexNormals;
    const DrawInput input =
        prepareDrawInput(vertices, scene, cam, settings, threads, vertexNormals);
    const double vertexMs = msSince(t);

    if (inputOut) *inputOut = input;

    // The draw, then the passes after it.
    RenderStats stats = draw(input, settings, frame, &background);
    // The clear the draw did (stats.clearMs so far) is reported as the clear, not as raster.
    stats.rasterMs = std::max(0.0, msSince(t) - stats.clearMs);
    stats.clearMs += clearMs;
    stats.vertexMs = vertexMs;
    stats.vertexBytes = vertexBytes(settings, mesh, variantKey(settings, input));
    if (settings.showNormals)
        normalsOverlay.draw(mesh, vertexNormals, cam, settings, input.nearPlane, frame, stats);
    // Last, so neither the normals nor the depth colours cover it.
    if (settings.shader == ShaderKind::Depth && settings.depthLegend && stats.depthFar > 0.0f)
        drawDepthLegend(frame, stats.depthNear, stats.depthFar);
    stats.postMs = msSince(t);
    return stats;
}

}  // namespace facet
