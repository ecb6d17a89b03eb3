// The pixel inspector (facet/inspect.hpp): the frame's draw re-run for one pixel through the fast
// path's own stages. The vertex stage is prepareDrawInput(), the front end is drawTriangles()
// called one triangle at a time (so the triangle's index is known), and its `emit` here, instead
// of a pixel loop, restricts the coverage setup to the pixel and runs the functions the scalar
// pixel loop runs (Planes::depthAt, passesDepth, fragmentWeights, interpolateVaryings, fragmentLod,
// fragmentColor, storeFragment) on a 1×1 framebuffer that holds the pixel's colour and depth.
// The vector span loop rounds exactly as the scalar one (span_loop-inl.hpp), so the colour found
// here is the frame's. Nothing of this runs during a frame.

#include "facet/inspect.hpp"

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>

#include "facet/camera.hpp"
#include "facet/multisample.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "passes/frame_passes.hpp"
#include "passes/supersample.hpp"
#include "pipeline/variants.hpp"
#include "pipeline/vertex_stage.hpp"
#include "shading/scalar_loop.hpp"

namespace facet {

using namespace detail;

namespace {

/// One sample position of the inspected pixel in the drawn (possibly supersampled) frame, and
/// the pixel's state there as the draw leaves it.
struct SamplePixel {
    int x = 0, y = 0;
    Framebuffer fb;  // 1×1: the colour and depth the frame holds at (x, y)
};

/// What the front end's emit call needs to inspect a triangle.
struct Probe {
    const DrawInput* input = nullptr;
    const Mesh* mesh = nullptr;
    const DrawConstants* constants = nullptr;
    const SnapGrid* grid = nullptr;
    int subdivision = 16;
    std::size_t triangle = 0;
    int piece = 0;  // emit calls for this triangle so far
    std::vector<SamplePixel>* samples = nullptr;
    std::vector<InspectedFragment>* out = nullptr;
};

/// The triangle's three vertices as fetched, projected and snapped.
void describeVertices(const Probe& pr, InspectedFragment& f) {
    for (int j = 0; j < 3; ++j) {
        InspectedVertex& v = f.vertices[j];
        v.index = pr.input->indices[3 * pr.triangle + static_cast<std::size_t>(j)];
        v.world = pr.mesh->positions[v.index];
        v.clip = pr.input->clip[v.index];
        v.screen = screenPosition(v.clip);
        v.fixedX = (*pr.grid)(v.screen.x);
        v.fixedY = (*pr.grid)(v.screen.y);
    }
}

/// The edge functions of `one` (a setup restricted to the pixel) at its centre, with the bias
/// of the top-left rule taken back out, and the vertices each edge joins.
void describeEdges(const CoverageSetup& one, InspectedFragment& f) {
    bool allMatched = true;
    for (int i = 0; i < 3; ++i) {
        InspectedEdge& e = f.edges[i];
        e.dx = one.stepY[i] / kSubPixel;
        e.dy = -one.stepX[i] / kSubPixel;
        e.topLeft = isTopLeft(e.dx, e.dy);
        e.value = one.e0[i] + (e.topLeft ? 0 : 1);
        e.inside = e.value > 0 || (e.value == 0 && e.topLeft);
        for (int a = 0; a < 3 && e.from < 0; ++a)
            for (int b = 0; b < 3; ++b)
                if (a != b && f.vertices[b].fixedX - f.vertices[a].fixedX == e.dx &&
                    f.vertices[b].fixedY - f.vertices[a].fixedY == e.dy) {
                    e.from = a;
                    e.to = b;
                    break;
                }
        allMatched = allMatched && e.from >= 0;
    }
    // Setup swaps vertices 1 and 2 of a front-facing triangle so inside is E ≥ 0: edge 0 then
    // runs 0 → 2.
    if (allMatched) f.backFacing = f.edges[0].to == 1;
    f.clipped = f.clipped || !allMatched;
}

/// The texels variant V's sampler reads at `uv` (and `lod`), with their weights.
template <class V>
void describeTexels(const Texture& tex, glm::vec2 uv, float lod, InspectedFragment& f) {
    auto addLevel = [&](int level, float share) {
        const MipLevel& m = tex.level(level);
        const BilinearTaps t = bilinearTaps(m, wrapCoord(uv.x), wrapCoord(uv.y));
        const int xs[4] = {t.x0, t.x1, t.x0, t.x1}, ys[4] = {t.y0, t.y0, t.y1, t.y1};
        const float ws[4] = {(1.0f - t.fx) * (1.0f - t.fy), t.fx * (1.0f - t.fy),
                             (1.0f - t.fx) * t.fy, t.fx * t.fy};
        for (int k = 0; k < 4; ++k)
            if (ws[k] * share > 0.0f)
                f.texels.push_back(
                    {level, xs[k], ys[k], texelColor(m, xs[k], ys[k]), ws[k] * share});
    };
    if constexpr (V::kFilter == TextureFilter::Nearest) {
        const glm::ivec2 t = nearestTexel(tex, uv);
        f.texels.push_back({0, t.x, t.y, texelColor(tex.level(0), t.x, t.y), 1.0f});
    } else if constexpr (V::kFilter == TextureFilter::Bilinear) {
        addLevel(0, 1.0f);
    } else {
        const TrilinearLevels levels = trilinearLevels(tex, lod);
        addLevel(levels.first, 1.0f - levels.fraction);
        if (levels.fraction != 0.0f) addLevel(levels.first + 1, levels.fraction);
    }
}

/// Everything after coverage for a covered fragment at sample `s`: the pixel loop's steps in
/// its order, each value kept.
template <class V>
void shadeFragment(const Probe& pr, const Planes& p, SamplePixel& s, InspectedFragment& f) {
    constexpr VaryingLayout L = V::kLayout;
    const DrawConstants& k = *pr.constants;
    const auto dx = static_cast<float>(s.x - p.baseX);
    const auto dy = static_cast<float>(s.y - p.baseY);
    f.depth = p.depthAt(dx, dy);
    f.depthTested = depthTested(V::kShader);
    f.storedDepth = s.fb.depth[0];
    f.passed = passesDepth<V::kShader>(s.fb, 0, f.depth);

    const float l1 = Planes::eval(p.l1, dx, dy), l2 = Planes::eval(p.l2, dx, dy);
    const float u1 = Planes::eval(p.u1, dx, dy) * f.depth,
                u2 = Planes::eval(p.u2, dx, dy) * f.depth;
    f.screenWeights = {1.0f - l1 - l2, l1, l2};
    f.perspectiveWeights = {1.0f - u1 - u2, u1, u2};
    float m1 = 0.0f, m2 = 0.0f;
    SubdividedSpan span;  // fresh: the same weights as the loop's kept span
    fragmentWeights<V>(p, s.x, s.y, dx, dy, f.depth, pr.subdivision,
                       1.0f / static_cast<float>(pr.subdivision), span, m1, m2);
    f.weights = {1.0f - m1 - m2, m1, m2};
    float a[V::kCount > 0 ? V::kCount : 1];
    interpolateVaryings<V>(p, m1, m2, a);
    f.hasColor = L.color;
    f.hasUv = L.uv;
    f.hasNormal = L.phong;
    if constexpr (L.color) f.color = vec3At(a, L.colorAt());
    if constexpr (L.uv) f.uv = {a[L.uvAt()], a[L.uvAt() + 1]};
    if constexpr (L.phong) {
        f.normal = vec3At(a, L.normalAt());
        f.position = vec3At(a, L.positionAt());
        f.lit = true;
        const glm::vec3 n = f.normal * inverseLength(f.normal);  // as phongTerms() scales it
        const LightTerms t = phongTerms(f.position, f.normal, k.eye, k.lighting, UnitPow{});
        const bool front = t.nl > 0.0f;  // the formula's rule: no light from behind
        f.lighting = {n,
                      t.l,
                      t.v,
                      t.h,
                      t.nl,
                      t.nh,
                      k.lighting.ambientTerm,
                      front ? t.diffuse : 0.0f,
                      front ? t.specular : 0.0f,
                      t.intensity};
    }
    const float lod = fragmentLod<V>(p, *k.texture, dx, dy, f.depth);
    if constexpr (V::kShader == ShaderKind::Texture) {
        f.textured = true;
        f.lod = lod;
        describeTexels<V>(*k.texture, f.uv, lod, f);
    }
    f.shaded = fragmentColor<V>(a, k, lod);
    f.rgba = packColor(f.shaded);
    if (f.passed) storeFragment<V::kShader>(s.fb, 0, f.depth, f.shaded);
}

/// The front end's emit for the inspector: one record per sample of the pixel inside the
/// piece's pixel box, shaded when covered. Returns the fragments, as a pixel loop does.
template <class V>
std::size_t probeTriangle(void* context, const CoverageSetup& setup, const Planes& planes) {
    Probe& pr = *static_cast<Probe*>(context);
    const int piece = pr.piece++;
    std::size_t fragments = 0;
    for (std::size_t si = 0; si < pr.samples->size(); ++si) {
        SamplePixel& s = (*pr.samples)[si];
        const CoverageSetup one = restrictSetup(setup, {s.x, s.y, s.x, s.y});
        if (one.box.empty()) continue;
        InspectedFragment f;
        f.triangle = pr.triangle;
        f.sample = static_cast<int>(si);
        f.piece = piece;
        f.clipped = piece > 0;
        describeVertices(pr, f);
        describeEdges(one, f);
        bool covered = false;
        forEachCovered(one, [&](int, int) { covered = true; });
        if (covered) {
            ++fragments;
            f.coverage = CoverageResult::Covered;
            shadeFragment<V>(pr, planes, s, f);
        } else {
            const bool noneOutside =
                std::all_of(std::begin(f.edges), std::end(f.edges),
                            [](const InspectedEdge& e) { return e.value >= 0; });
            f.onEdge = noneOutside;  // some E = 0 on an edge that is not top-left
        }
        pr.out->push_back(std::move(f));
    }
    return fragments;
}

/// The reference path's value of pixel (x, y), from a window of the frame just wide enough
/// that a Subdivided span starts where the frame's does.
void addReference(const Scene& scene, const RenderSettings& settings, PixelHistory& h) {
    RenderSettings s = settings;
    s.showNormals = false;
    s.depthLegend = false;
    int x0 = h.x;
    if (s.interp == Interp::Subdivided) {
        const int n = std::clamp(s.subdivision, kMinSubdivision, kMaxSubdivision);
        x0 = h.x / n * n;
    }
    const Result<reference::Image> window =
        reference::renderWindow(scene, s, {x0, h.y, h.x - x0 + 1, 1});
    if (!window) {
        h.notes.push_back("no reference value: " + window.error().message);
        return;
    }
    const reference::Image& ref = *window;
    const auto i = static_cast<std::size_t>(h.x - x0);
    h.hasReference = true;
    h.referenceColor = ref.color[i];
    h.referenceRgba = ref.toRgba()[i];
    h.referenceDepth = ref.depth[i];
    h.referenceAmbiguous = ref.ambiguous[i] != 0;
    if (settings.shader == ShaderKind::Depth)
        h.notes.emplace_back(
            "Depth shader: the reference colour maps only this pixel's depth, so "
            "compare the depths");
    if (settings.supersample > 1)
        h.notes.emplace_back("the reference samples the pixel centre once (no supersampling)");
}

}  // namespace

const char* vertexName(int vertex) {
    static const char* kNames[3] = {"v0", "v1", "v2"};
    return vertex >= 0 && vertex < 3 ? kNames[vertex] : "cut";
}

PixelHistory inspectPixel(const Scene& scene, const RenderSettings& settings, int x, int y) {
    PixelHistory h;
    h.x = x;
    h.y = y;
    h.background = rgbaFromHex(settings.background);
    h.finalColor = h.background;
    h.finalDepth = kEmptyDepth;
    const Camera& camera = scene.camera;
    if (x < 0 || y < 0 || x >= camera.width || y >= camera.height) {
        h.notes.emplace_back("the pixel is outside the image");
        return h;
    }
    if (Status st = checkFrame(camera, settings); !st) {
        h.notes.push_back("nothing is drawn: " + st.error().what());
        return h;
    }
    if (settings.mode != DrawMode::Solid) {
        h.notes.emplace_back("only Solid mode is inspected: lines and points are not listed");
        return h;
    }
    if (msaaSamples(settings.msaa) > 1) {
        // Its coverage is per sample, its shading point can move to the centroid: a history
        // of the pixel centre alone would not explain the resolved colour.
        h.notes.emplace_back(
            "multisampled frames are not inspected: inspect with --msaa 1 (the same triangles "
            "and shading at the pixel centre)");
        return h;
    }
    if (settings.showNormals || settings.depthLegend)
        h.notes.emplace_back(
            "overlays drawn after the triangles (normals, legend) are not part of "
            "the history");

    // Supersampled, the frame is drawn at n times the size: the pixel is n×n samples of it.
    const int n = std::clamp(settings.supersample, 1, kMaxSupersample);
    h.samples = n;
    const Camera drawn =
        n == 1 ? camera : resizedCamera(camera, camera.width * n, camera.height * n);
    std::vector<SamplePixel> samples;
    for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
            SamplePixel s{x * n + sx, y * n + sy, {}};
            s.fb.resize(1, 1);
            s.fb.clear(h.background);
            samples.push_back(std::move(s));
        }

    VertexStage stage;
    std::span<const glm::vec3> normals;
    const DrawInput input = prepareDrawInput(stage, scene, drawn, settings, 1, normals);
    const VariantKey key = variantKey(settings, input);
    const DrawConstants constants{input.texture ? input.texture : &whiteTexture(), input.lighting,
                                  input.eye, glm::vec3(1.0f)};
    const int bits = clampedSubPixelBits(settings);
    const SnapGrid grid = SnapGrid::ofBits(bits);
    Probe probe{&input,
                scene.mesh.get(),
                &constants,
                &grid,
                std::clamp(settings.subdivision, kMinSubdivision, kMaxSubdivision),
                0,
                0,
                &samples,
                &h.fragments};
    dispatch(key, [&](auto variant) {
        using V = decltype(variant);
        RenderStats stats;
        const std::size_t triangles = input.indices.size() / 3;
        for (std::size_t t = 0; t < triangles; ++t) {
            probe.triangle = t;
            probe.piece = 0;
            drawTriangles(input, V::kLayout, settings.cullBackFaces, drawn.width, drawn.height, t,
                          t + 1, &probeTriangle<V>, &probe, stats, bits);
        }
    });

    if (settings.shader == ShaderKind::Depth) {
        // Its colours map the whole frame's visible depth range: the one value a pixel cannot
        // know alone, so a frame is rendered for it.
        RenderSettings s = settings;
        s.showNormals = false;
        s.depthLegend = false;
        Renderer renderer;
        Framebuffer frame;
        // A camera render() refuses has drawn nothing above either: the range stays empty.
        if (const Result<RenderStats> stats = renderer.render(scene, s, frame)) {
            h.depthNear = stats.value().depthNear;
            h.depthFar = stats.value().depthFar;
        }
        for (SamplePixel& s2 : samples)
            if (s2.fb.depth[0] != kEmptyDepth)
                s2.fb.color[0] = depthColor(s2.fb.depth[0], h.depthNear, h.depthFar);
    }
    RgbaSum sum;
    for (const SamplePixel& s : samples) {
        sum.add(s.fb.color[0]);
        h.finalDepth = std::min(h.finalDepth, s.fb.depth[0]);
    }
    h.finalColor = n == 1 ? samples[0].fb.color[0] : sum.mean(static_cast<std::uint32_t>(n * n));
    addReference(scene, settings, h);
    return h;
}

}  // namespace facet
