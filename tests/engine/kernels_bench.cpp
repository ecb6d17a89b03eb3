// Micro-benchmarks of the fast path's kernels (Google Benchmark): triangle setup, block
// rasterization, shading, and the whole frame for context. Every input is fixed (no clock, no
// std:: random distributions, whose output differs between standard libraries), so two runs or
// two machines measure the same work and the counters can be compared directly.
//
// The kernels are called the way the engine calls them (pipeline.cpp, tile_renderer.cpp) with the
// same Variant instantiations the dispatcher picks, so a number here is a number of the renderer.
// Only the bunny benchmarks need ../shared; without it they are skipped with a message.
//
// Rates: items_per_second is triangles/s for setup, pixels/s for rasterization and shading,
// fragments/s for fragmentColor and frames/s for the whole render.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "coverage/coverage.hpp"
#include "facet/advanced/draw.hpp"
#include "facet/advanced/fast_lighting.hpp"
#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "facet/settings.hpp"
#include "facet/texture.hpp"
#include "frontend/front_end.hpp"
#include "pipeline/span_targets.hpp"
#include "shading/fragment.hpp"
#include "shading/scalar_loop.hpp"
#include "shared_data.hpp"

namespace {

using namespace facet;
using namespace facet::detail;

// ---------------------------------------------------------------------------------------------
// Fixed inputs

/// SplitMix64: a fixed sequence on every platform (unlike std::uniform_real_distribution).
class Rng {
  public:
    explicit Rng(std::uint64_t seed) : s_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [lo, hi), from the top 53 bits.
    double uniform(double lo, double hi) {
        return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53;
    }

  private:
    std::uint64_t s_;
};

const std::string kBunnyScene = test::sharedData("scenes/bunny_1920x1080.scene");

/// The bunny at 1920×1080, loaded once for all benchmarks (loading costs more than most of them);
/// null with `error` set when the shared data is missing, and under CI the end of the run (the
/// benchmark's own error would not fail it).
const Scene* bunny(std::string& error) {
    if (std::string missing = test::missingSharedData(kBunnyScene); !missing.empty()) {
        if (test::sharedDataRequired()) {
            std::fprintf(stderr, "%s\n", missing.c_str());
            std::exit(1);
        }
        error = std::move(missing);
        return nullptr;
    }
    static const Result<Scene> scene = loadScene(kBunnyScene);
    if (!scene.ok()) {
        error = scene.error().what();
        return nullptr;
    }
    return &scene.value();
}

/// The bunny in clip space, transformed exactly as Renderer::render does (float matrix built in
/// double).
struct ClipMesh {
    std::vector<glm::vec4> clip;
    DrawInput input;
};

const ClipMesh* bunnyClip(std::string& error) {
    static ClipMesh mesh;
    const Scene* scene = bunny(error);
    if (scene == nullptr) return nullptr;
    if (mesh.clip.empty()) {
        const glm::mat4 clipFromWorldF(clipFromWorld(scene->camera));
        for (const glm::vec3& p : scene->mesh->positions)
            mesh.clip.push_back(clipFromWorldF * glm::vec4(p, 1.0f));
        mesh.input.clip = mesh.clip;
        mesh.input.indices = scene->mesh->indices;
        mesh.input.nearPlane = static_cast<float>(resolveNearPlane(RenderSettings{}, *scene->mesh));
    }
    return &mesh;
}

/// The bunny scene's own lighting (scenes/bunny_1920x1080.scene), written out so that the
/// shading benchmarks do not need the shared data.
FastLighting benchLighting() {
    LightingParams params;
    params.ambient = 0.4;
    params.light.position = {0.6, 1.0, -1.2, 1.0};  // in front of the quad below, as seen by eye
    params.light.intensity = 1.0;
    params.material = {0.5, 0.7, 0.3, 20.0};
    return prepareLighting(params);
}

/// A 512×512 texture with detail at every scale (so no mip level is a flat colour): each level
/// of the chain differs, and bilinear weights are never all 0 or 1.
const Texture& benchTexture() {
    static const Texture texture = [] {
        constexpr int n = 512;
        std::vector<std::uint32_t> pixels(static_cast<std::size_t>(n) * n);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const auto r = static_cast<std::uint32_t>((x ^ y) & 0xFF);
                const auto g = static_cast<std::uint32_t>((x * 3 + y) & 0xFF);
                const auto b = static_cast<std::uint32_t>(((x / 32 + y / 32) & 1) ? 230 : 40);
                pixels[static_cast<std::size_t>(y) * n + static_cast<std::size_t>(x)] =
                    packRgba(r, g, b);
            }
        return Texture::fromRgba(n, n, std::move(pixels), "bench").value();
    }();
    return texture;
}

/// An emit callback that only counts its calls, so drawTriangles is timed alone.
std::size_t countEmit(void* context, const CoverageSetup&, const Planes&) {
    ++*static_cast<std::size_t*>(context);
    return 0;
}

/// What drawTriangles hands the rasterizer, kept to be replayed.
struct Emitted {
    CoverageSetup setup;
    Planes planes;
};

std::size_t keepEmit(void* context, const CoverageSetup& setup, const Planes& planes) {
    static_cast<std::vector<Emitted>*>(context)->push_back({setup, planes});
    return 0;
}

// ---------------------------------------------------------------------------------------------
// 1. Triangle setup

// The whole front end over the bunny's 69,451 triangles (fetch, reject, near clip, snap,
// setupCoverage, cull, planes) in the painter layout (depth only), with a rasterizer that only
// counts its calls ("emitted"). Arg: back-face culling.
void setupDrawTriangles(benchmark::State& state) {
    std::string error;
    const ClipMesh* mesh = bunnyClip(error);
    if (mesh == nullptr) {
        state.SkipWithError(error.c_str());
        return;
    }
    const bool cull = state.range(0) != 0;
    const std::size_t triangles = mesh->input.indices.size() / 3;
    std::size_t emitted = 0;
    for (auto _ : state) {
        emitted = 0;
        RenderStats stats;
        benchmark::DoNotOptimize(drawTriangles(mesh->input, VaryingLayout{}, cull, 1920, 1080, 0,
                                               triangles, &countEmit, &emitted, stats));
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(triangles));
    state.counters["emitted"] = static_cast<double>(emitted);
}
BENCHMARK(setupDrawTriangles)
    ->Name("setup/drawTriangles/bunny1080")
    ->ArgName("cull")
    ->Arg(0)
    ->Arg(1);

// setupCoverage alone on 4096 small triangles (vertices within 6 px of a random centre, about
// 11 px² on average, either facing) spread over a 1080p screen: the size of the bunny's
// triangles at 1080p (about 15 px each), where setup, not pixels, is the cost.
void setupCoverageSmall(benchmark::State& state) {
    constexpr int kCount = 4096;
    struct Snapped {
        std::int64_t x[3], y[3];
    };
    std::vector<Snapped> tris(kCount);
    Rng rng(1);
    for (Snapped& t : tris) {
        const double cx = rng.uniform(0.0, 1920.0), cy = rng.uniform(0.0, 1080.0);
        for (int i = 0; i < 3; ++i) {
            t.x[i] = SnapGrid{}(cx + rng.uniform(-6.0, 6.0));
            t.y[i] = SnapGrid{}(cy + rng.uniform(-6.0, 6.0));
        }
    }
    const PixelRect screen{0, 0, 1919, 1079};
    for (auto _ : state) {
        for (const Snapped& t : tris) {
            CoverageSetup out;
            const Facing facing = setupCoverage(t.x, t.y, screen, out);
            benchmark::DoNotOptimize(facing);
            benchmark::DoNotOptimize(out);
        }
    }
    state.SetItemsProcessed(state.iterations() * kCount);
}
BENCHMARK(setupCoverageSmall)->Name("setup/setupCoverage/small");

// ---------------------------------------------------------------------------------------------
// 2. Block rasterization

/// 16 triangles of about `area` pixels, one shape turned by 16 angles and moved by sub-pixel
/// offsets, so the count does not hinge on one lucky alignment with the pixel grid.
std::vector<CoverageSetup> rasterTriangles(double area) {
    // Shape (0, 0), (1, 0.25), (0.3, 1) has area 0.4625: scale its sides by sqrt(area / 0.4625).
    const double s = std::sqrt(area / 0.4625);
    const glm::dvec2 shape[3] = {{0.0, 0.0}, {s, 0.25 * s}, {0.3 * s, s}};
    const glm::dvec2 centroid = (shape[0] + shape[1] + shape[2]) / 3.0;
    const PixelRect clip{0, 0, 1199, 1199};
    std::vector<CoverageSetup> setups;
    for (int k = 0; k < 16; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 16.0;
        const double c = std::cos(a), sn = std::sin(a);
        const glm::dvec2 at(600.0 + 0.37 * k / 16.0, 600.0 + 0.61 * ((k * 7) % 16) / 16.0);
        std::int64_t xs[3], ys[3];
        for (int i = 0; i < 3; ++i) {
            const glm::dvec2 d = shape[i] - centroid;
            xs[i] = SnapGrid{}(at.x + c * d.x - sn * d.y);
            ys[i] = SnapGrid{}(at.y + sn * d.x + c * d.y);
        }
        CoverageSetup setup;
        if (setupCoverage(xs, ys, clip, setup) != Facing::Degenerate) setups.push_back(setup);
    }
    return setups;
}

// forEachCovered counting the covered pixels. Arg: triangle area in pixels.
void rasterForEachCovered(benchmark::State& state) {
    const std::vector<CoverageSetup> tris = rasterTriangles(static_cast<double>(state.range(0)));
    std::size_t covered = 0, boxPixels = 0;
    for (const CoverageSetup& s : tris)
        boxPixels += static_cast<std::size_t>(s.box.x1 - s.box.x0 + 1) *
                     static_cast<std::size_t>(s.box.y1 - s.box.y0 + 1);
    for (auto _ : state) {
        covered = 0;
        for (const CoverageSetup& s : tris) forEachCovered(s, [&](int, int) { ++covered; });
        benchmark::DoNotOptimize(covered);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(covered));
    state.counters["px/tri"] = static_cast<double>(covered) / static_cast<double>(tris.size());
    // Covered share of the bounding boxes: the work the box walk wastes is the rest.
    state.counters["fill"] = static_cast<double>(covered) / static_cast<double>(boxPixels);
    state.counters["tris/s"] = benchmark::Counter(static_cast<double>(tris.size()),
                                                  benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(rasterForEachCovered)
    ->Name("raster/forEachCovered")
    ->ArgName("area")
    ->Arg(8)
    ->Arg(64)
    ->Arg(1024)
    ->Arg(100000);

// ---------------------------------------------------------------------------------------------
// 3. Shading

// The variants the dispatcher (pipeline.cpp) instantiates for these settings, all perspective:
// painter on a mesh without colours (depth only, white: the bunny's default), Gouraud (lit
// colours interpolated), Phong on a mesh without colours, the texture shader, and Spot's
// texture × Phong.
constexpr auto kPersp = Interp::Perspective;
constexpr auto kNear = TextureFilter::Nearest;
using PainterV = Variant<ShaderKind::Painter, kPersp, false, false, false, kNear, false>;
using GouraudV = Variant<ShaderKind::Painter, kPersp, true, false, false, kNear, false>;
using PhongV = Variant<ShaderKind::Painter, kPersp, false, false, true, kNear, false>;
using BilinearV =
    Variant<ShaderKind::Texture, kPersp, false, true, false, TextureFilter::Bilinear, false>;
using TrilinearV =
    Variant<ShaderKind::Texture, kPersp, false, true, false, TextureFilter::Trilinear, false>;
using TexturePhongV =
    Variant<ShaderKind::Texture, kPersp, false, true, true, TextureFilter::Bilinear, true>;

constexpr int kQuad = 256;

/// A 256×256-pixel quad filling a 256×256 frame, as two triangles in perspective: 1/w goes from
/// 1 to 0.6 across it, so perspective division, varying mip levels and the depth test all do
/// real work. The fill rule gives each of the 65,536 pixels to exactly one triangle. Varyings:
/// per-vertex colours, uv over [0, 1]² (a 512² texture at λ from 0.7 to 1.7, so trilinear
/// blends levels 0 to 2), normals tilted about the quad's normal, world positions on the plane
/// z = 0 facing the eye and the light. The kernel gets whole triangles; the renderer gives it
/// the same triangles cut to 64×64 tiles (tile_renderer.cpp), which changes only the boxes.
std::vector<Emitted> quadTriangles(const VaryingLayout& layout) {
    const glm::vec2 px[4] = {{0, 0}, {kQuad, 0}, {kQuad, kQuad}, {0, kQuad}};
    const float invW[4] = {1.0f, 0.8f, 0.6f, 0.8f};  // affine in screen space: a planar quad
    std::vector<glm::vec4> clip;
    for (int i = 0; i < 4; ++i) {
        const float w = 1.0f / invW[i];
        clip.emplace_back(px[i].x * w, px[i].y * w, w, w);
    }
    const std::vector<glm::vec3> colors = {
        {1.0f, 0.2f, 0.1f}, {0.1f, 0.9f, 0.2f}, {0.2f, 0.3f, 1.0f}, {0.9f, 0.9f, 0.1f}};
    const std::vector<glm::vec2> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const std::vector<glm::vec3> normals = {{-0.3f, -0.3f, -0.906f},
                                            {0.3f, -0.3f, -0.906f},
                                            {0.3f, 0.3f, -0.906f},
                                            {-0.3f, 0.3f, -0.906f}};
    const std::vector<glm::vec3> positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    const std::vector<std::uint32_t> indices = {0, 1, 2, 0, 2, 3};
    DrawInput in{.clip = clip,
                 .colors = colors,
                 .uvs = uvs,
                 .normals = normals,
                 .positions = positions,
                 .indices = indices};
    std::vector<Emitted> out;
    RenderStats stats;
    drawTriangles(in, layout, false, kQuad, kQuad, 0, 2, &keepEmit, &out, stats);
    return out;
}

DrawConstants benchConstants() {
    return {&benchTexture(), benchLighting(), glm::vec3(0.0f, 0.0f, -3.0f), glm::vec3(1.0f)};
}

// Times rasterizeTriangle<V> over `tris`, which must cover the 256×256 frame exactly, with
// the given vector loops (null: the scalar loop). Depth is cleared before each iteration,
// outside the timing, so every pixel passes the depth test and is shaded.
template <class V>
void timeTriangles(benchmark::State& state, const std::vector<Emitted>& tris, PixelLoopFn spans,
                   PixelLoopFn blocks) {
    const DrawConstants constants = benchConstants();
    Framebuffer fb;
    fb.resize(kQuad, kQuad);
    fb.clear(0);
    RasterContext ctx{&fb, &constants, 16, spans, blocks};
    std::size_t pixels = 0;
    for (auto _ : state) {
        state.PauseTiming();
        std::fill(fb.depth.begin(), fb.depth.end(), kEmptyDepth);
        state.ResumeTiming();
        pixels = 0;
        for (const Emitted& t : tris) pixels += rasterizeTriangle<V>(ctx, t.setup, t.planes);
    }
    benchmark::DoNotOptimize(fb.color.data());
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pixels));
    if (pixels != static_cast<std::size_t>(kQuad) * kQuad)
        state.SkipWithError("the triangles do not cover exactly 256x256 pixels");
}

// rasterizeTriangle<V>, the whole per-pixel loop (coverage, depth, interpolation, shading,
// store), on the quad, with the vector loops of the best target.
template <class V>
void shadeQuad(benchmark::State& state) {
    timeTriangles<V>(state, quadTriangles(V::kLayout), spanLoopFor<V>(), blockLoopFor<V>());
}
BENCHMARK_TEMPLATE(shadeQuad, PainterV)->Name("shade/painter");
BENCHMARK_TEMPLATE(shadeQuad, GouraudV)->Name("shade/gouraud");
BENCHMARK_TEMPLATE(shadeQuad, PhongV)->Name("shade/phong");
BENCHMARK_TEMPLATE(shadeQuad, BilinearV)->Name("shade/textureBilinear");
BENCHMARK_TEMPLATE(shadeQuad, TrilinearV)->Name("shade/textureTrilinear");
BENCHMARK_TEMPLATE(shadeQuad, TexturePhongV)->Name("shade/texturePhongCombine");

/// The same quad as a grid of 4×4-pixel cells, two triangles each (8,192 triangles of 8 pixels,
/// about a dense mesh's size: the bunny's average 7), with every varying interpolated across
/// the quad as in quadTriangles().
std::vector<Emitted> smallTriangles(const VaryingLayout& layout) {
    constexpr int kCells = kQuad / 4;
    std::vector<glm::vec4> clip;
    std::vector<glm::vec3> colors, normals, positions;
    std::vector<glm::vec2> uvs;
    for (int j = 0; j <= kCells; ++j)
        for (int i = 0; i <= kCells; ++i) {
            const float u = static_cast<float>(i) / kCells, v = static_cast<float>(j) / kCells;
            const float w = 1.0f / (1.0f - 0.2f * u - 0.2f * v);  // the quad's 1/w: 1 to 0.6
            clip.emplace_back(u * kQuad * w, v * kQuad * w, w, w);
            colors.emplace_back(1.0f - 0.8f * u, 0.2f + 0.7f * v, 0.1f + 0.8f * u * v);
            uvs.emplace_back(u, v);
            normals.emplace_back(0.6f * u - 0.3f, 0.6f * v - 0.3f, -0.906f);
            positions.emplace_back(2.0f * u - 1.0f, 2.0f * v - 1.0f, 0.0f);
        }
    std::vector<std::uint32_t> indices;
    for (int j = 0; j < kCells; ++j)
        for (int i = 0; i < kCells; ++i) {
            const auto at = [&](int di, int dj) {
                return static_cast<std::uint32_t>((j + dj) * (kCells + 1) + i + di);
            };
            indices.insert(indices.end(),
                           {at(0, 0), at(1, 0), at(1, 1), at(0, 0), at(1, 1), at(0, 1)});
        }
    DrawInput in{.clip = clip,
                 .colors = colors,
                 .uvs = uvs,
                 .normals = normals,
                 .positions = positions,
                 .indices = indices};
    std::vector<Emitted> out;
    RenderStats stats;
    drawTriangles(in, layout, false, kQuad, kQuad, 0, indices.size() / 3, &keepEmit, &out, stats);
    return out;
}

// rasterizeTriangle<V> on the small triangles, with the vector loops of the best target or
// without (the scalar loop): their ratio in one run is what the block loop gains.
template <class V, bool Vector>
void shadeSmall(benchmark::State& state) {
    timeTriangles<V>(state, smallTriangles(V::kLayout), Vector ? spanLoopFor<V>() : nullptr,
                     Vector ? blockLoopFor<V>() : nullptr);
}
BENCHMARK_TEMPLATE(shadeSmall, PainterV, false)->Name("shadeSmall/painter/scalar");
BENCHMARK_TEMPLATE(shadeSmall, PainterV, true)->Name("shadeSmall/painter/vector");
BENCHMARK_TEMPLATE(shadeSmall, GouraudV, false)->Name("shadeSmall/gouraud/scalar");
BENCHMARK_TEMPLATE(shadeSmall, GouraudV, true)->Name("shadeSmall/gouraud/vector");
BENCHMARK_TEMPLATE(shadeSmall, PhongV, false)->Name("shadeSmall/phong/scalar");
BENCHMARK_TEMPLATE(shadeSmall, PhongV, true)->Name("shadeSmall/phong/vector");
BENCHMARK_TEMPLATE(shadeSmall, BilinearV, false)->Name("shadeSmall/textureBilinear/scalar");
BENCHMARK_TEMPLATE(shadeSmall, BilinearV, true)->Name("shadeSmall/textureBilinear/vector");

// The same quad behind what is already drawn: early depth rejects every pixel, so this is the
// cost of coverage and the depth test alone (overdraw that loses).
void shadeOccluded(benchmark::State& state) {
    const std::vector<Emitted> tris = quadTriangles(PhongV::kLayout);
    const DrawConstants constants = benchConstants();
    Framebuffer fb;
    fb.resize(kQuad, kQuad);
    fb.clear(0);
    std::fill(fb.depth.begin(), fb.depth.end(), 0.0f);
    RasterContext ctx{&fb, &constants, 16, spanLoopFor<PhongV>(), blockLoopFor<PhongV>()};
    std::size_t pixels = 0;
    for (auto _ : state) {
        pixels = 0;
        for (const Emitted& t : tris) pixels += rasterizeTriangle<PhongV>(ctx, t.setup, t.planes);
        benchmark::DoNotOptimize(pixels);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(pixels));
}
BENCHMARK(shadeOccluded)->Name("shade/phongOccluded");

/// Interpolated varyings of 4096 fragments spread over the quad, in V's layout, precomputed so
/// only fragmentColor is timed.
template <class V>
std::vector<float> fragmentVaryings(int count) {
    const std::vector<Emitted> tris = quadTriangles(V::kLayout);
    std::vector<float> out;
    Rng rng(7);
    for (int i = 0; i < count; ++i) {
        const Planes& p = tris[static_cast<std::size_t>(i) % tris.size()].planes;
        const auto m1 = static_cast<float>(rng.uniform(0.0, 0.5));
        const auto m2 = static_cast<float>(rng.uniform(0.0, 0.5));
        for (int j = 0; j < V::kCount; ++j) out.push_back(p.a0[j] + m1 * p.d1[j] + m2 * p.d2[j]);
    }
    return out;
}

// fragmentColor<V> alone: lighting or texture filtering without coverage, depth or stores.
template <class V>
void fragmentOnly(benchmark::State& state) {
    constexpr int kCount = 4096;
    const std::vector<float> varyings = fragmentVaryings<V>(kCount);
    const DrawConstants constants = benchConstants();
    for (auto _ : state) {
        glm::vec3 sum(0.0f);
        for (std::size_t i = 0; i < static_cast<std::size_t>(kCount); ++i)
            sum += fragmentColor<V>(&varyings[i * V::kCount], constants, 0.0f);
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * kCount);
}
BENCHMARK_TEMPLATE(fragmentOnly, PhongV)->Name("fragment/phong");
BENCHMARK_TEMPLATE(fragmentOnly, BilinearV)->Name("fragment/textureBilinear");

// ---------------------------------------------------------------------------------------------
// 4. The whole frame, for context: Renderer::render of the bunny at 1080p, painter shader
// (clear, transform, binning, rasterization). Arg: engine threads. Wall-clock time, since the
// worker threads' CPU time is not the main thread's.
void renderBunny(benchmark::State& state) {
    std::string error;
    const Scene* scene = bunny(error);
    if (scene == nullptr) {
        state.SkipWithError(error.c_str());
        return;
    }
    RenderSettings settings;
    settings.threads = static_cast<int>(state.range(0));
    Renderer renderer;
    Framebuffer frame;
    RenderStats stats = renderer.render(*scene, settings, frame).value();  // scratch buffers, once
    for (auto _ : state) {
        stats = renderer.render(*scene, settings, frame).value();
        benchmark::DoNotOptimize(frame.color.data());
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["fragments"] = static_cast<double>(stats.fragments);
}
BENCHMARK(renderBunny)
    ->Name("render/bunny1080painter")
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
