// The OpenGL twin (app/gl) against the reference path: an independent renderer held to the
// same specification, on the course scenes, Spot and the bunny. Outside the reference's ambiguity
// mask, coverage and colours must agree within the tolerances stated below (kTriangles...),
// which were measured on llvmpipe. Each case prints one summary line:
//   [gl-vs-ref] <case> covered=<n> ambiguous=<n> differing=<n> (<%>)
//               diff p50/p99/p99.9/max=<lsb> over1=<%>
// covered: unambiguous pixels the reference drew; ambiguous: pixels the reference flags as
// rounding-dependent; differing: coverage mismatches among the unambiguous pixels, and their
// share of `covered`; the diff percentiles (8-bit steps, largest channel) are over the pixels
// both drew; over1: the share of those more than one step apart.
// Then: the twin in a context whose state the caller set, a second context, the CLI command.
// Without a usable EGL (no libegl-mesa0, no driver) every test is skipped and says why.

#include <epoxy/gl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <unistd.h>

#include "facet/evaluation/image_diff.hpp"
#include "facet/evaluation/image_metrics.hpp"
#include "facet/evaluation/reference_compare.hpp"
#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene.hpp"
#include "facet/scene_io.hpp"
#include "facet/settings.hpp"
#include "gl_context.hpp"
#include "gl_renderer.hpp"
#include "scene_cases.hpp"
#include "shared_data.hpp"

namespace {

using facet::DrawMode;
using facet::Interp;
using facet::Lighting;
using facet::ShaderKind;
using facet::TextureFilter;

// One context and renderer for the whole binary, made on first use and released before exit
// (the renderer first, while its context is current).
struct Twin {
    std::optional<facet::GlContext> context;
    std::optional<facet::GlRenderer> renderer;
    std::string whyNot;  ///< why there is no context, for the skip message
    bool tried = false;
};

Twin& twin() {
    static Twin t;
    if (!t.tried) {
        t.tried = true;
        facet::Result<facet::GlContext> c = facet::GlContext::createHeadless();
        if (!c) {
            t.whyNot = c.error().what();
            return t;
        }
        t.context.emplace(std::move(c).value());
        facet::Result<facet::GlRenderer> r = facet::GlRenderer::create();
        if (!r) {
            t.whyNot = r.error().what();
            return t;
        }
        t.renderer.emplace(std::move(r).value());
        std::printf("[gl-vs-ref] %s\n", t.context->description().c_str());
    }
    return t;
}

class TwinEnvironment : public testing::Environment {
  public:
    void TearDown() override {
        Twin& t = twin();
        t.renderer.reset();
        t.context.reset();
    }
};
[[maybe_unused]] testing::Environment* const kEnvironment =
    testing::AddGlobalTestEnvironment(new TwinEnvironment);

// Without a context (no EGL or Mesa driver) this machine cannot run the twin, so its tests skip
// (fail under CI=true, shared_data.hpp); a context without a renderer is the twin's own failure
// (e.g. a shader that does not build).
#define REQUIRE_TWIN()                                                                        \
    do {                                                                                      \
        REQUIRE_PREREQUISITE(twin().context, "no headless OpenGL context: " + twin().whyNot); \
        if (!twin().renderer) FAIL() << "the OpenGL twin cannot start: " << twin().whyNot;    \
    } while (false)

/// What a case may differ by, measured on llvmpipe (Mesa 22.3.6, Debian 12) and stated with
/// some room; the measured values are in the comments and in each case's summary line.
struct Tolerance {
    double coverage;  ///< coverage mismatches / covered pixels
    int p99;          ///< 99th percentile of the colour difference, in 8-bit steps
    int max;          ///< largest colour difference
    double over1;     ///< share of the pixels both drew that differ by more than one step
};

/// Triangles and vertex squares: coverage agreed exactly in every case measured (0 of 11.6M
/// covered pixels), colours within 1 step (float shading; bilinear with llvmpipe's 8-bit
/// weights is still within 1), over1 at most 0.002%.
constexpr Tolerance kTriangles{.coverage = 1e-4, .p99 = 1, .max = 2, .over1 = 1e-4};
/// Trilinear: llvmpipe takes one level of detail per 2×2 pixel quad, with 8-bit fractions,
/// where the engine takes the exact derivatives per pixel. Measured p99 2, max 8, over1 5.9%
/// (the brick facet, minified everywhere).
constexpr Tolerance kTrilinear{.coverage = 1e-4, .p99 = 3, .max = 10, .over1 = 0.08};
/// Lines (wireframe, normals): GL's lines are parallelograms under the fill rule, not
/// Bresenham; twin.vert moves the ends to pixel centres and nudges ties. Measured coverage
/// mismatches at most 0.073%, over1 0.018%; a line pixel one row off shows what is under it,
/// so the largest difference is unbounded.
constexpr Tolerance kLines{.coverage = 0.002, .p99 = 1, .max = 255, .over1 = 0.001};
/// Lines crossing the near plane: the end GL clips cannot be moved to a pixel centre first.
/// Measured coverage mismatches at most 1.19%.
constexpr Tolerance kClippedLines{.coverage = 0.02, .p99 = 1, .max = 255, .over1 = 0.001};

using Case = facet::test::SceneCase;

const Tolerance& toleranceFor(const Case& c) {
    if (c.mode == DrawMode::Wireframe) return c.dolly < 1.0 ? kClippedLines : kLines;
    if (c.normals) return kLines;
    if (c.shader == ShaderKind::Texture && c.filter == TextureFilter::Trilinear) return kTrilinear;
    return kTriangles;
}

std::vector<Case> allCases() {
    const std::vector<std::string> scenes{"course/example0", "course/example1", "course/example2",
                                          "course/example_textured", "scenes/spot_1280x720"};
    std::vector<Case> cases;
    for (const std::string& scene : scenes) {
        for (const Interp interp : {Interp::Affine, Interp::Perspective})
            cases.push_back({.scene = scene, .interp = interp});
        cases.push_back({.scene = scene, .lighting = Lighting::Gouraud});
        cases.push_back({.scene = scene, .lighting = Lighting::Phong});
        cases.push_back({.scene = scene, .shader = ShaderKind::Depth});
    }
    for (const std::string scene : {"course/example_textured", "scenes/spot_1280x720"}) {
        for (const Interp interp : {Interp::Affine, Interp::Perspective})
            cases.push_back({.scene = scene, .shader = ShaderKind::Texture, .interp = interp});
        for (const TextureFilter filter : {TextureFilter::Nearest, TextureFilter::Trilinear})
            cases.push_back({.scene = scene, .shader = ShaderKind::Texture, .filter = filter});
        cases.push_back({.scene = scene,
                         .shader = ShaderKind::Texture,
                         .lighting = Lighting::Phong,
                         .combine = true});
    }
    for (const std::string scene : {"course/example2", "scenes/spot_1280x720"}) {
        cases.push_back({.scene = scene, .shader = ShaderKind::Simple});
        cases.push_back({.scene = scene, .cull = true});
        cases.push_back({.scene = scene, .mode = DrawMode::Vertices});
        cases.push_back({.scene = scene, .mode = DrawMode::Wireframe});
        cases.push_back({.scene = scene, .normals = true});
        cases.push_back({.scene = scene, .shader = ShaderKind::Depth, .normals = true});
    }
    // Close-ups: triangles cross the near plane and run far beyond the image.
    for (const std::string scene : {"course/example2", "scenes/spot_1280x720"}) {
        for (const double dolly : {0.1, 0.02}) {
            cases.push_back({.scene = scene, .dolly = dolly});
            cases.push_back({.scene = scene, .shader = ShaderKind::Depth, .dolly = dolly});
            cases.push_back({.scene = scene, .mode = DrawMode::Wireframe, .dolly = dolly});
        }
    }
    cases.push_back({.scene = "scenes/spot_1280x720",
                     .shader = ShaderKind::Texture,
                     .lighting = Lighting::Phong,
                     .filter = TextureFilter::Trilinear,
                     .combine = true,
                     .dolly = 0.3});
    // The 69k-triangle bunny: most triangles cover no pixel centre or one.
    for (const Lighting lighting : {Lighting::Off, Lighting::Gouraud, Lighting::Phong})
        cases.push_back({.scene = "scenes/bunny_1280x720", .lighting = lighting});
    cases.push_back({.scene = "scenes/bunny_1280x720", .shader = ShaderKind::Depth});
    return cases;
}

class GlVsReference : public testing::TestWithParam<Case> {};

TEST_P(GlVsReference, AgreesWithinStatedTolerances) {
    REQUIRE_TWIN();
    Twin& t = twin();
    const Case& c = GetParam();
    REQUIRE_SHARED_SCENE(loaded, c.scene);
    facet::Scene storage;
    const facet::Scene* scene = facet::test::dollied(loaded, c.dolly, storage);
    const facet::RenderSettings settings = facet::test::settingsFor(c);

    facet::Framebuffer gl;
    const facet::Result<facet::GlStats> stats = t.renderer->render(*scene, settings, gl);
    ASSERT_TRUE(stats.ok()) << stats.error().what();
    const facet::reference::Image ref = facet::reference::render(*scene, settings).value();
    ASSERT_EQ(gl.width, ref.width);
    ASSERT_EQ(gl.height, ref.height);

    // The histogram: colour differences over the unambiguous pixels both images drew.
    facet::DiffHistogram h;
    const facet::ReferenceDiff r =
        facet::compareWithReference(gl, ref, c.shader, settings.background, &h);
    const double coverage = static_cast<double>(r.coverageDiffers) /
                            static_cast<double>(std::max<std::size_t>(1, r.comparedCovered));
    const double over1 = h.shareAbove(1);
    const std::string name = facet::test::caseName(c);
    std::printf(
        "[gl-vs-ref] %-46s covered=%zu ambiguous=%zu differing=%zu (%.4f%%) diff "
        "p50/p99/p99.9/max=%d/%d/%d/%d over1=%.3f%%\n",
        name.c_str(), r.comparedCovered, r.ambiguous, r.coverageDiffers, 100.0 * coverage,
        h.percentile(0.5), h.percentile(0.99), h.percentile(0.999), h.max(), 100.0 * over1);
    const Tolerance& tolerance = toleranceFor(c);
    EXPECT_LE(coverage, tolerance.coverage) << name << r.examples;
    EXPECT_LE(h.percentile(0.99), tolerance.p99) << name << r.examples;
    EXPECT_LE(h.max(), tolerance.max) << name << r.examples;
    EXPECT_LE(over1, tolerance.over1) << name << r.examples;
}

std::string paramName(const testing::TestParamInfo<Case>& param) {
    return facet::test::caseName(param.param);
}

INSTANTIATE_TEST_SUITE_P(Scenes, GlVsReference, testing::ValuesIn(allCases()), paramName);

facet::Framebuffer renderTwin(facet::GlRenderer& renderer, const facet::Scene& scene) {
    facet::Framebuffer frame;
    const facet::Result<facet::GlStats> stats =
        renderer.render(scene, facet::RenderSettings{}, frame);
    EXPECT_TRUE(stats.ok()) << stats.error().what();
    return frame;
}

// The viewer will share its window's context with the twin: a render must neither depend on
// the state the caller left nor change it.
TEST(GlTwinContext, RenderIgnoresAndRestoresTheCallersState) {
    REQUIRE_TWIN();
    Twin& t = twin();
    REQUIRE_SHARED_SCENE(scene, "course/example2");
    const facet::Framebuffer clean = renderTwin(*t.renderer, *scene);

    glViewport(1, 2, 3, 4);
    glEnable(GL_BLEND);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 1, 1);
    glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    glDepthFunc(GL_LEQUAL);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glPixelStorei(GL_PACK_ROW_LENGTH, 7);  // as a caller's own readback might leave them
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 3);
    const facet::Framebuffer dirty = renderTwin(*t.renderer, *scene);
    EXPECT_TRUE(dirty.color == clean.color && dirty.depth == clean.depth);

    GLint viewport[4] = {}, depthFunc = 0, clipDepth = 0, framebuffer = -1;
    GLfloat clear[4] = {};
    GLboolean mask[4] = {};
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &clipDepth);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    EXPECT_EQ(std::vector<GLint>(viewport, viewport + 4), (std::vector<GLint>{1, 2, 3, 4}));
    EXPECT_TRUE(glIsEnabled(GL_BLEND) && glIsEnabled(GL_SCISSOR_TEST));
    EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST) || glIsEnabled(GL_CULL_FACE));
    EXPECT_EQ(depthFunc, GL_LEQUAL);
    EXPECT_EQ(clipDepth, GL_NEGATIVE_ONE_TO_ONE);
    EXPECT_EQ(framebuffer, 0);
    EXPECT_EQ(clear[2], 0.75f);
    EXPECT_EQ(mask[1], GL_FALSE);
    GLint packRowLength = 0, unpackSkipRows = 0;
    glGetIntegerv(GL_PACK_ROW_LENGTH, &packRowLength);
    glGetIntegerv(GL_UNPACK_SKIP_ROWS, &unpackSkipRows);
    EXPECT_EQ(packRowLength, 7);
    EXPECT_EQ(unpackSkipRows, 3);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// The benchmark's frame: upload once, draw the resident mesh (twice here), read back once. The
// picture is render()'s, the draw sends nothing, and draw() refuses what upload() did not send.
TEST(GlTwinContext, ResidentDrawsGiveRendersPicture) {
    REQUIRE_TWIN();
    Twin& t = twin();
    REQUIRE_SHARED_SCENE(scene, "course/example2");
    facet::RenderSettings phong;
    phong.lighting = Lighting::Phong;
    facet::Framebuffer rendered;
    ASSERT_TRUE(t.renderer->render(*scene, phong, rendered).ok());

    facet::GlStats stats;
    ASSERT_TRUE(t.renderer->upload(*scene, phong, stats)) << "upload";
    EXPECT_GT(stats.uploadBytes, 0u);
    const std::size_t sent = stats.uploadBytes;
    for (int i = 0; i < 2; ++i) ASSERT_TRUE(t.renderer->draw(*scene, phong, stats)) << i;
    EXPECT_EQ(stats.uploadBytes, sent);  // the draws sent nothing
    EXPECT_EQ(stats.trianglesIn, scene->mesh->triangleCount());
    facet::Framebuffer resident;
    ASSERT_TRUE(t.renderer->readBack(*scene, phong, resident, stats));
    EXPECT_TRUE(resident.color == rendered.color && resident.depth == rendered.depth);

    // Gouraud is another variant (it reads the colour, not the position): not uploaded.
    facet::RenderSettings gouraud = phong;
    gouraud.lighting = Lighting::Gouraud;
    const facet::Status other = t.renderer->draw(*scene, gouraud, stats);
    ASSERT_FALSE(other);
    EXPECT_NE(other.error().what().find("upload"), std::string::npos) << other.error().what();
    // Another mesh than the one uploaded.
    facet::Scene copy = *scene;
    copy.mesh = std::make_shared<const facet::Mesh>(*scene->mesh);
    EXPECT_FALSE(t.renderer->draw(copy, phong, stats));
    // A fresh upload has nothing drawn to read back; a draw beyond the driver's size fails.
    facet::Scene wide = *scene;
    wide.camera.width = 1 << 20;
    ASSERT_TRUE(t.renderer->upload(*scene, phong, stats));
    EXPECT_FALSE(t.renderer->readBack(*scene, phong, resident, stats));
    EXPECT_FALSE(t.renderer->draw(wide, phong, stats));
    EXPECT_FALSE(t.renderer->readBack(*scene, phong, resident, stats));
}

// A second context with its own renderer draws the same picture; the first works on after.
TEST(GlTwinContext, ASecondContextDrawsTheSamePicture) {
    REQUIRE_TWIN();
    Twin& t = twin();
    REQUIRE_SHARED_SCENE(scene, "course/example1");
    const facet::Framebuffer first = renderTwin(*t.renderer, *scene);
    {
        facet::Result<facet::GlContext> other = facet::GlContext::createHeadless();
        ASSERT_TRUE(other.ok()) << other.error().what();
        facet::Result<facet::GlRenderer> renderer = facet::GlRenderer::create();
        ASSERT_TRUE(renderer.ok()) << renderer.error().what();
        EXPECT_TRUE(renderTwin(*renderer, *scene).color == first.color);
    }  // the renderer goes first, while its context is still current
    ASSERT_TRUE(t.context->makeCurrent());
    EXPECT_TRUE(renderTwin(*t.renderer, *scene).color == first.color);
}

// Multisampling through GL (a multisampled FBO resolved by glBlitFramebuffer) against the
// engine's MSAA: the same silhouettes smoothed. GL shades an edge pixel at its centre where the
// engine takes the covered samples' centroid, and llvmpipe's sample positions are its own
// business, so the two are compared by how close they are, against how far the one-sample frame
// is from either.
TEST(GlTwinMsaa, MatchesTheEnginesMsaa) {
    REQUIRE_TWIN();
    Twin& t = twin();
    for (const char* name : {"course/example1", "scenes/spot_1280x720"}) {
        REQUIRE_SHARED_SCENE(scene, name);
        facet::RenderSettings s;
        s.lighting = facet::Lighting::Gouraud;
        facet::Framebuffer gl1, gl4, engine1, engine4;
        facet::Renderer engine;
        engine.render(*scene, s, engine1);
        ASSERT_TRUE(t.renderer->render(*scene, s, gl1).ok());
        s.msaa = 4;
        engine.render(*scene, s, engine4);
        const facet::Result<facet::GlStats> st = t.renderer->render(*scene, s, gl4);
        ASSERT_TRUE(st.ok()) << st.error().what();
        const double twins = facet::measureError(gl4.color, engine4.color).rmse;
        const double oneSample = facet::measureError(engine1.color, engine4.color).rmse;
        const double glOne = facet::measureError(gl1.color, gl4.color).rmse;
        const facet::ImageDiff d = facet::diffImages(gl4, engine4);
        std::printf(
            "[gl-msaa] %-22s RMSE GL 4x vs engine 4x %.3f (max %d, %zu px differ); "
            "engine 1x vs 4x %.3f; GL 1x vs 4x %.3f\n",
            name, twins, d.maxError, d.pixelsDiffering, oneSample, glOne);
        EXPECT_GT(glOne, 0.5 * oneSample) << name << ": GL's frame should be multisampled";
        // Measured (llvmpipe, Mesa 22.3.6, Gouraud): example1 0.50 against 1.76 (0.28 of it),
        // Spot 0.18 against 0.51 (0.35).
        EXPECT_LT(twins, 0.45 * oneSample) << name;
    }
}

// `facet render-gl` as a user runs it: a PNG and the median time of the frames.
TEST(GlTwinCli, RenderGlWritesThePngAndTheMedianTime) {
    REQUIRE_TWIN();
    const std::string scene = facet::test::sharedScenePath("course/example0");
    REQUIRE_SHARED_DATA(scene);
    const std::filesystem::path png = std::filesystem::temp_directory_path() /
                                      ("facet_gl_twin_" + std::to_string(::getpid()) + ".png");
    const std::string cmd = std::string(FACET_CLI) + " render-gl " + scene + " -o " + png.string() +
                            " --lighting gouraud --frames 3 2>&1";
    std::string out;
    FILE* p = popen(cmd.c_str(), "r");
    ASSERT_NE(p, nullptr);
    char line[512];
    while (std::fgets(line, sizeof line, p)) out += line;
    const int status = pclose(p);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
    EXPECT_NE(out.find("median "), std::string::npos) << out;
    EXPECT_TRUE(std::filesystem::exists(png)) << out;
    std::filesystem::remove(png);
}

}  // namespace
