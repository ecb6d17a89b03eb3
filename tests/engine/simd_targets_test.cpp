// The vector loops (span and block) on every SIMD target compiled into the engine that this CPU
// has (forced one at a time through Highway), against the scalar loop: the images must be equal
// bit for bit, colour and depth, for every variant with vector loops, on the course scenes, Spot,
// the bunny and a sphere of small triangles drawn twice (depth ties); and the block loop alone
// must cover exactly forEachCovered()'s pixels of random small triangles. The same for the
// multisampled span loop against the scalar multisampled loop, sample by sample, on those scenes
// and on a plane of triangles sharing every edge, drawn twice (depth ties).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <hwy/targets.h>
#include <glm/geometric.hpp>

#include "coverage/coverage.hpp"
#include "facet/advanced/draw.hpp"
#include "facet/camera.hpp"
#include "facet/multisample.hpp"
#include "facet/procedural.hpp"
#include "facet/render.hpp"
#include "pipeline/span_targets.hpp"
#include "scene_cases.hpp"
#include "shading/fragment.hpp"
#include "shading/span_loop.hpp"
#include "test_scenes.hpp"
#include "world_at.hpp"

namespace facet::test {
namespace {

/// The settings that reach the span loop (affine or perspective, no derivatives) and the two
/// that do not (trilinear, subdivided), which must not change either.
std::vector<SceneCase> settingsCases(const std::string& scene) {
    using S = ShaderKind;
    using I = Interp;
    using L = Lighting;
    using F = TextureFilter;
    return {
        {scene, DrawMode::Solid, S::Painter, I::Perspective},
        {scene, DrawMode::Solid, S::Painter, I::Affine},
        {scene, DrawMode::Solid, S::Simple, I::Perspective},
        {scene, DrawMode::Solid, S::Painter, I::Perspective, L::Gouraud},
        {scene, DrawMode::Solid, S::Painter, I::Perspective, L::Phong},
        {scene, DrawMode::Solid, S::Painter, I::Affine, L::Phong},
        {scene, DrawMode::Solid, S::Depth, I::Perspective},
        {scene, DrawMode::Solid, S::Texture, I::Perspective, L::Off, F::Nearest},
        {scene, DrawMode::Solid, S::Texture, I::Perspective, L::Off, F::Bilinear},
        {scene, DrawMode::Solid, S::Texture, I::Affine, L::Off, F::Bilinear},
        {scene, DrawMode::Solid, S::Texture, I::Perspective, L::Off, F::Trilinear},
        {scene, DrawMode::Solid, S::Texture, I::Perspective, L::Phong, F::Bilinear, true},
        {scene, DrawMode::Solid, S::Texture, I::Perspective, L::Gouraud, F::Nearest, true},
        {scene, DrawMode::Solid, S::Painter, I::Subdivided, L::Gouraud},
    };
}

/// The compiled targets this CPU supports, each a single HWY_* bit.
std::vector<std::int64_t> runnableTargets() {
    hwy::SetSupportedTargetsForTest(0);
    const std::int64_t both = detail::spanTargetsCompiled() & hwy::SupportedTargets();
    std::vector<std::int64_t> out;
    for (std::int64_t rest = both; rest != 0; rest &= rest - 1) out.push_back(rest & -rest);
    return out;
}

/// Samples (or pixels) where two framebuffers differ, colour and depth (bitwise: the cleared
/// depth is +inf and must stay so).
struct Diffs {
    std::size_t color = 0, depth = 0;
};
Diffs differences(const Framebuffer& a, const Framebuffer& b) {
    Diffs n;
    EXPECT_EQ(a.color.size(), b.color.size());
    for (std::size_t i = 0; i < a.color.size() && i < b.color.size(); ++i) {
        n.color += a.color[i] != b.color[i] ? 1 : 0;
        n.depth += std::memcmp(&a.depth[i], &b.depth[i], sizeof(float)) != 0;
    }
    return n;
}

/// The multisampled span loop exists for this target (else the comparisons would compare the
/// scalar loop with itself).
void expectMsaaSpanLoop() {
    detail::VariantKey key{
        ShaderKind::Painter, Interp::Perspective, {}, TextureFilter::Nearest, false};
    key.layout.color = true;
    EXPECT_NE(detail::msaaSpanLoop(key), nullptr) << detail::spanTarget();
}

/// Renders `scene` at every sample count with the scalar loops, then on every target, and
/// expects the same per-sample buffer (every sample's colour and depth) and resolved frame.
void expectEveryTargetGivesTheScalarSamples(const Scene& scene, const RenderSettings& base,
                                            const std::string& what) {
    Renderer renderer;
    for (const int n : kMsaaCounts) {
        RenderSettings settings = base;
        settings.msaa = n;
        const std::string name = what + " msaa" + std::to_string(n);
        Framebuffer scalarFrame;
        detail::enableSpanLoops(false);
        const RenderStats expected = renderer.render(scene, settings, scalarFrame).value();
        const Framebuffer scalarSamples = facet::sampleBuffer(renderer);
        detail::enableSpanLoops(true);
        ASSERT_GT(expected.fragments, 0u) << name;
        ASSERT_EQ(scalarSamples.color.size(), scalarFrame.color.size() * static_cast<unsigned>(n))
            << name;
        for (const std::int64_t target : runnableTargets()) {
            hwy::SetSupportedTargetsForTest(target);
            ASSERT_STREQ(detail::spanTarget(), hwy::TargetName(target));
            expectMsaaSpanLoop();
            Framebuffer frame;
            const RenderStats actual = renderer.render(scene, settings, frame).value();
            EXPECT_EQ(actual.fragments, expected.fragments) << name;
            const Diffs samples = differences(scalarSamples, facet::sampleBuffer(renderer));
            const Diffs pixels = differences(scalarFrame, frame);
            const char* on = hwy::TargetName(target);
            EXPECT_EQ(samples.color, 0u) << name << " sample colours on " << on;
            EXPECT_EQ(samples.depth, 0u) << name << " sample depths on " << on;
            EXPECT_EQ(pixels.color, 0u) << name << " resolved colours on " << on;
            EXPECT_EQ(pixels.depth, 0u) << name << " resolved depths on " << on;
        }
        hwy::SetSupportedTargetsForTest(0);
    }
}

class SimdTargets : public testing::TestWithParam<std::string> {
  protected:
    void TearDown() override {
        detail::enableSpanLoops(true);
        hwy::SetSupportedTargetsForTest(0);
    }
};

/// Renders `scene` with every settings case, scalar loop first, then on every target: the
/// fragment counts, colours and depths must be equal.
void expectEveryTargetGivesTheScalarImage(const Scene& scene, const std::string& name) {
    const std::vector<std::int64_t> targets = runnableTargets();
    // At least the portable fallback; on x86-64 also SSE4 on any CPU of the last 15 years.
    ASSERT_FALSE(targets.empty());
    for (const SceneCase& c : settingsCases(name)) {
        const RenderSettings settings = settingsFor(c);
        Renderer renderer;
        Framebuffer scalar;
        detail::enableSpanLoops(false);
        const RenderStats expected = renderer.render(scene, settings, scalar).value();
        detail::enableSpanLoops(true);
        ASSERT_GT(expected.fragments, 0u) << caseName(c);
        for (const std::int64_t target : targets) {
            hwy::SetSupportedTargetsForTest(target);
            ASSERT_STREQ(detail::spanTarget(), hwy::TargetName(target));
            Framebuffer vector;
            const RenderStats actual = renderer.render(scene, settings, vector).value();
            EXPECT_EQ(actual.fragments, expected.fragments) << caseName(c);
            std::size_t colorDiffs = 0, depthDiffs = 0;
            for (std::size_t i = 0; i < scalar.color.size(); ++i) {
                colorDiffs += scalar.color[i] != vector.color[i] ? 1 : 0;
                // Bitwise: the cleared depth is +inf and must stay so.
                depthDiffs += std::memcmp(&scalar.depth[i], &vector.depth[i], sizeof(float)) != 0;
            }
            EXPECT_EQ(colorDiffs, 0u) << caseName(c) << " on " << hwy::TargetName(target);
            EXPECT_EQ(depthDiffs, 0u) << caseName(c) << " on " << hwy::TargetName(target);
        }
        hwy::SetSupportedTargetsForTest(0);
    }
}

// Multisampling on the same scenes at a smaller size (four to eight times the samples), with
// the settings whose variants have a multisampled span loop: vertex colours, both lightings,
// depth, the vector bilinear texel and the lane-by-lane texture shading.
TEST_P(SimdTargets, EveryTargetGivesTheScalarSamples) {
    REQUIRE_SHARED_SCENE(loaded, GetParam());
    Scene scene = *loaded;
    scene.camera = resizedCamera(scene.camera, 320, 180);
    for (const SceneCase& c : settingsCases(GetParam())) {
        if (c.interp == Interp::Subdivided || c.filter == TextureFilter::Trilinear) continue;
        expectEveryTargetGivesTheScalarSamples(scene, settingsFor(c), caseName(c));
    }
}

class SimdTargetsMsaa : public testing::Test {
  protected:
    void TearDown() override {
        detail::enableSpanLoops(true);
        hwy::SetSupportedTargetsForTest(0);
    }
};

/// A plane of triangles sharing every edge, inner vertices jittered, wider than the image (every
/// sample covered), cells wide enough (about 30 px) for the span loop, tilted in depth; then
/// the same triangles again in other colours, `copies` times: exact depth ties.
Scene jitteredPlane(int copies) {
    const int w = 200, h = 120, cols = 7, rows = 4;
    Scene scene;
    scene.camera.width = w;
    scene.camera.height = h;
    scene.camera.focal = 150.0;
    Mesh mesh;
    const std::vector<glm::vec3> grid =
        jitteredGrid(scene.camera, cols, rows, 3.0, 9.3, 2024u,
                     [](int i, int j) { return 2.0 + 0.15 * i + 0.1 * j; });
    for (int copy = 0; copy <= copies; ++copy) {
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (std::size_t v = 0; v < grid.size(); ++v) {
            mesh.positions.push_back(grid[v]);
            mesh.colors.emplace_back(static_cast<float>(v % 5) / 4.0f,
                                     static_cast<float>(v % 3) / 2.0f,
                                     static_cast<float>(copy) / static_cast<float>(copies + 1));
        }
        appendGridTriangles(mesh.indices, cols, rows, base);
    }
    scene.mesh = std::make_shared<const Mesh>(std::move(mesh));
    return scene;
}

// Shared edges (every sample covered once: the plane alone leaves no background sample) and
// depth ties (drawn again, the plane keeps its first colours under the depth test; without it
// the last copy's), on every target, sample for sample against the scalar loop.
TEST_F(SimdTargetsMsaa, SharedEdgesAndDepthTiesGiveTheScalarSamples) {
    const Scene once = jitteredPlane(0), thrice = jitteredPlane(2);
    for (const ShaderKind shader : {ShaderKind::Painter, ShaderKind::Simple}) {
        for (const Interp interp : {Interp::Perspective, Interp::Affine}) {
            RenderSettings s;
            s.shader = shader;
            s.interp = interp;
            s.background = 0xFF00FF;  // no vertex colour is magenta
            std::string what(toString(shader));
            what += ' ';
            what += toString(interp);
            expectEveryTargetGivesTheScalarSamples(once, s, what + " plane");
            expectEveryTargetGivesTheScalarSamples(thrice, s, what + " plane thrice");
            // With the depth test, on the best target: every sample covered (written), and the
            // ties keep the first copy.
            if (shader != ShaderKind::Painter) continue;
            for (const int n : kMsaaCounts) {
                s.msaa = n;
                Renderer renderer;
                Framebuffer frame;
                renderer.render(once, s, frame);
                const Framebuffer plane = facet::sampleBuffer(renderer);
                std::size_t background = 0;
                for (const float z : plane.depth) background += std::isinf(z) ? 1 : 0;
                EXPECT_EQ(background, 0u) << what << " msaa" << n;
                renderer.render(thrice, s, frame);
                const Diffs d = differences(plane, facet::sampleBuffer(renderer));
                EXPECT_EQ(d.color, 0u) << what << " msaa" << n;
                EXPECT_EQ(d.depth, 0u) << what << " msaa" << n;
            }
        }
    }
}

TEST_P(SimdTargets, EveryTargetGivesTheScalarImage) {
    REQUIRE_SHARED_SCENE(scene, GetParam());
    expectEveryTargetGivesTheScalarImage(*scene, GetParam());
}

/// A sphere of small triangles (3 to 6 px: the block loop's) in a frame whose size is no multiple
/// of the tile size, so tile edges cut triangles; drawn twice, the second copy with other
/// colours and uvs at the very same depths: every pixel of it is a depth tie, which LESS rejects,
/// so a loop that let a tie through would show the second copy's colour.
Scene smallTriangleScene(const Scene& textured) {
    Mesh sphere = makeUvSphere(48, 96);
    const std::size_t n = sphere.positions.size();
    Mesh twice = sphere;
    for (std::size_t i = 0; i < n; ++i) {
        twice.positions.push_back(sphere.positions[i]);
        twice.colors.push_back(glm::vec3(1.0f) - sphere.colors[i]);
        twice.uvs.push_back(glm::vec2(1.0f) - sphere.uvs[i]);
    }
    for (const std::uint32_t i : sphere.indices)
        twice.indices.push_back(i + static_cast<std::uint32_t>(n));
    Scene scene = test::sceneOf(std::move(twice),
                                test::lookAt({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}, 260.0, 301, 197));
    scene.texture = textured.texture;
    scene.lighting = textured.lighting;
    return scene;
}

TEST(SimdTargetsSmallTriangles, EveryTargetGivesTheScalarImage) {
    REQUIRE_SHARED_SCENE(textured, "course/example_textured");
    ASSERT_NE(textured->texture, nullptr);
    expectEveryTargetGivesTheScalarImage(smallTriangleScene(*textured), "small_triangles");
}

/// Phong's lane shortcuts against the scalar loop: a flat grid whose vertex normals are tiny
/// (|n|² interpolates to subnormal values, which rsqrtLanes() scales on its slow path), exactly
/// opposed (|n| passes through zero) or unit and turned away from the light (whole vectors where
/// no lane faces it, whose halfway vector and power lightLanes() skips), next to lit unit ones.
Scene phongShortcutScene() {
    Mesh grid;
    constexpr int kSide = 12;
    for (int y = 0; y <= kSide; ++y)
        for (int x = 0; x <= kSide; ++x) {
            grid.positions.emplace_back(static_cast<float>(x - kSide / 2),
                                        static_cast<float>(y - kSide / 2), 0.0f);
            const float tiny = 1e-21f;
            const glm::vec3 normals[4] = {
                {0.0f, 0.0f, (x + y) % 2 ? tiny : -tiny},
                {x % 2 ? 1.0f : -1.0f, 0.0f, 0.0f},
                {0.0f, 0.0f, -1.0f},
                glm::normalize(
                    glm::vec3(static_cast<float>(x - 6), static_cast<float>(y - 6), 4.0f))};
            grid.normals.push_back(normals[(x / 3 + y / 3) % 4]);
        }
    for (int y = 0; y < kSide; ++y)
        for (int x = 0; x < kSide; ++x) {
            const auto at = [](int i, int j) { return static_cast<std::uint32_t>(j * 13 + i); };
            grid.indices.insert(grid.indices.end(), {at(x, y), at(x + 1, y), at(x + 1, y + 1),
                                                     at(x, y), at(x + 1, y + 1), at(x, y + 1)});
        }
    Scene scene = test::sceneOf(std::move(grid),
                                test::lookAt({1.0, 2.0, 14.0}, {0.0, 0.0, 0.0}, 90.0, 131, 93));
    scene.lighting.light.position = {2.0, -3.0, 5.0, 1.0};
    scene.lighting.material = Material{0.2, 0.6, 0.8, 20.0};
    return scene;
}

TEST(SimdTargetsPhong, TinyOpposedAndUnlitNormalsGiveTheScalarImage) {
    const std::vector<std::int64_t> targets = runnableTargets();
    ASSERT_FALSE(targets.empty());
    const Scene scene = phongShortcutScene();
    for (const Interp interp : {Interp::Perspective, Interp::Affine}) {
        RenderSettings settings;
        settings.shader = ShaderKind::Painter;
        settings.lighting = Lighting::Phong;
        settings.interp = interp;
        Renderer renderer;
        Framebuffer scalar;
        detail::enableSpanLoops(false);
        ASSERT_GT(renderer.render(scene, settings, scalar).value().fragments, 0u);
        detail::enableSpanLoops(true);
        // The shortcuts must be reached: some pixels lit beyond the ambient term, some not.
        std::size_t distinct = 0;
        for (std::size_t i = 1; i < scalar.color.size(); ++i)
            distinct += scalar.color[i] != scalar.color[i - 1] ? 1 : 0;
        EXPECT_GT(distinct, 100u);
        for (const std::int64_t target : targets) {
            hwy::SetSupportedTargetsForTest(target);
            Framebuffer vector;
            ASSERT_TRUE(renderer.render(scene, settings, vector).ok());
            std::size_t diffs = 0;
            for (std::size_t i = 0; i < scalar.color.size(); ++i)
                diffs += scalar.color[i] != vector.color[i] ? 1 : 0;
            EXPECT_EQ(diffs, 0u) << hwy::TargetName(target);
        }
        hwy::SetSupportedTargetsForTest(0);
    }
}

/// The block loop's variants in the direct test: no depth test (every covered pixel is
/// written), and the depth test with constant depth (ties).
using SimpleV = detail::Variant<ShaderKind::Simple, Interp::Affine, false, false, false,
                                TextureFilter::Nearest, false>;
using PainterV = detail::Variant<ShaderKind::Painter, Interp::Perspective, false, false, false,
                                 TextureFilter::Nearest, false>;

/// A random small triangle in grid units with its box restricted to a random rectangle (a
/// tile's edges); vertices often on pixel centres (x·256 + 128) or pixel corners, so that edges
/// pass through centres and the top-left rule decides.
bool randomSmallTriangle(std::mt19937& rng, detail::CoverageSetup& out) {
    std::uniform_int_distribution<int> pixel(2, 30), size(-12, 12), sub(0, 255), kind(0, 2);
    const int bx = pixel(rng), by = pixel(rng);
    std::int64_t xs[3], ys[3];
    for (int v = 0; v < 3; ++v) {
        const auto place = [&](int base) {
            const int k = kind(rng);
            const std::int64_t frac = k == 0 ? 128 : k == 1 ? 0 : sub(rng);
            return std::int64_t{base + (v == 0 ? 0 : size(rng))} * detail::kSubPixel + frac;
        };
        xs[v] = place(bx);
        ys[v] = place(by);
    }
    const detail::PixelRect frame{0, 0, 47, 47};
    if (detail::setupCoverage(xs, ys, frame, out) == detail::Facing::Degenerate) return false;
    if (out.box.empty()) return false;
    std::uniform_int_distribution<int> cut(0, 47);
    const detail::PixelRect tile{cut(rng) / 2, cut(rng) / 2, 24 + cut(rng) / 2, 24 + cut(rng) / 2};
    out = detail::restrictSetup(out, tile);
    return !out.box.empty() && detail::fitsBlockLoop(out);
}

// fitsBlockLoop()'s promise, on values around its short test's limits (2^23 and a box of 254
// columns plus rows, padded): every edge value the block loop forms over the padded box fits in
// 32 bits. A short test too generous (2^24, say) fails here.
TEST(BlockLoop, FitsOnlyWhereEveryLaneValueFitsIn32Bits) {
    std::mt19937 rng(11);
    std::uniform_int_distribution<std::int64_t> near(-(std::int64_t{1} << 24),
                                                     std::int64_t{1} << 24);
    std::uniform_int_distribution<int> side(0, 250);
    int accepted = 0;
    for (int n = 0; n < 20000; ++n) {
        detail::CoverageSetup s{};
        const int scale = n % 4;  // values up to 2^24 >> scale
        for (int i = 0; i < 3; ++i) {
            s.e0[i] = near(rng) >> scale;
            s.stepX[i] = near(rng) >> scale;
            s.stepY[i] = near(rng) >> scale;
        }
        const int w = side(rng);
        s.box = {0, 0, w, std::max(0, 246 - w - side(rng) % 3)};
        if (!detail::fitsBlockLoop(s)) continue;
        ++accepted;
        const std::int64_t columns = s.box.x1 - s.box.x0 + detail::kMaxBlockSide;
        const std::int64_t rows = s.box.y1 - s.box.y0 + detail::kMaxBlockSide;
        for (int i = 0; i < 3; ++i)
            for (const std::int64_t x : {std::int64_t{0}, columns})
                for (const std::int64_t y :
                     {std::int64_t{0}, rows}) {  // a plane: extremes at corners
                    const std::int64_t v = s.e0[i] + x * s.stepX[i] + y * s.stepY[i];
                    ASSERT_LE(v, std::numeric_limits<std::int32_t>::max()) << n;
                    ASSERT_GE(v, std::numeric_limits<std::int32_t>::min()) << n;
                }
    }
    EXPECT_GT(accepted, 1000);
}

TEST(BlockLoop, CoversExactlyTheScalarPixelsOnEveryTarget) {
    const std::vector<std::int64_t> targets = runnableTargets();
    ASSERT_FALSE(targets.empty());
    detail::DrawConstants constants{&detail::whiteTexture(), {}, glm::vec3(0.0f), glm::vec3(1.0f)};
    detail::Planes planes{};
    planes.q[0] = 0.5f;  // depth 2 everywhere, weights 0: every fragment white
    constexpr std::uint32_t kWhite = 0xFFFFFFFFu;
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        const detail::PixelLoopFn simple = detail::blockLoopFor<SimpleV>();
        const detail::PixelLoopFn painter = detail::blockLoopFor<PainterV>();
        ASSERT_NE(simple, nullptr);
        ASSERT_NE(painter, nullptr);
        std::mt19937 rng(7);
        int tested = 0, edgeCentres = 0;
        while (tested < 3000) {
            detail::CoverageSetup setup{};
            if (!randomSmallTriangle(rng, setup)) continue;
            ++tested;
            Framebuffer fb;
            fb.resize(48, 48);
            fb.clear(0u);
            std::vector<char> covered(fb.color.size(), 0);
            std::size_t count = 0;
            detail::forEachCovered(setup, [&](int x, int y) {
                covered[fb.index(x, y)] = 1;
                ++count;
            });
            // Centres exactly on an edge: E = 0 on a top-left edge, −1 (the bias) on another.
            for (int y = setup.box.y0; y <= setup.box.y1; ++y)
                for (int x = setup.box.x0; x <= setup.box.x1; ++x)
                    for (int i = 0; i < 3; ++i) {
                        const std::int64_t e = setup.e0[i] + (x - setup.box.x0) * setup.stepX[i] +
                                               (y - setup.box.y0) * setup.stepY[i];
                        edgeCentres += e == 0 || e == -1 ? 1 : 0;
                    }
            detail::RasterContext ctx{&fb, &constants, 16, nullptr, nullptr};
            ASSERT_EQ(simple(ctx, setup, planes, detail::PixelTarget::frame(fb)), count)
                << hwy::TargetName(target);
            std::size_t wrong = 0;
            for (std::size_t i = 0; i < covered.size(); ++i)
                wrong += (fb.color[i] == kWhite) != (covered[i] != 0) ? 1 : 0;
            ASSERT_EQ(wrong, 0u) << "simple, triangle " << tested << " on "
                                 << hwy::TargetName(target);

            // Depth 2 against a checkerboard of 2 (a tie: LESS fails) and 3 (passes).
            fb.clear(0u);
            for (int y = 0; y < fb.height; ++y)
                for (int x = 0; x < fb.width; ++x)
                    fb.depth[fb.index(x, y)] = (x + y) % 2 == 0 ? 2.0f : 3.0f;
            ASSERT_EQ(painter(ctx, setup, planes, detail::PixelTarget::frame(fb)), count)
                << hwy::TargetName(target);
            for (int y = 0; y < fb.height; ++y)
                for (int x = 0; x < fb.width; ++x) {
                    const std::size_t i = fb.index(x, y);
                    const bool written = covered[i] != 0 && (x + y) % 2 == 1;
                    wrong += (fb.color[i] == kWhite) != written ? 1 : 0;
                    wrong += fb.depth[i] != ((x + y) % 2 == 0 || written ? 2.0f : 3.0f) ? 1 : 0;
                }
            ASSERT_EQ(wrong, 0u) << "painter, triangle " << tested << " on "
                                 << hwy::TargetName(target);
        }
        // The random triangles must reach the top-left rule often, or the test proves little.
        EXPECT_GT(edgeCentres, 1000) << hwy::TargetName(target);
    }
    hwy::SetSupportedTargetsForTest(0);
}

// The fallback and the best target must both be among those run: the test would otherwise pass
// having compared nothing.
TEST(SimdTargetsList, IncludesTheFallbackAndTheBest) {
    const std::vector<std::int64_t> targets = runnableTargets();
    ASSERT_GE(targets.size(), 1u);
    const std::string best = detail::spanTarget();
    bool sawBest = false;
    std::string names;
    for (const std::int64_t t : targets) {
        sawBest = sawBest || best == hwy::TargetName(t);
        names += std::string(" ") + hwy::TargetName(t);
    }
    std::printf("span loop targets run:%s (best: %s)\n", names.c_str(), best.c_str());
    EXPECT_TRUE(sawBest) << best;
    EXPECT_TRUE((targets.back() & (HWY_SCALAR | HWY_EMU128)) != 0)
        << "the last (lowest) target is " << hwy::TargetName(targets.back());
}

std::string sceneName(const testing::TestParamInfo<std::string>& param) {
    std::string name = param.param;
    for (char& ch : name)
        if (ch == '/') ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Scenes, SimdTargets,
                         testing::Values("course/example0", "course/example1", "course/example2",
                                         "course/example_textured", "scenes/spot_1280x720",
                                         "scenes/bunny_1280x720"),
                         sceneName);

}  // namespace
}  // namespace facet::test
