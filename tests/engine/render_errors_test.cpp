// The API tells instead of throwing (README, "Errors"): Renderer::render, renderDebugView, draw,
// countCoverage and Framebuffer::resize return an error value for a camera or a size the engine
// refuses, with the message the CLI prints, and leave the frame as it was; nothing throws.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "facet/advanced/draw.hpp"
#include "facet/camera.hpp"
#include "facet/debug_view.hpp"
#include "facet/error.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/limits.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"

using namespace facet;

namespace {

// One triangle in front of the default camera, so a frame that is drawn draws something.
Scene triangleScene() {
    Scene scene;
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    mesh->indices = {0, 1, 2};
    scene.mesh = std::move(mesh);
    scene.camera.width = 64;
    scene.camera.height = 48;
    return scene;
}

// Renders `scene` into a frame holding one 2x2 image first, and returns the error; the frame
// must be untouched.
std::string renderError(const Scene& scene, const RenderSettings& settings = {}) {
    Renderer renderer;
    Framebuffer frame;
    EXPECT_TRUE(frame.resize(2, 2));
    frame.clear(0x12345678u);
    const Result<RenderStats> result = renderer.render(scene, settings, frame);
    EXPECT_FALSE(result) << "rendered " << scene.camera.width << "x" << scene.camera.height;
    EXPECT_EQ(frame.width, 2);
    EXPECT_EQ(frame.height, 2);
    EXPECT_EQ(frame.color[0], 0x12345678u);
    return result ? std::string() : result.error().what();
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST(RenderErrors, NegativeWidthIsAnErrorNotAnException) {
    Scene scene = triangleScene();
    scene.camera.width = -10;
    const std::string e = renderError(scene);
    EXPECT_TRUE(has(e, "image size must be 1..16384")) << e;
    EXPECT_TRUE(has(e, "-10x48")) << e;
}

TEST(RenderErrors, ZeroSizeIsAnErrorNotAnEmptyFrame) {
    Scene scene = triangleScene();
    scene.camera.height = 0;
    const std::string e = renderError(scene);
    EXPECT_TRUE(has(e, "64x0")) << e;
}

TEST(RenderErrors, OverTheSideLimitIsAnError) {
    Scene scene = triangleScene();
    scene.camera.width = kMaxImageSide + 1;
    EXPECT_TRUE(has(renderError(scene), "16385x48"));
}

TEST(RenderErrors, FrameMemoryOverTheLimitIsTheCliMessage) {
    // 16384² at 4x4 supersampling: 34 GiB of buffers, refused before any is allocated.
    Scene scene = triangleScene();
    scene.camera.width = kMaxImageSide;
    scene.camera.height = kMaxImageSide;
    RenderSettings settings;
    settings.supersample = 4;
    const std::string e = renderError(scene, settings);
    EXPECT_EQ(e, *frameMemoryProblem(kMaxImageSide, kMaxImageSide, 4));
    EXPECT_TRUE(has(e, "16384x16384 frame at 4x4 supersampling needs")) << e;
    // MSAA counts too.
    settings.supersample = 1;
    settings.msaa = 8;
    EXPECT_TRUE(has(renderError(scene, settings), "MSAA 8x"));
}

TEST(RenderErrors, NonFiniteOrDegenerateCamerasAreErrors) {
    Scene scene = triangleScene();
    scene.camera.eye.x = std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(has(renderError(scene), "camera: camera vectors must be finite"));
    scene = triangleScene();
    scene.camera.look = scene.camera.eye;
    EXPECT_TRUE(has(renderError(scene), "look-at point equals the camera position"));
    scene = triangleScene();
    scene.camera.up = glm::normalize(scene.camera.look - scene.camera.eye);
    EXPECT_TRUE(has(renderError(scene), "parallel"));
    scene = triangleScene();
    scene.camera.focal = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(has(renderError(scene), "focal length"));
}

TEST(RenderErrors, DebugViewsRefuseTheSame) {
    Scene scene = triangleScene();
    scene.camera.width = -10;
    RenderSettings settings;
    settings.view = DebugView::Overdraw;
    EXPECT_TRUE(has(renderError(scene, settings), "-10x48"));
    Renderer renderer;
    Framebuffer frame;
    DebugMap map;
    EXPECT_FALSE(renderer.renderDebugView(scene, settings, frame, map));
}

TEST(RenderErrors, AValidFrameStillRenders) {
    const Scene scene = triangleScene();
    Renderer renderer;
    Framebuffer frame;
    const Result<RenderStats> result = renderer.render(scene, {}, frame);
    ASSERT_TRUE(result) << result.error().what();
    EXPECT_EQ(frame.width, 64);
    EXPECT_EQ(result.value().trianglesRasterized, 1u);
}

TEST(RenderErrors, DrawAndCountCoverageCheckTheirSizes) {
    Renderer renderer;
    const std::vector<glm::vec4> clip = {{0, 0, 1, 1}, {8, 0, 1, 1}, {0, 8, 1, 1}};
    const std::vector<std::uint32_t> indices = {0, 1, 2};
    const DrawInput input{.clip = clip, .indices = indices};
    Framebuffer empty;
    const Result<RenderStats> none = facet::draw(renderer, input, {}, empty);
    ASSERT_FALSE(none);
    EXPECT_TRUE(has(none.error().what(), "0x0")) << none.error().what();
    // A frame whose planes do not match its size is refused, not overrun.
    Framebuffer lying;
    lying.width = 16;
    lying.height = 16;
    const Result<RenderStats> wrong = facet::draw(renderer, input, {}, lying);
    ASSERT_FALSE(wrong);
    EXPECT_TRUE(has(wrong.error().what(), "Framebuffer::resize")) << wrong.error().what();
    Framebuffer frame;
    ASSERT_TRUE(frame.resize(16, 16));
    frame.clear(0);
    EXPECT_TRUE(facet::draw(renderer, input, {}, frame));

    std::vector<std::uint16_t> counts(3, 7);
    const Status refused = facet::countCoverage(renderer, input, {}, -10, 4, counts);
    ASSERT_FALSE(refused);
    EXPECT_TRUE(has(refused.error().what(), "-10x4"));
    EXPECT_EQ(counts.size(), 3u);  // untouched
    EXPECT_TRUE(facet::countCoverage(renderer, input, {}, 16, 16, counts));
    EXPECT_EQ(counts.size(), 256u);
}

TEST(RenderErrors, FramebufferResizeRefusesWhatItCannotHold) {
    Framebuffer frame;
    const Status negative = frame.resize(-10, 4);
    ASSERT_FALSE(negative);
    EXPECT_TRUE(has(negative.error().what(), "-10x4"));
    const Status huge = frame.resize(1 << 20, 1 << 20);
    ASSERT_FALSE(huge);
    EXPECT_TRUE(has(huge.error().what(), "limit")) << huge.error().what();
    EXPECT_EQ(frame.width, 0);
    EXPECT_TRUE(frame.resize(3, 2));
    EXPECT_EQ(frame.color.size(), 6u);
}

TEST(RenderErrors, StatusTruthMeansSuccess) {
    const Status ok;
    EXPECT_TRUE(ok);
    EXPECT_TRUE(ok.ok());
    const Status failed = Error{{"f.scene", 3}, "bad"};
    EXPECT_FALSE(failed);
    EXPECT_EQ(failed.error().what(), "f.scene:3: bad");
}

// The reference renderer and the ground truth refuse what the fast path refuses, with the same
// message, before allocating: a user comparing against them gets an error value too.
TEST(RenderErrors, TheReferenceAndTheGroundTruthRefuseWhatRenderRefuses) {
    std::vector<Scene> refused;
    for (int width : {-10, 0, kMaxImageSide + 1}) {
        refused.push_back(triangleScene());
        refused.back().camera.width = width;
    }
    refused.push_back(triangleScene());
    refused.back().camera.look = refused.back().camera.eye;  // eye == look
    refused.push_back(triangleScene());
    refused.back().camera.eye.x = std::numeric_limits<double>::quiet_NaN();
    for (const Scene& scene : refused) {
        const std::string fast = renderError(scene);
        const Result<reference::Image> ref = reference::render(scene, RenderSettings{});
        ASSERT_FALSE(ref) << fast;
        EXPECT_EQ(ref.error().what(), fast);
        const Result<reference::Image> samples = reference::renderSamples(scene, RenderSettings{});
        ASSERT_FALSE(samples) << fast;
        EXPECT_EQ(samples.error().what(), fast);
        const Result<GroundTruth> truth = renderGroundTruth(scene, RenderSettings{}, 2);
        ASSERT_FALSE(truth) << fast;
        EXPECT_EQ(truth.error().what(), fast);
        EXPECT_EQ(renderGroundTruthPixel(scene, RenderSettings{}, 0, 0, 2).width, 0);
    }
}

TEST(RenderErrors, TheGroundTruthRefusesAnImageBeyondTheReferencesMemory) {
    Scene scene = triangleScene();
    scene.camera = resizedCamera(scene.camera, kMaxImageSide, kMaxImageSide);
    // 16384² at 16×16 samples would be 2.3 TB of doubles: refused before allocating.
    const Result<GroundTruth> truth = renderGroundTruth(scene, RenderSettings{}, 16);
    ASSERT_FALSE(truth);
    EXPECT_TRUE(has(truth.error().what(), "ground truth at 16x16 samples")) << truth.error().what();
    EXPECT_TRUE(has(truth.error().what(), "the limit is 8")) << truth.error().what();
    // A small frame at the same samples is fine.
    EXPECT_TRUE(renderGroundTruth(triangleScene(), RenderSettings{}, 16));
}

TEST(RenderErrors, AReferenceWindowOutsideTheFrameIsAnError) {
    const Scene scene = triangleScene();
    for (const reference::Window w :
         {reference::Window{0, 0, 0, 1}, reference::Window{-1, 0, 2, 2},
          reference::Window{60, 0, 8, 1}, reference::Window{0, 47, 1, 2}}) {
        const Result<reference::Image> r = reference::renderWindow(scene, RenderSettings{}, w);
        ASSERT_FALSE(r) << w.x << "," << w.y << " " << w.width << "x" << w.height;
        EXPECT_TRUE(has(r.error().what(), "is not inside the 64x48 frame")) << r.error().what();
    }
    const Result<reference::Image> inside =
        reference::renderWindow(scene, RenderSettings{}, {56, 40, 8, 8});
    ASSERT_TRUE(inside);
    EXPECT_EQ(inside->width, 8);
}

// The scaled window (the ground truth's supersampled render) checks the scene's own camera, the
// scale and the window in the scaled image's pixels, and at scale n draws what renderWindow draws
// for the camera resized n times.
TEST(RenderErrors, AScaledReferenceWindowIsCheckedAndMatchesTheResizedCamera) {
    const Scene scene = triangleScene();
    const RenderSettings s;
    const Result<reference::Image> below = reference::renderScaledWindow(scene, s, 0, {0, 0, 1, 1});
    ASSERT_FALSE(below);
    EXPECT_TRUE(has(below.error().what(), "scale 0 is below 1")) << below.error().what();
    const Result<reference::Image> outside =
        reference::renderScaledWindow(scene, s, 2, {120, 0, 16, 1});
    ASSERT_FALSE(outside);
    EXPECT_TRUE(has(outside.error().what(), "is not inside the 128x96 frame"))
        << outside.error().what();
    Scene bad = scene;
    bad.camera.width = -10;
    EXPECT_FALSE(reference::renderScaledWindow(bad, s, 2, {0, 0, 1, 1}));
    Scene noMesh = scene;
    noMesh.mesh = nullptr;
    EXPECT_FALSE(reference::renderScaledWindow(noMesh, s, 2, {0, 0, 1, 1}));

    const reference::Window window{40, 30, 48, 36};
    const Result<reference::Image> scaled = reference::renderScaledWindow(scene, s, 2, window);
    ASSERT_TRUE(scaled) << scaled.error().what();
    Scene big = scene;
    big.camera = resizedCamera(scene.camera, 128, 96);
    const Result<reference::Image> resized = reference::renderWindow(big, s, window);
    ASSERT_TRUE(resized);
    EXPECT_GT(std::count_if(scaled->depth.begin(), scaled->depth.end(),
                            [](double d) { return std::isfinite(d); }),
              0);  // the triangle is in the window
    EXPECT_EQ(scaled->color, resized->color);
    EXPECT_EQ(scaled->depth, resized->depth);
    EXPECT_EQ(scaled->ambiguous, resized->ambiguous);
}
