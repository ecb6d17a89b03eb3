// The threaded engine: the image must not depend on the thread count (tiles are rasterized in
// submission order), tile borders must neither drop nor double pixels, and a steady frame must
// allocate nothing (counted by replacing the global operator new in this test binary).

#include <atomic>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "facet/advanced/draw.hpp"
#include "facet/camera.hpp"
#include "facet/procedural.hpp"
#include "facet/render.hpp"
#include "scene_cases.hpp"
#include "test_scenes.hpp"

namespace {

std::atomic<std::size_t> gAllocations{0};

}  // namespace

// Every C++ allocation of the process passes here, the engine's vectors included. GCC cannot see
// that the deletes below pair with this malloc.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
    gAllocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}

namespace facet::test {
namespace {

struct ThreadCase {
    SceneCase scene;
    int threads;
};

std::string threadCaseName(const testing::TestParamInfo<ThreadCase>& info) {
    return caseName(info.param.scene) + "_t" + std::to_string(info.param.threads);
}

class ThreadCount : public testing::TestWithParam<ThreadCase> {};

// Every thread count gives the one-thread image bit for bit, colour and depth, and the same
// counters.
TEST_P(ThreadCount, GivesTheOneThreadImage) {
    const ThreadCase& c = GetParam();
    REQUIRE_SHARED_SCENE(scene, c.scene.scene);
    RenderSettings settings = settingsFor(c.scene);
    settings.threads = 1;
    Renderer one, many;
    Framebuffer expected, actual;
    const RenderStats a = one.render(*scene, settings, expected).value();
    settings.threads = c.threads;
    const RenderStats b = many.render(*scene, settings, actual).value();
    ASSERT_GT(a.fragments, 0u);
    EXPECT_EQ(a.fragments, b.fragments);
    EXPECT_EQ(a.trianglesRasterized, b.trianglesRasterized);
    EXPECT_EQ(a.trianglesCulled, b.trianglesCulled);
    EXPECT_EQ(a.trianglesClipped, b.trianglesClipped);
    std::size_t colorDiffs = 0, depthDiffs = 0;
    for (std::size_t i = 0; i < expected.color.size(); ++i) {
        colorDiffs += expected.color[i] != actual.color[i] ? 1 : 0;
        depthDiffs += expected.depth[i] != actual.depth[i] ? 1 : 0;
    }
    EXPECT_EQ(colorDiffs, 0u);
    EXPECT_EQ(depthDiffs, 0u);
}

std::vector<ThreadCase> threadCases() {
    std::vector<ThreadCase> cases;
    const SceneCase scenes[] = {
        {.scene = "scenes/bunny_1280x720", .lighting = Lighting::Phong},
        {.scene = "scenes/spot_1280x720", .shader = ShaderKind::Texture, .combine = true},
        {.scene = "course/example2", .shader = ShaderKind::Depth, .interp = Interp::Affine},
        {.scene = "course/example_textured",
         .shader = ShaderKind::Texture,
         .interp = Interp::Subdivided,
         .filter = TextureFilter::Trilinear},
        {.scene = "scenes/spot_1280x720",
         .lighting = Lighting::Gouraud,
         .cull = true,
         .dolly = 0.3},
    };
    for (const SceneCase& s : scenes)
        for (const int t : {2, 3, 7}) cases.push_back({s, t});
    return cases;
}

INSTANTIATE_TEST_SUITE_P(Scenes, ThreadCount, testing::ValuesIn(threadCases()), threadCaseName);

// A closed mesh covers every pixel inside its silhouette exactly twice (front and back), whatever
// the tiling: pixels on tile borders are neither lost nor drawn twice by neighbouring tiles.
TEST(Tiles, BordersNeitherDropNorDoublePixels) {
    // 301×197: not a multiple of the tile size.
    const Scene scene = test::sceneOf(
        makeUvSphere(48, 96), test::lookAt({0.0, 0.0, 3.0}, {0.0, 0.0, 0.0}, 260.0, 301, 197));
    Renderer renderer;
    RenderSettings settings;
    settings.threads = 2;
    const std::vector<glm::vec4> clip = clipPositions(scene.camera, scene.mesh->positions);
    const DrawInput input{.clip = clip, .indices = scene.mesh->indices, .nearPlane = 1e-3f};
    std::vector<std::uint16_t> counts;
    facet::countCoverage(renderer, input, settings, scene.camera.width, scene.camera.height,
                         counts);
    std::size_t inside = 0, wrong = 0;
    for (const std::uint16_t n : counts) {
        inside += n > 0 ? 1 : 0;
        wrong += (n != 0 && n != 2) ? 1 : 0;
    }
    EXPECT_GT(inside, 10000u);
    EXPECT_EQ(wrong, 0u);
}

// The shaded draw clears each tile itself, right before its first triangles, instead of the frame
// being cleared first: a frame holding garbage (the last frame's picture, say) must come out as
// a cleared one would, every tile included, those no triangle reaches and those of an empty
// mesh too, at 1 and 2 threads.
TEST(Tiles, ClearEveryPixelWhenDrawingOverAnOldFrame) {
    Scene scene;
    scene.mesh = std::make_shared<const facet::Mesh>(makeUvSphere(24, 48));
    scene.camera.eye = {0.0, 0.0, 3.0};
    scene.camera.look = {0.0, 0.0, 0.0};
    scene.camera.up = {0.0, -1.0, 0.0};
    scene.camera.width = 301;  // the sphere in the middle: tiles at the sides hold no triangle
    scene.camera.height = 197;
    scene.camera.focal = 120.0;
    for (const int threads : {1, 2})
        for (const ShaderKind shader : {ShaderKind::Painter, ShaderKind::Simple}) {
            RenderSettings settings;
            settings.threads = threads;
            settings.shader = shader;
            Renderer renderer;
            Framebuffer clean, reused;
            ASSERT_TRUE(renderer.render(scene, settings, clean));
            reused.resize(scene.camera.width, scene.camera.height);
            for (std::size_t i = 0; i < reused.color.size(); ++i) {
                reused.color[i] = 0x12345678u;
                reused.depth[i] = -1.0f;  // nearer than anything: no fragment would pass
            }
            ASSERT_TRUE(renderer.render(scene, settings, reused));
            EXPECT_TRUE(reused.color == clean.color) << threads << " threads";
            EXPECT_TRUE(reused.depth == clean.depth) << threads << " threads";

            Scene empty = scene;  // no triangle at all: still every pixel cleared
            empty.mesh = std::make_shared<const facet::Mesh>();
            for (std::size_t i = 0; i < reused.color.size(); ++i) reused.color[i] = 0x12345678u;
            ASSERT_TRUE(renderer.render(empty, settings, reused));
            std::size_t wrong = 0;
            for (const std::uint32_t c : reused.color) wrong += c == 0x12345678u ? 1 : 0;
            EXPECT_EQ(wrong, 0u) << threads << " threads, empty mesh";
        }
}

// After the first frame, frames of the same size allocate nothing: the engine keeps its scratch
// buffers, bins and records. Counted for every shader family and thread count.
TEST(Allocation, NoneAfterTheFirstFrame) {
    REQUIRE_SHARED_SCENE(bunny, "scenes/bunny_1280x720");
    REQUIRE_SHARED_SCENE(spot, "scenes/spot_1280x720");
    struct Run {
        const Scene* scene;
        RenderSettings settings;
    };
    std::vector<Run> runs;
    for (const int threads : {1, 2}) {
        RenderSettings s;
        s.threads = threads;
        runs.push_back({bunny, s});
        s.lighting = Lighting::Gouraud;
        runs.push_back({bunny, s});
        s.lighting = Lighting::Phong;
        s.showNormals = true;
        runs.push_back({spot, s});
        s.showNormals = false;
        s.shader = ShaderKind::Texture;
        s.filter = TextureFilter::Trilinear;
        runs.push_back({spot, s});
        s.shader = ShaderKind::Depth;
        s.depthLegend = true;
        runs.push_back({spot, s});
        s.mode = DrawMode::Wireframe;
        runs.push_back({bunny, s});
    }
    for (const Run& run : runs) {
        Renderer renderer;
        Framebuffer frame;
        renderer.render(*run.scene, run.settings, frame);
        renderer.render(*run.scene, run.settings, frame);
        const std::size_t before = gAllocations.load();
        for (int i = 0; i < 3; ++i) renderer.render(*run.scene, run.settings, frame);
        EXPECT_EQ(gAllocations.load() - before, 0u)
            << toString(run.settings.shader) << " " << toString(run.settings.lighting) << " "
            << toString(run.settings.mode) << " threads " << run.settings.threads;
    }
}

}  // namespace
}  // namespace facet::test
