// The vector loops (span and block) on every SIMD target compiled into the engine that this CPU
// has (forced one at a time through Highway), against the scalar loop: the images must be equal
// bit for bit, colour and depth, for every variant with vector loops, on the course scenes, Spot,
// the bunny and a sphere of small triangles drawn twice (depth ties); and the block loop alone
// must cover exactly forEachCovered()'s pixels of random small triangles.

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include "coverage/coverage.hpp"
#include "facet/procedural.hpp"
#include "facet/render.hpp"
#include "pipeline/span_targets.hpp"
#include "scene_cases.hpp"
#include "shading/fragment.hpp"
#include "shading/span_loop.hpp"

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
        const RenderStats expected = renderer.render(scene, settings, scalar);
        detail::enableSpanLoops(true);
        ASSERT_GT(expected.fragments, 0u) << caseName(c);
        for (const std::int64_t target : targets) {
            hwy::SetSupportedTargetsForTest(target);
            ASSERT_STREQ(detail::spanTarget(), hwy::TargetName(target));
            Framebuffer vector;
            const RenderStats actual = renderer.render(scene, settings, vector);
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

TEST_P(SimdTargets, EveryTargetGivesTheScalarImage) {
    std::string error;
    const Scene* scene = loadCached(GetParam(), error);
    ASSERT_NE(scene, nullptr) << error;
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
    Scene scene;
    scene.mesh = std::make_shared<const Mesh>(std::move(twice));
    scene.texture = textured.texture;
    scene.lighting = textured.lighting;
    scene.camera.eye = {0.0, 0.0, 3.0};
    scene.camera.look = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, -1.0, 0.0};
    scene.camera.width = 301;
    scene.camera.height = 197;
    scene.camera.focal = 260.0;
    return scene;
}

TEST(SimdTargetsSmallTriangles, EveryTargetGivesTheScalarImage) {
    std::string error;
    const Scene* textured = loadCached("course/example_textured", error);
    ASSERT_NE(textured, nullptr) << error;
    ASSERT_NE(textured->texture, nullptr);
    expectEveryTargetGivesTheScalarImage(smallTriangleScene(*textured), "small_triangles");
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

TEST(BlockLoop, CoversExactlyTheScalarPixelsOnEveryTarget) {
    const std::vector<std::int64_t> targets = runnableTargets();
    ASSERT_FALSE(targets.empty());
    detail::DrawConstants constants{&detail::whiteTexture(), {}, glm::vec3(0.0f), glm::vec3(1.0f)};
    detail::Planes planes{};
    planes.q[0] = 0.5f;  // depth 2 everywhere, weights 0: every fragment white
    constexpr std::uint32_t kWhite = 0xFFFFFFFFu;
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        const detail::RasterizeFn simple = detail::blockLoopFor<SimpleV>();
        const detail::RasterizeFn painter = detail::blockLoopFor<PainterV>();
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
            ASSERT_EQ(simple(&ctx, setup, planes), count) << hwy::TargetName(target);
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
            ASSERT_EQ(painter(&ctx, setup, planes), count) << hwy::TargetName(target);
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
