// The pixel inspector (facet/inspect.hpp): its fragment list for a hand-built scene whose answer
// is known (a shared edge through pixel centres, a depth-test failure), its final colour against
// the frame's pixel over many pixels of real scenes and settings, its lighting and texel
// breakdowns against the colour they explain, the one-pixel reference and ground truth against
// the whole-frame ones, and `facet inspect` as a user runs it.

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "facet/camera.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/inspect.hpp"
#include "facet/mesh_io.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "run_process.hpp"
#include "shared_data.hpp"
#include "test_scenes.hpp"

namespace facet {
namespace {

// The camera below maps world (x, y, 0) to pixel (32 − 32x, 32 − 32y): eye at z = −5 looking
// along +z with up −y, focal 160 over 64×64 pixels.
constexpr int kSide = 64;

Camera testCamera() {
    return facet::test::lookAt({0.0, 0.0, -5.0}, {0.0, 0.0, 0.0}, 160.0, kSide, kSide);
}

/// World point of pixel position (px, py) at z = 0 (exact in binary for the values used).
glm::vec3 at(double px, double py) {
    return {static_cast<float>((32.0 - px) / 32.0), static_cast<float>((32.0 - py) / 32.0), 0.0f};
}

/// Triangle 0 (red) left of the column x = 20.5 px, triangle 1 (green) right of it, sharing that
/// edge from y = 8 to y = 40: the centres of pixels (20, 8…39) lie exactly on it. Triangle 2
/// (blue), drawn last, lies behind both (z = 1) and covers them: it fails the depth test there.
Scene twoTrianglesAndABackOne() {
    auto mesh = std::make_shared<Mesh>();
    const glm::vec3 red(1, 0, 0), green(0, 1, 0), blue(0, 0, 1);
    mesh->positions = {at(8.0, 8.0),       at(20.5, 8.0),       at(20.5, 40.0),        // red
                       at(20.5, 8.0),      at(33.0, 40.0),      at(20.5, 40.0),        // green
                       {1.0f, 1.0f, 1.0f}, {-1.0f, 1.0f, 1.0f}, {1.0f, -1.0f, 1.0f}};  // blue
    mesh->colors = {red, red, red, green, green, green, blue, blue, blue};
    mesh->indices = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    Scene scene;
    scene.mesh = mesh;
    scene.camera = testCamera();
    return scene;
}

std::uint32_t frameAt(const Scene& scene, const RenderSettings& settings, int x, int y) {
    Renderer renderer;
    Framebuffer frame;
    renderer.render(scene, settings, frame);
    return frame.color[frame.index(x, y)];
}

int coveredCount(const PixelHistory& h) {
    return static_cast<int>(
        std::count_if(h.fragments.begin(), h.fragments.end(),
                      [](const auto& f) { return f.coverage == CoverageResult::Covered; }));
}

TEST(Inspect, SharedEdgeBelongsToOneTriangleAndTheBackOneFailsDepth) {
    const Scene scene = twoTrianglesAndABackOne();
    const RenderSettings settings;  // solid, painter, perspective
    const PixelHistory h = inspectPixel(scene, settings, 20, 20);
    ASSERT_EQ(h.fragments.size(), 3u);

    // Triangle 0: its box holds the pixel, but the centre is on its right edge: excluded.
    const InspectedFragment& red = h.fragments[0];
    EXPECT_EQ(red.triangle, 0u);
    EXPECT_EQ(red.coverage, CoverageResult::Excluded);
    EXPECT_TRUE(red.onEdge);
    int onRedEdge = 0;
    for (const InspectedEdge& e : red.edges)
        if (e.value == 0) {
            ++onRedEdge;
            EXPECT_FALSE(e.topLeft);
            EXPECT_FALSE(e.inside);
            EXPECT_EQ(e.dx, 0);  // the vertical shared edge
        }
    EXPECT_EQ(onRedEdge, 1);

    // Triangle 1: the same edge is its left edge: covered, and drawn (nothing was there).
    const InspectedFragment& green = h.fragments[1];
    EXPECT_EQ(green.triangle, 1u);
    EXPECT_EQ(green.coverage, CoverageResult::Covered);
    int onGreenEdge = 0;
    for (const InspectedEdge& e : green.edges)
        if (e.value == 0) {
            ++onGreenEdge;
            EXPECT_TRUE(e.topLeft);
            EXPECT_TRUE(e.inside);
        }
    EXPECT_EQ(onGreenEdge, 1);
    EXPECT_TRUE(green.depthTested);
    EXPECT_TRUE(std::isinf(green.storedDepth));
    EXPECT_TRUE(green.passed);
    EXPECT_FLOAT_EQ(green.depth, 5.0f);
    EXPECT_EQ(green.rgba, packRgba(0, 255, 0));

    // Triangle 2, behind: covered, but its depth is not below the green one's: discarded.
    const InspectedFragment& blue = h.fragments[2];
    EXPECT_EQ(blue.triangle, 2u);
    EXPECT_EQ(blue.coverage, CoverageResult::Covered);
    EXPECT_FLOAT_EQ(blue.depth, 6.0f);
    EXPECT_EQ(blue.storedDepth, green.depth);
    EXPECT_FALSE(blue.passed);
    EXPECT_EQ(blue.rgba, packRgba(0, 0, 255));  // what it would have written

    EXPECT_EQ(h.finalColor, packRgba(0, 255, 0));
    EXPECT_EQ(h.finalColor, frameAt(scene, settings, 20, 20));
    EXPECT_FLOAT_EQ(h.finalDepth, 5.0f);
    ASSERT_TRUE(h.hasReference);
    EXPECT_EQ(h.referenceRgba, h.finalColor);
    EXPECT_DOUBLE_EQ(h.referenceDepth, 5.0);
}

TEST(Inspect, EveryCentreOnTheSharedEdgeBelongsToExactlyOneOfTheTwo) {
    const Scene scene = twoTrianglesAndABackOne();
    const RenderSettings settings;
    for (int y = 8; y < 40; ++y) {
        const PixelHistory h = inspectPixel(scene, settings, 20, y);
        int front = 0;
        for (const InspectedFragment& f : h.fragments)
            if (f.triangle < 2 && f.coverage == CoverageResult::Covered) ++front;
        EXPECT_EQ(front, 1) << "row " << y;
    }
}

TEST(Inspect, VerticesAreTheMeshsInWorldClipAndFixedPoint) {
    const Scene scene = twoTrianglesAndABackOne();
    const PixelHistory h = inspectPixel(scene, RenderSettings{}, 20, 20);
    ASSERT_FALSE(h.fragments.empty());
    const InspectedFragment& red = h.fragments[0];
    EXPECT_EQ(red.vertices[1].index, 1u);
    EXPECT_EQ(red.vertices[1].world, scene.mesh->positions[1]);
    EXPECT_FLOAT_EQ(red.vertices[1].clip.w, 5.0f);
    EXPECT_DOUBLE_EQ(red.vertices[1].screen.x, 20.5);
    EXPECT_EQ(red.vertices[1].fixedX, 20 * 256 + 128);  // 1/256 px units
    EXPECT_EQ(red.vertices[1].fixedY, 8 * 256);
    EXPECT_FALSE(red.clipped);
    for (const InspectedEdge& e : red.edges) EXPECT_GE(e.from, 0);
}

TEST(Inspect, SimpleShaderTestsNoDepthSoTheLastTriangleWins) {
    const Scene scene = twoTrianglesAndABackOne();
    RenderSettings settings;
    settings.shader = ShaderKind::Simple;
    const PixelHistory h = inspectPixel(scene, settings, 20, 20);
    ASSERT_EQ(coveredCount(h), 2);
    for (const InspectedFragment& f : h.fragments)
        if (f.coverage == CoverageResult::Covered) {
            EXPECT_FALSE(f.depthTested);
            EXPECT_TRUE(f.passed);
        }
    EXPECT_EQ(h.finalColor, packRgba(0, 0, 255));
    EXPECT_EQ(h.finalColor, frameAt(scene, settings, 20, 20));
}

TEST(Inspect, BackgroundPixelHasNoFragmentAndCullingDropsBackFaces) {
    const Scene scene = twoTrianglesAndABackOne();
    RenderSettings settings;
    const PixelHistory empty = inspectPixel(scene, settings, 62, 62);
    EXPECT_TRUE(empty.fragments.empty());
    EXPECT_EQ(empty.finalColor, rgbaFromHex(settings.background));
    EXPECT_EQ(empty.finalColor, frameAt(scene, settings, 62, 62));

    const PixelHistory all = inspectPixel(scene, settings, 20, 20);
    settings.cullBackFaces = true;
    const PixelHistory culled = inspectPixel(scene, settings, 20, 20);
    for (const InspectedFragment& f : culled.fragments) EXPECT_FALSE(f.backFacing);
    std::size_t front = 0;
    for (const InspectedFragment& f : all.fragments) front += f.backFacing ? 0 : 1;
    EXPECT_EQ(culled.fragments.size(), front);
    EXPECT_EQ(culled.finalColor, frameAt(scene, settings, 20, 20));
}

TEST(Inspect, OutsideTheImageOrInWireframeItSaysSo) {
    const Scene scene = twoTrianglesAndABackOne();
    RenderSettings settings;
    EXPECT_FALSE(inspectPixel(scene, settings, -1, 3).notes.empty());
    EXPECT_FALSE(inspectPixel(scene, settings, 3, kSide).notes.empty());
    settings.mode = DrawMode::Wireframe;
    const PixelHistory h = inspectPixel(scene, settings, 20, 20);
    EXPECT_TRUE(h.fragments.empty());
    EXPECT_FALSE(h.notes.empty());
}

TEST(Inspect, AMultisampledFrameIsNotInspectedAndItSaysSo) {
    // Its colour comes from per-sample coverage and possibly a centroid, not the centre alone.
    const Scene scene = twoTrianglesAndABackOne();
    RenderSettings settings;
    settings.msaa = 4;
    const PixelHistory h = inspectPixel(scene, settings, 20, 20);
    EXPECT_TRUE(h.fragments.empty());
    ASSERT_FALSE(h.notes.empty());
    EXPECT_NE(h.notes.front().find("--msaa 1"), std::string::npos);
    settings.msaa = 1;  // the same pixel at one sample is listed
    EXPECT_FALSE(inspectPixel(scene, settings, 20, 20).fragments.empty());
}

// --- Real scenes: the final colour is the frame's pixel ------------------------------------

struct RealCase {
    const char* scene;
    RenderSettings settings;
    const char* name;
};

RenderSettings with(auto&& edit) {
    RenderSettings s;
    edit(s);
    return s;
}

std::vector<RealCase> realCases() {
    return {
        {"course/example0", with([](RenderSettings&) {}), "painter"},
        {"course/example1", with([](RenderSettings& s) { s.lighting = Lighting::Phong; }), "phong"},
        {"course/example2", with([](RenderSettings& s) { s.lighting = Lighting::Gouraud; }),
         "gouraud"},
        {"course/example1", with([](RenderSettings& s) { s.interp = Interp::Affine; }), "affine"},
        {"course/example2", with([](RenderSettings& s) {
             s.interp = Interp::Subdivided;
             s.subdivision = 8;
             s.lighting = Lighting::Phong;
         }),
         "subdivided_phong"},
        {"course/example_textured", with([](RenderSettings& s) {
             s.shader = ShaderKind::Texture;
             s.filter = TextureFilter::Trilinear;
         }),
         "trilinear"},
        {"course/example_textured", with([](RenderSettings& s) {
             s.shader = ShaderKind::Texture;
             s.filter = TextureFilter::Nearest;
             s.combine = true;
             s.lighting = Lighting::Phong;
         }),
         "nearest_combine_phong"},
        {"course/example_textured", with([](RenderSettings& s) {
             s.shader = ShaderKind::Texture;
             s.interp = Interp::Subdivided;
             s.subdivision = 16;
         }),
         "bilinear_subdivided"},
        {"course/example0", with([](RenderSettings& s) { s.shader = ShaderKind::Depth; }), "depth"},
        {"course/example1", with([](RenderSettings& s) { s.shader = ShaderKind::Simple; }),
         "simple"},
        {"course/example2", with([](RenderSettings& s) {
             s.cullBackFaces = true;
             s.subPixelBits = 4;
         }),
         "cull_4bits"},
        {"scenes/bunny_1280x720", with([](RenderSettings& s) { s.lighting = Lighting::Gouraud; }),
         "bunny_gouraud"},
        {"scenes/spot_1280x720", with([](RenderSettings& s) {
             s.shader = ShaderKind::Texture;
             s.filter = TextureFilter::Trilinear;
             s.combine = true;
             s.lighting = Lighting::Phong;
         }),
         "spot_trilinear_combine_phong"},
        {"course/example1", with([](RenderSettings& s) {
             s.supersample = 2;
             s.lighting = Lighting::Phong;
         }),
         "supersample2_phong"},
    };
}

class InspectRealScene : public ::testing::TestWithParam<RealCase> {};

TEST_P(InspectRealScene, FinalColourIsTheFramesPixelAtManyPixels) {
    const RealCase& c = GetParam();
    const std::string path = test::sharedData(std::string(c.scene) + ".scene");
    REQUIRE_SHARED_DATA(path);
    Result<Scene> loaded = loadScene(path);
    ASSERT_TRUE(loaded) << loaded.error().what();
    Scene scene = std::move(loaded).value();
    // The course's textured scene names no image: the course's brick, as its tests use.
    if (c.settings.shader == ShaderKind::Texture && !scene.texture) {
        ASSERT_TRUE(loadSceneTexture(scene, test::sharedData("course/brick.jpg")));
    }
    // A smaller frame keeps the test quick; every pixel is still a real one of that frame.
    scene.camera = resizedCamera(scene.camera, 160, 120);
    Renderer renderer;
    Framebuffer frame;
    renderer.render(scene, c.settings, frame);

    // Pixels drawn on (most of them) and a few of the background, from a fixed seed.
    std::mt19937 rng(17);
    std::vector<std::pair<int, int>> pixels;
    const std::uint32_t background = rgbaFromHex(c.settings.background);
    for (int tries = 0; tries < 20000 && pixels.size() < 60; ++tries) {
        const int x = static_cast<int>(rng() % static_cast<unsigned>(frame.width));
        const int y = static_cast<int>(rng() % static_cast<unsigned>(frame.height));
        const bool drawn = frame.color[frame.index(x, y)] != background;
        if (drawn || pixels.size() % 10 == 9) pixels.emplace_back(x, y);
    }
    int withFragments = 0;
    for (const auto& [x, y] : pixels) {
        const PixelHistory h = inspectPixel(scene, c.settings, x, y);
        EXPECT_EQ(h.finalColor, frame.color[frame.index(x, y)]) << "pixel " << x << ", " << y;
        if (c.settings.supersample == 1) {
            EXPECT_EQ(h.finalDepth, frame.depth[frame.index(x, y)]) << "pixel " << x << ", " << y;
        }
        withFragments += coveredCount(h) > 0 ? 1 : 0;
    }
    EXPECT_GT(withFragments, 30);  // the test looked at drawn pixels, not only background
}

INSTANTIATE_TEST_SUITE_P(Scenes, InspectRealScene, ::testing::ValuesIn(realCases()),
                         [](const auto& param) { return std::string(param.param.name); });

Scene loadShared(const std::string& relative, int width, int height) {
    Result<Scene> loaded = loadScene(test::sharedData(relative));
    if (!loaded) return {};
    Scene scene = std::move(loaded).value();
    scene.camera = resizedCamera(scene.camera, width, height);
    // The course's textured scene names no image: the course's brick, as its tests use.
    if (!scene.texture && !loadSceneTexture(scene, test::sharedData("course/brick.jpg"))) return {};
    return scene;
}

TEST(Inspect, LightingTermsSumToTheIntensityThatLitTheColour) {
    const std::string path = test::sharedData("course/example1.scene");
    REQUIRE_SHARED_DATA(path);
    const Scene scene = loadShared("course/example1.scene", 160, 120);
    RenderSettings settings;
    settings.lighting = Lighting::Phong;
    Renderer renderer;
    Framebuffer frame;
    renderer.render(scene, settings, frame);
    int checked = 0;
    for (int y = 0; y < frame.height; y += 7)
        for (int x = 0; x < frame.width; x += 7) {
            const PixelHistory h = inspectPixel(scene, settings, x, y);
            for (const InspectedFragment& f : h.fragments) {
                if (f.coverage != CoverageResult::Covered) continue;
                ASSERT_TRUE(f.lit);
                const InspectedLighting& l = f.lighting;
                EXPECT_NEAR(l.ambient + l.diffuse + l.specular, l.intensity, 1e-5f);
                if (l.nDotL <= 0.0f) {
                    EXPECT_EQ(l.diffuse + l.specular, 0.0f);
                }
                EXPECT_GE(l.nDotH, 0.0f);
                EXPECT_LE(l.nDotH, 1.0f);
                for (int k = 0; k < 3; ++k)
                    EXPECT_NEAR(f.shaded[k], std::clamp(f.color[k] * l.intensity, 0.0f, 1.0f),
                                1e-6f);
                ++checked;
            }
        }
    EXPECT_GT(checked, 50);
}

TEST(Inspect, TexelWeightsSumToOneAndBlendToTheTextureColour) {
    const std::string path = test::sharedData("course/example_textured.scene");
    REQUIRE_SHARED_DATA(path);
    const Scene scene = loadShared("course/example_textured.scene", 160, 120);
    for (const TextureFilter filter :
         {TextureFilter::Nearest, TextureFilter::Bilinear, TextureFilter::Trilinear}) {
        RenderSettings settings;
        settings.shader = ShaderKind::Texture;
        settings.filter = filter;
        int checked = 0, twoLevels = 0;
        for (int y = 0; y < 120; y += 9)
            for (int x = 0; x < 160; x += 9) {
                for (const InspectedFragment& f : inspectPixel(scene, settings, x, y).fragments) {
                    if (f.coverage != CoverageResult::Covered) continue;
                    ASSERT_TRUE(f.textured);
                    ASSERT_FALSE(f.texels.empty());
                    float sum = 0.0f;
                    glm::vec3 blend(0.0f);
                    int firstLevel = f.texels.front().level;
                    for (const InspectedTexel& t : f.texels) {
                        sum += t.weight;
                        blend += t.color * t.weight;
                        twoLevels += t.level != firstLevel ? 1 : 0;
                    }
                    EXPECT_NEAR(sum, 1.0f, 1e-5f);
                    for (int k = 0; k < 3; ++k) EXPECT_NEAR(blend[k], f.shaded[k], 1e-4f);
                    if (filter == TextureFilter::Nearest) {
                        EXPECT_EQ(f.texels.size(), 1u);
                    }
                    if (filter != TextureFilter::Trilinear) {
                        EXPECT_EQ(f.lod, 0.0f);
                    }
                    ++checked;
                }
            }
        EXPECT_GT(checked, 20) << toString(filter);
        if (filter == TextureFilter::Trilinear) {
            EXPECT_GT(twoLevels, 0);
        }
    }
}

// --- The one-pixel reference and ground truth -----------------------------------------------

TEST(Inspect, ReferenceWindowIsTheWholeFramesPixels) {
    const std::string path = test::sharedData("course/example2.scene");
    REQUIRE_SHARED_DATA(path);
    const Scene scene = loadShared("course/example2.scene", 96, 72);
    RenderSettings settings;
    settings.lighting = Lighting::Phong;
    settings.interp = Interp::Subdivided;
    settings.subdivision = 8;
    const reference::Image whole = reference::render(scene, settings).value();
    const reference::Window window{16, 30, 40, 9};  // x a multiple of the subdivision
    const reference::Image part = reference::renderWindow(scene, settings, window).value();
    ASSERT_EQ(part.width, window.width);
    ASSERT_EQ(part.height, window.height);
    int drawn = 0;
    for (int y = 0; y < window.height; ++y)
        for (int x = 0; x < window.width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y * window.width + x);
            const std::size_t j =
                static_cast<std::size_t>((y + window.y) * whole.width + x + window.x);
            if (whole.ambiguous[j] || part.ambiguous[i]) continue;
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(part.color[i][k], whole.color[j][k], 1e-9);
            drawn += std::isfinite(whole.depth[j]) ? 1 : 0;
        }
    EXPECT_GT(drawn, 50);
}

TEST(Inspect, GroundTruthOfOnePixelIsTheWholeTruthsPixel) {
    const std::string path = test::sharedData("course/example_textured.scene");
    REQUIRE_SHARED_DATA(path);
    const Scene scene = loadShared("course/example_textured.scene", 64, 48);
    RenderSettings settings;
    settings.shader = ShaderKind::Texture;
    const GroundTruth whole = renderGroundTruth(scene, settings, 4).value();
    for (const auto& [x, y] : {std::pair{32, 24}, {10, 30}, {50, 12}, {0, 0}}) {
        const GroundTruth one = renderGroundTruthPixel(scene, settings, x, y, 4);
        ASSERT_EQ(one.width, 1);
        const std::size_t i = static_cast<std::size_t>(y * whole.width + x);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(one.color[0][k], whole.color[i][k], 1e-5f);
        EXPECT_FLOAT_EQ(one.coverage[0], whole.coverage[i]);
    }
    EXPECT_EQ(renderGroundTruthPixel(scene, settings, 64, 0).width, 0);
}

// --- facet inspect ------------------------------------------------------------------------

using facet_test::Outcome;

Outcome runCli(const std::string& args) {
    return facet_test::runCommand(std::string(FACET_CLI) + " " + args);
}

TEST(InspectCli, PrintsTheHistoryOfTheSharedEdgePixel) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("facet_inspect_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    Scene scene = twoTrianglesAndABackOne();
    scene.meshPath = (dir / "two.off").string();
    ASSERT_TRUE(writeOff(*scene.mesh, scene.meshPath));
    const std::string sceneFile = (dir / "two.scene").string();
    ASSERT_TRUE(writeScene(scene, sceneFile));

    const Outcome r = runCli("inspect " + sceneFile + " 20 20 --truth-samples 4");
    EXPECT_EQ(r.exitCode, 0) << r.out;
    EXPECT_NE(r.out.find("final colour  #00FF00"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("reference     #00FF00"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("ground truth"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("3 triangles with the pixel in its box: 2 fragments, 1 excluded"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("#1 triangle 0 "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("EXCLUDED by the top-left rule"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("PASS (written)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("FAIL (discarded)"), std::string::npos) << r.out;

    const Outcome outside = runCli("inspect " + sceneFile + " 64 3");
    EXPECT_EQ(outside.exitCode, 2);
    EXPECT_NE(outside.out.find("outside the 64x64 image"), std::string::npos) << outside.out;
    const Outcome missing = runCli("inspect " + (dir / "nope.scene").string() + " 1 1");
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.out.find("nope.scene"), std::string::npos) << missing.out;
    fs::remove_all(dir);
}

}  // namespace
}  // namespace facet
