// The Compare panel's "against the ground truth" (accuracy_job.hpp) and what it is built on:
// the reference path's progress hook and a cancellable ground truth, the methods around the
// user's settings, and the job itself on a small tilted textured quad (real rendering, small
// images, 2×2 to 4×4 samples: each test well under a few seconds).

#include <algorithm>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "accuracy/accuracy_methods.hpp"
#include "accuracy_job.hpp"
#include "facet/camera.hpp"
#include "facet/evaluation/ground_truth.hpp"
#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/texture.hpp"
#include "world_at.hpp"

namespace {

using namespace facet;
using namespace facet::view;

using facet::test::worldAt;

// A floor-like quad receding from depth 1.5 at the bottom of the image to 12 at the top, a
// checkerboard tiled 4×4 times over it: affine interpolation bends its lines visibly. With
// `layers`, that many copies over the same pixels, the farthest first, each one in front of
// the last: the work of a much bigger image in the memory of a small one.
Scene tiltedQuad(int width, int height, int layers = 1) {
    Scene scene;
    scene.camera.width = width;
    scene.camera.height = height;
    scene.camera.focal = 0.8 * width;
    const double w = width, h = height;
    Mesh mesh;
    for (int k = layers - 1; k >= 0; --k) {
        const double z = 1.0 + 0.01 * k;
        const auto first = static_cast<std::uint32_t>(mesh.positions.size());
        mesh.positions.push_back(worldAt(scene.camera, -0.2 * w, 1.1 * h, 1.5 * z));
        mesh.positions.push_back(worldAt(scene.camera, 1.2 * w, 1.1 * h, 1.5 * z));
        mesh.positions.push_back(worldAt(scene.camera, 1.2 * w, 0.05 * h, 12.0 * z));
        mesh.positions.push_back(worldAt(scene.camera, -0.2 * w, 0.05 * h, 12.0 * z));
        for (const glm::vec2 uv :
             {glm::vec2(0, 4), glm::vec2(4, 4), glm::vec2(4, 0), glm::vec2(0, 0)})
            mesh.uvs.push_back(uv);
        for (const std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(first + i);
    }
    scene.mesh = std::make_shared<const Mesh>(std::move(mesh));
    std::vector<std::uint32_t> checks(32 * 32);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x)
            checks[static_cast<std::size_t>(y * 32 + x)] =
                ((x / 8 + y / 8) % 2) ? packRgba(230, 60, 40) : packRgba(250, 250, 250);
    Result<Texture> texture = Texture::fromRgba(32, 32, std::move(checks), "checks");
    EXPECT_TRUE(texture.ok());
    scene.texture = std::make_shared<const Texture>(std::move(texture.value()));
    return scene;
}

RenderSettings textured() {
    RenderSettings s;
    s.shader = ShaderKind::Texture;
    s.interp = Interp::Affine;
    s.filter = TextureFilter::Bilinear;
    return s;
}

// The report's row of a method; a failure and an empty row when there is none.
const AccuracyRow& row(const AccuracyReport& r, const std::string& method) {
    static const AccuracyRow none;
    for (const AccuracyRow& x : r.rows)
        if (x.method == method) return x;
    ADD_FAILURE() << "no row " << method;
    return none;
}

TEST(ReferenceProgress, ReachesOneInStepsAndLeavesTheImageAsItWas) {
    const Scene scene = tiltedQuad(80, 60);
    const RenderSettings settings = textured();
    const reference::Image plain = reference::render(scene, settings).value();
    std::vector<double> seen;
    const reference::Image tracked = reference::render(scene, settings, [&](double f) {
                                         seen.push_back(f);
                                         return true;
                                     }).value();
    EXPECT_FALSE(tracked.cancelled);
    EXPECT_EQ(tracked.color, plain.color);  // bit-identical
    EXPECT_EQ(tracked.depth, plain.depth);
    EXPECT_EQ(tracked.ambiguous, plain.ambiguous);
    ASSERT_GE(seen.size(), 20u);  // about every half percent of the pixel work
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.back(), 1.0);
}

TEST(ReferenceProgress, FalseCancelsAndAGroundTruthComesBackEmpty) {
    const Scene scene = tiltedQuad(80, 60);
    int calls = 0;
    const GroundTruth truth = renderGroundTruth(scene, textured(), 4, [&](double f) {
                                  ++calls;
                                  return f < 0.3;
                              }).value();
    EXPECT_TRUE(truth.cancelled);
    EXPECT_EQ(truth.width, 0);
    EXPECT_TRUE(truth.color.empty());
    EXPECT_LT(calls, 100);  // stopped at about 30 %, not run to the end
    const GroundTruth whole = renderGroundTruth(scene, textured(), 2).value();
    EXPECT_FALSE(whole.cancelled);
    EXPECT_EQ(whole.width, 80);
}

TEST(AccuracyMethods, AroundTheUserSettingsKeepTheirShaderAndCombine) {
    const Scene scene = tiltedQuad(40, 30);
    RenderSettings user = textured();
    user.mode = DrawMode::Wireframe;
    user.combine = true;
    user.lighting = Lighting::Gouraud;
    user.showNormals = true;
    const std::vector<app::AccuracyMethod> methods = app::accuracyMethods(scene, user);
    // 5 interpolations, 3 filters, 2 lightings, 3 supersamplings, 3 multisamplings
    ASSERT_EQ(methods.size(), 16u);
    for (const app::AccuracyMethod& m : methods) {
        EXPECT_EQ(m.settings.shader, ShaderKind::Texture) << m.name;
        EXPECT_TRUE(m.settings.combine) << m.name;
        EXPECT_EQ(m.settings.mode, DrawMode::Solid) << m.name;  // what the ground truth draws
        EXPECT_FALSE(m.settings.showNormals) << m.name;
        if (m.axis != "interp") {
            EXPECT_EQ(m.settings.interp, Interp::Affine) << m.name;
        }
        if (m.axis != "lighting") {
            EXPECT_EQ(m.settings.lighting, Lighting::Gouraud) << m.name;
        }
        EXPECT_EQ(m.settings.supersample, m.name == "2x2" ? 2 : m.name == "4x4" ? 4 : 1) << m.name;
        EXPECT_EQ(m.settings.msaa, m.name == "msaa2"   ? 2
                                   : m.name == "msaa4" ? 4
                                   : m.name == "msaa8" ? 8
                                                       : 1)
            << m.name;
    }
    EXPECT_EQ(methods[0].name, "affine");
    EXPECT_EQ(methods[4].name, "perspective");
    EXPECT_EQ(methods[4].settings.interp, Interp::Perspective);

    // Painter without lighting: the interpolations alone (no texture, nothing lit to compare).
    RenderSettings painter;
    painter.shader = ShaderKind::Painter;
    EXPECT_EQ(app::accuracyMethods(scene, painter).size(), 11u);
    // Texture without combine ignores the lit colour: no lighting axis.
    RenderSettings plainTexture = textured();
    plainTexture.lighting = Lighting::Phong;
    EXPECT_EQ(app::accuracyMethods(scene, plainTexture).size(), 14u);

    // The one-argument form is the overload around baseSettings(), as before.
    const std::vector<app::AccuracyMethod> base = app::accuracyMethods(scene);
    ASSERT_EQ(base.size(), 16u);
    for (const app::AccuracyMethod& m : base) {
        EXPECT_EQ(m.settings.shader, ShaderKind::Texture);
        EXPECT_TRUE(m.settings.combine);
        if (m.axis != "lighting") {
            EXPECT_EQ(m.settings.lighting, Lighting::Phong);
        }
        if (m.axis != "filter") {
            EXPECT_EQ(m.settings.filter, TextureFilter::Trilinear);
        }
    }
}

TEST(AccuracyJob, MeasuresEveryMethodAndPerspectiveBeatsAffine) {
    const Scene scene = tiltedQuad(96, 64);
    AccuracyJob job;
    // An 8x8 truth: finer than every method, 4x4 supersampling included.
    ASSERT_TRUE(job.start(scene, 7, textured(), 8, 2, 1));
    EXPECT_TRUE(job.running());
    job.wait();
    EXPECT_FALSE(job.running());
    const AccuracyStatus status = job.status();
    EXPECT_EQ(status.fraction, 1.0);
    EXPECT_TRUE(status.message.empty()) << status.message;
    ASSERT_EQ(job.reportCount(), 1u);
    const std::shared_ptr<const AccuracyReport> report = job.report();
    ASSERT_TRUE(report);
    EXPECT_EQ(report->width, 96);
    EXPECT_EQ(report->height, 64);
    EXPECT_EQ(report->samples, 8);
    EXPECT_EQ(report->frames, 2);
    EXPECT_EQ(report->leftOut, "");
    EXPECT_GT(report->groundTruthSeconds, 0.0);
    ASSERT_EQ(report->rows.size(), 14u);
    for (const char* m :
         {"affine", "subdivided:8", "subdivided:16", "subdivided:32", "perspective", "nearest",
          "bilinear", "trilinear", "1x1", "2x2", "4x4", "msaa2", "msaa4", "msaa8"}) {
        const AccuracyRow& r = row(*report, m);
        EXPECT_GT(r.times.median, 0.0) << m;
        EXPECT_EQ(r.times.frames, 2) << m;
        EXPECT_EQ(r.error.pixels, 96u * 64u) << m;
    }
    const double affine = row(*report, "affine").error.rmse;
    const double perspective = row(*report, "perspective").error.rmse;
    EXPECT_LE(perspective, affine);
    EXPECT_GT(affine, 2.0 * perspective) << "affine bends the checks: far off the truth";
    EXPECT_TRUE(std::any_of(report->rows.begin(), report->rows.end(),
                            [](const AccuracyRow& r) { return r.pareto; }));
    // Affine and bilinear are both the user's settings: measured once, the same numbers.
    EXPECT_EQ(row(*report, "affine").times, row(*report, "bilinear").times);
    EXPECT_EQ(row(*report, "affine").error.rmse, row(*report, "bilinear").error.rmse);
    EXPECT_EQ(row(*report, "affine").pareto, row(*report, "bilinear").pareto);
    const std::string state = accuracyStateText(report.get());
    EXPECT_NE(state.find("accuracy_rows 14\n"), std::string::npos) << state;
    // Supersampling and multisampling remove the silhouette aliasing every one-sample method
    // shares.
    EXPECT_LT(row(*report, "4x4").error.rmse, row(*report, "1x1").error.rmse);
    EXPECT_LT(row(*report, "msaa4").error.rmse, row(*report, "1x1").error.rmse);
    EXPECT_NE(state.find("accuracy_interp_perspective "), std::string::npos) << state;
}

TEST(AccuracyJob, TheTruthIsFinerThanEveryMethodInTheTable) {
    const Scene scene = tiltedQuad(64, 48);
    const std::vector<app::AccuracyMethod> all = app::accuracyMethods(scene, textured());
    std::string leftOut;
    std::vector<app::AccuracyMethod> kept = app::methodsBelowTruth(all, 4, &leftOut);
    EXPECT_EQ(kept.size(), all.size() - 1);
    EXPECT_EQ(leftOut, "4x4");
    for (const app::AccuracyMethod& m : kept) EXPECT_LT(m.settings.supersample, 4) << m.name;
    kept = app::methodsBelowTruth(all, 2, &leftOut);
    // A 2x2 truth has 4 samples per pixel: MSAA 4x and 8x are not below it.
    EXPECT_EQ(leftOut, "2x2, 4x4, msaa4, msaa8");
    EXPECT_EQ(app::methodsBelowTruth(all, 8, &leftOut).size(), all.size());
    EXPECT_EQ(leftOut, "");

    // A 4x4 truth measures no 4x4 method: the row that was "best" against itself is gone, and
    // the Pareto front is computed without it.
    AccuracyJob job;
    ASSERT_TRUE(job.start(scene, 3, textured(), 4, 1, 0));
    job.wait();
    const std::shared_ptr<const AccuracyReport> report = job.report();
    ASSERT_TRUE(report);
    EXPECT_EQ(report->rows.size(), all.size() - 1);
    EXPECT_EQ(report->leftOut, "4x4");
    EXPECT_NE(accuracyStateText(report.get()).find("accuracy_left_out 4x4\n"), std::string::npos);
    for (const AccuracyRow& r : report->rows) {
        EXPECT_NE(r.method, "4x4");
        EXPECT_GT(r.error.rmse, 0.0) << r.method << ": measured against itself?";
    }
}

TEST(AccuracyJob, CancelStopsItQuicklyAndLeavesNoResult) {
    // 40 layers of 400×300 at 4×4 samples: several seconds of reference rendering if it were
    // let run (one layer at 8×8 takes about 0.2 s here), in 70 MB.
    const Scene scene = tiltedQuad(400, 300, 40);
    AccuracyJob job;
    ASSERT_TRUE(job.start(scene, 1, textured(), 4));
    const auto t0 = std::chrono::steady_clock::now();
    while (job.status().fraction <= 0.0 &&
           std::chrono::steady_clock::now() - t0 < std::chrono::seconds(20))
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_TRUE(job.running());
    EXPECT_NE(job.status().label.find("ground truth"), std::string::npos) << job.status().label;
    const auto t1 = std::chrono::steady_clock::now();
    job.cancel();
    job.wait();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    EXPECT_LT(seconds, 2.0);  // one progress step is about 1/200 of the whole
    EXPECT_FALSE(job.running());
    EXPECT_FALSE(job.report());
    EXPECT_EQ(job.reportCount(), 0u);
    EXPECT_EQ(job.status().message, "Cancelled.");

    // A new request after it runs normally.
    ASSERT_TRUE(job.start(tiltedQuad(32, 24), 1, textured(), 2, 1, 0));
    job.wait();
    EXPECT_TRUE(job.report());
}

TEST(AccuracyJob, ANewRequestReplacesTheOneInFlight) {
    AccuracyJob job;
    ASSERT_TRUE(job.start(tiltedQuad(400, 300, 40), 1, textured(), 4));
    ASSERT_TRUE(job.start(tiltedQuad(32, 24), 2, textured(), 2, 1, 0));  // cancels, joins
    job.wait();
    const std::shared_ptr<const AccuracyReport> report = job.report();
    ASSERT_TRUE(report);
    EXPECT_EQ(report->width, 32);
    EXPECT_EQ(report->view.picture.sceneVersion, 2u);
    EXPECT_EQ(job.reportCount(), 1u);
}

TEST(AccuracyJob, ARequestTooBigForMemoryIsRefusedWithAMessage) {
    Scene scene = tiltedQuad(32, 24);
    scene.camera.width = kMaxImageSide;
    scene.camera.height = kMaxImageSide;
    AccuracyJob job;
    EXPECT_FALSE(job.start(scene, 1, textured(), 8));
    EXPECT_FALSE(job.running());
    EXPECT_NE(job.status().message.find("GB"), std::string::npos) << job.status().message;
    EXPECT_FALSE(job.report());
}

TEST(AccuracyJob, AReportGoesStaleWhenTheViewOrSettingsChange) {
    Scene scene = tiltedQuad(48, 32);
    RenderSettings settings = textured();
    AccuracyJob job;
    ASSERT_TRUE(job.start(scene, 3, settings, 2, 1, 0));
    job.wait();
    const std::shared_ptr<const AccuracyReport> report = job.report();
    ASSERT_TRUE(report);
    EXPECT_TRUE(reportFresh(*report, accuracyView(scene, 3, settings)));

    // Another draw mode is still the same measurement (the methods are Solid).
    RenderSettings wire = settings;
    wire.mode = DrawMode::Wireframe;
    EXPECT_TRUE(reportFresh(*report, accuracyView(scene, 3, wire)));
    // Picking a measured method keeps it fresh; a setting no row has does not.
    RenderSettings picked = settings;
    applyMethod(row(*report, "subdivided:16"), picked);
    EXPECT_EQ(picked.interp, Interp::Subdivided);
    EXPECT_EQ(picked.subdivision, 16);
    EXPECT_TRUE(reportFresh(*report, accuracyView(scene, 3, picked)));
    picked.subdivision = 64;
    EXPECT_FALSE(reportFresh(*report, accuracyView(scene, 3, picked)));
    RenderSettings shader = settings;
    shader.shader = ShaderKind::Painter;
    EXPECT_FALSE(reportFresh(*report, accuracyView(scene, 3, shader)));

    EXPECT_FALSE(reportFresh(*report, accuracyView(scene, 4, settings)));  // another scene
    Scene moved = scene;
    moved.camera.eye.x += 0.01;
    EXPECT_FALSE(reportFresh(*report, accuracyView(moved, 3, settings)));
    Scene resized = scene;
    resized.camera.width = 50;
    EXPECT_FALSE(reportFresh(*report, accuracyView(resized, 3, settings)));
    Scene lit = scene;
    lit.lighting.material.ks = 0.9;
    EXPECT_FALSE(reportFresh(*report, accuracyView(lit, 3, settings)));
    Scene retextured = scene;
    retextured.texture = std::make_shared<const Texture>();
    EXPECT_FALSE(reportFresh(*report, accuracyView(retextured, 3, settings)));
}

TEST(AccuracyJob, TheParetoFrontIsWhatNothingBeatsOnBoth) {
    std::vector<AccuracyRow> rows(7);
    auto set = [&](std::size_t i, double ms, double rmse) {
        rows[i].times.median = ms;
        rows[i].error.rmse = rmse;
    };
    set(0, 1.0, 5.0);     // fastest
    set(1, 2.0, 1.0);     // most accurate
    set(2, 2.5, 3.0);     // beaten by 1 on both
    set(3, 1.0, 6.0);     // as fast as 0, less accurate
    set(4, 2.0, 1.0);     // the same as 1 (the same method on another axis): both on
    set(5, 3.0, 0.9999);  // a hair more accurate than 1 but slower: a tie, so beaten
    set(6, 1.5, 2.0);     // between 0 and 1
    markPareto(rows);
    EXPECT_TRUE(rows[0].pareto);
    EXPECT_TRUE(rows[1].pareto);
    EXPECT_FALSE(rows[2].pareto);
    EXPECT_FALSE(rows[3].pareto);
    EXPECT_TRUE(rows[4].pareto);
    EXPECT_FALSE(rows[5].pareto);
    EXPECT_TRUE(rows[6].pareto);
}

}  // namespace
