// The lab kit (lab/, docs/lab.md): the checks pass with facet's solution and say "not started"
// for the stubs; the lab renderer, built with the solution, draws the course scenes as the
// engine and the reference path do (within 1 LSB, except where the reference marks a pixel
// ambiguous); the one rule where the course is simpler (no fill rule) is tested as such; the
// CLI's --renderer lab; and a handout built from scratch in a temporary folder.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "facet/advanced/draw.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "facet/texture.hpp"
#include "lab/checks.hpp"
#include "lab/renderer.hpp"
#include "run_process.hpp"
#include "shared_data.hpp"

namespace {

namespace fs = std::filesystem;
using facet::test::courseDir;
using facet::test::sharedData;
using facet_test::countOf;

TEST(LabChecks, TheSolutionPassesEveryStep) {
    REQUIRE_SHARED_DATA(courseDir() + "/example0.scene");
    const std::vector<lab::StepResult> results = lab::runChecks(courseDir());
    ASSERT_EQ(results.size(), static_cast<std::size_t>(lab::kStepCount));
    for (const lab::StepResult& r : results)
        EXPECT_EQ(r.outcome, lab::Outcome::Passed) << lab::formatResults(results);
}

TEST(LabChecks, MissingCourseDataIsAFailedStepNamingTheFile) {
    const std::vector<lab::StepResult> results = lab::runChecks("/nonexistent/course");
    ASSERT_FALSE(results.empty());
    EXPECT_EQ(results[0].outcome, lab::Outcome::Failed);
    EXPECT_NE(results[0].got.find("example0.scene"), std::string::npos) << results[0].got;
    // The rest are not checked, or wait for setLookAt (projectPoints uses it).
    for (std::size_t i = 1; i < results.size(); ++i)
        EXPECT_TRUE(results[i].outcome == lab::Outcome::NotChecked ||
                    results[i].outcome == lab::Outcome::Waiting)
            << lab::formatResults(results);
    EXPECT_EQ(results[3].outcome, lab::Outcome::Waiting);
}

TEST(LabChecks, TheStubsReportEveryStepNotStarted) {
    REQUIRE_SHARED_DATA(courseDir() + "/example0.scene");
    const facet_test::Outcome run =
        facet_test::runCommand(std::string(FACET_LAB_CHECK_STUBS) + " " + courseDir());
    EXPECT_EQ(run.exitCode, 1) << run.out;
    EXPECT_EQ(countOf(run.out, " not started ("), lab::kStepCount) << run.out;
    EXPECT_EQ(countOf(run.out, "FAILED"), 0) << run.out;
    EXPECT_NE(run.out.find("0 of 12 steps pass"), std::string::npos) << run.out;
}

// ---- the lab renderer against the engine and the reference ---------------------------------

struct Case {
    const char* scene;
    facet::DrawMode mode;
    facet::ShaderKind shader;
    facet::Interp interp;
    facet::Lighting lighting;
    const char* name;
};

class LabRenderer : public ::testing::TestWithParam<Case> {};

// 8-bit channels of a packed pixel differ by at most 1.
bool withinOneStep(std::uint32_t a, std::uint32_t b) {
    for (int shift = 0; shift < 24; shift += 8) {
        const int ca = static_cast<int>((a >> shift) & 0xFF);
        const int cb = static_cast<int>((b >> shift) & 0xFF);
        if (std::abs(ca - cb) > 1) return false;
    }
    return true;
}

TEST_P(LabRenderer, AgreesWithTheEngineAndTheReference) {
    const Case& c = GetParam();
    const std::string path = sharedData(std::string("course/") + c.scene);
    REQUIRE_SHARED_DATA(path);
    facet::Result<facet::Scene> loaded = facet::loadScene(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().what();
    facet::Scene scene = std::move(loaded).value();
    if (c.shader == facet::ShaderKind::Texture) {
        REQUIRE_SHARED_DATA(sharedData("course/brick.jpg"));
        ASSERT_TRUE(facet::loadSceneTexture(scene, sharedData("course/brick.jpg")));
    }
    facet::RenderSettings settings;
    settings.mode = c.mode;
    settings.shader = c.shader;
    settings.interp = c.interp;
    settings.lighting = c.lighting;
    settings.filter = facet::TextureFilter::Nearest;  // the course's Texture.sample
    ASSERT_EQ(lab::differences(settings), "");

    lab::Renderer labRenderer;
    facet::Framebuffer mine;
    const lab::Report report = labRenderer.render(scene, settings, mine);
    EXPECT_TRUE(report.notStarted.empty());

    facet::Renderer engine;
    facet::Framebuffer fast;
    engine.render(scene, settings, fast);
    const facet::reference::Image ref = facet::reference::render(scene, settings).value();
    const std::vector<std::uint32_t> refRgba = ref.toRgba();
    ASSERT_EQ(mine.color.size(), refRgba.size());
    ASSERT_EQ(fast.color.size(), refRgba.size());

    std::size_t drawn = 0, offReference = 0, offEngine = 0, ambiguousDiffering = 0;
    const std::uint32_t background = facet::rgbaFromHex(settings.background);
    for (std::size_t i = 0; i < refRgba.size(); ++i) {
        if (mine.color[i] != background) ++drawn;
        const bool agreeRef = withinOneStep(mine.color[i], refRgba[i]);
        const bool agreeFast = withinOneStep(mine.color[i], fast.color[i]);
        if (ref.ambiguous[i]) {
            ambiguousDiffering += (!agreeRef || !agreeFast) ? 1 : 0;
            continue;
        }
        if (!agreeRef && offReference++ < 5)
            ADD_FAILURE() << c.name << ": pixel (" << i % mine.width << ", " << i / mine.width
                          << ") lab " << facet::hexFromRgba(mine.color[i]) << " reference "
                          << facet::hexFromRgba(refRgba[i]);
        if (!agreeFast && offEngine++ < 5)
            ADD_FAILURE() << c.name << ": pixel (" << i % mine.width << ", " << i / mine.width
                          << ") lab " << facet::hexFromRgba(mine.color[i]) << " engine "
                          << facet::hexFromRgba(fast.color[i]);
    }
    EXPECT_EQ(offReference, 0u);
    EXPECT_EQ(offEngine, 0u);
    // The pictures are not empty, and the pixels left to the ambiguity rule are a thin seam.
    EXPECT_GT(drawn, 150u) << c.name;
    EXPECT_LT(ambiguousDiffering, refRgba.size() / 200) << c.name;
    std::printf("%s: %zu pixels drawn, %zu on edges differ (reference: ambiguous)\n", c.name, drawn,
                ambiguousDiffering);
}

using facet::DrawMode;
using facet::Interp;
using facet::Lighting;
using facet::ShaderKind;
INSTANTIATE_TEST_SUITE_P(
    CourseScenes, LabRenderer,
    ::testing::Values(Case{"example0.scene", DrawMode::Solid, ShaderKind::Painter, Interp::Affine,
                           Lighting::Off, "cube_painter_affine"},
                      Case{"example0.scene", DrawMode::Solid, ShaderKind::Simple, Interp::Affine,
                           Lighting::Off, "cube_simple_affine"},
                      Case{"example0.scene", DrawMode::Wireframe, ShaderKind::Painter,
                           Interp::Affine, Lighting::Off, "cube_wireframe"},
                      Case{"example0.scene", DrawMode::Vertices, ShaderKind::Painter,
                           Interp::Affine, Lighting::Off, "cube_vertices"},
                      Case{"example1.scene", DrawMode::Solid, ShaderKind::Painter,
                           Interp::Perspective, Lighting::Gouraud, "bunny_gouraud_perspective"},
                      Case{"example1.scene", DrawMode::Wireframe, ShaderKind::Painter,
                           Interp::Perspective, Lighting::Off, "bunny_wireframe_perspective"},
                      Case{"example2.scene", DrawMode::Solid, ShaderKind::Painter, Interp::Affine,
                           Lighting::Gouraud, "monkey_gouraud_affine"},
                      Case{"example2.scene", DrawMode::Solid, ShaderKind::Painter,
                           Interp::Perspective, Lighting::Off, "monkey_painter_perspective"},
                      Case{"example_textured.scene", DrawMode::Solid, ShaderKind::Texture,
                           Interp::Affine, Lighting::Off, "wall_texture_affine"},
                      Case{"example_textured.scene", DrawMode::Solid, ShaderKind::Texture,
                           Interp::Perspective, Lighting::Off, "wall_texture_perspective"}),
    [](const ::testing::TestParamInfo<Case>& p) { return std::string(p.param.name); });

// Where the course is simpler: its inside test (all barycentric coordinates >= 0) has no fill
// rule, so a pixel centre exactly on an edge two triangles share is drawn by both; facet's
// top-left rule gives it to exactly one (spec §5).
TEST(LabRasterizer, CoursesInsideTestDrawsASharedEdgeTwiceWhereFacetDrawsItOnce) {
    // The square from (0.5, 0.5) to (8.5, 8.5) split along its diagonal, which runs through the
    // pixel centres (i + ½, i + ½).
    const auto vertex = [](double x, double y) {
        lab::Fragment f;
        f.position = {x, y};
        f.depth = 1.0;
        return f;
    };
    const lab::Fragment a = vertex(0.5, 0.5), b = vertex(8.5, 0.5), c = vertex(8.5, 8.5),
                        d = vertex(0.5, 8.5);
    std::vector<lab::Fragment> frags;
    lab::rasterizeFace(a, b, c, 16, 16, frags);
    lab::rasterizeFace(a, c, d, 16, 16, frags);
    std::vector<int> labCount(16 * 16, 0);
    for (const lab::Fragment& f : frags)
        ++labCount[static_cast<std::size_t>(lab::pixelOf(f).y * 16 + lab::pixelOf(f).x)];

    const std::vector<glm::vec4> clip{{0.5f, 0.5f, 1.0f, 1.0f},
                                      {8.5f, 0.5f, 1.0f, 1.0f},
                                      {8.5f, 8.5f, 1.0f, 1.0f},
                                      {0.5f, 8.5f, 1.0f, 1.0f}};
    const std::vector<std::uint32_t> idx{0, 1, 2, 0, 2, 3};
    facet::DrawInput in;
    in.clip = clip;
    in.indices = idx;
    facet::Renderer engine;
    std::vector<std::uint16_t> facetCount;
    facet::countCoverage(engine, in, facet::RenderSettings{}, 16, 16, facetCount);

    // The diagonal: both triangles' edge, drawn twice by the lab, once by facet. The square's
    // right and bottom sides also run through pixel centres: the top-left rule leaves them to
    // the neighbours beyond (none here), the course's test draws them. Elsewhere the same.
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            const std::size_t i = static_cast<std::size_t>(y * 16 + x);
            int wantLab = facetCount[i];
            int wantFacet = facetCount[i];
            if (x == y && x < 8) {
                wantLab = 2;
                wantFacet = 1;
            } else if (x == 8 && y == 8) {
                wantLab = 2;  // the corner both triangles share
                wantFacet = 0;
            } else if ((x == 8 && y < 8) || (y == 8 && x < 8)) {
                wantLab = 1;
                wantFacet = 0;
            }
            EXPECT_EQ(labCount[i], wantLab) << "pixel (" << x << ", " << y << ")";
            EXPECT_EQ(facetCount[i], wantFacet) << "pixel (" << x << ", " << y << ")";
        }
    }
    // Inside, away from the edges, both draw every pixel once.
    EXPECT_EQ(facetCount[3 * 16 + 1], 1);
    EXPECT_EQ(labCount[3 * 16 + 1], 1);
}

// ---- the CLI ---------------------------------------------------------------------------------

TEST(LabCli, RenderWithTheLabRendererWritesItsPicture) {
    const std::string scene = sharedData("course/example2.scene");
    REQUIRE_SHARED_DATA(scene);
    const fs::path out = fs::path(::testing::TempDir()) / "lab_cli_monkey.png";
    const facet_test::Outcome run =
        facet_test::runCommand(std::string(FACET_CLI) + " render " + scene +
                               " --renderer lab --lighting gouraud -o " + out.string());
    ASSERT_EQ(run.exitCode, 0) << run.out;
    EXPECT_NE(run.out.find("the lab's pipeline"), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("not started"), std::string::npos) << run.out;

    facet::Result<facet::Scene> loaded = facet::loadScene(scene);
    ASSERT_TRUE(loaded.ok());
    facet::RenderSettings settings;
    settings.lighting = facet::Lighting::Gouraud;
    lab::Renderer r;
    facet::Framebuffer frame;
    r.render(loaded.value(), settings, frame);
    facet::Result<facet::Texture> png = facet::loadTexture(out.string());
    ASSERT_TRUE(png.ok()) << png.error().what();
    EXPECT_EQ(png->level(0).texels, frame.color);

    const facet_test::Outcome bad = facet_test::runCommand(
        std::string(FACET_CLI) + " render " + scene + " --renderer nope -o " + out.string());
    EXPECT_EQ(bad.exitCode, 2) << bad.out;
}

}  // namespace
