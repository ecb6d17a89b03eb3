// The span loop on every SIMD target compiled into the engine that this CPU has (forced one at a
// time through Highway), against the scalar loop: the images must be equal bit for bit, colour
// and depth, for every variant with a span loop, on the course scenes, Spot and the bunny.

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include "facet/render.hpp"
#include "pipeline/span_targets.hpp"
#include "scene_cases.hpp"

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

TEST_P(SimdTargets, EveryTargetGivesTheScalarImage) {
    std::string error;
    const Scene* scene = loadCached(GetParam(), error);
    ASSERT_NE(scene, nullptr) << error;
    const std::vector<std::int64_t> targets = runnableTargets();
    // At least the portable fallback; on x86-64 also SSE4 on any CPU of the last 15 years.
    ASSERT_FALSE(targets.empty());
    for (const SceneCase& c : settingsCases(GetParam())) {
        const RenderSettings settings = settingsFor(c);
        Renderer renderer;
        Framebuffer scalar;
        detail::enableSpanLoops(false);
        const RenderStats expected = renderer.render(*scene, settings, scalar);
        detail::enableSpanLoops(true);
        ASSERT_GT(expected.fragments, 0u) << caseName(c);
        for (const std::int64_t target : targets) {
            hwy::SetSupportedTargetsForTest(target);
            ASSERT_STREQ(detail::spanTarget(), hwy::TargetName(target));
            Framebuffer vector;
            const RenderStats actual = renderer.render(*scene, settings, vector);
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
