// Where each interpolation method fails, on the course's textured facet (a brick wall seen at
// an angle): the reference path's perspective-correct image is the truth; the fast path's
// perspective mode must match it within 1 LSB, affine must be visibly wrong (this test pins how
// wrong), and the subdivided modes must fall in between, closer to the truth as N shrinks.
// Each mode prints one line:
//   [interp-error] <mode> mean=<LSB> rmse=<LSB> max=<LSB> over2=<% of covered pixels>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "facet/evaluation/reference_compare.hpp"
#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "shared_data.hpp"

#include <glm/geometric.hpp>

namespace {

/// Errors against the reference's perspective-correct picture (8-bit) over the pixels it drew
/// and does not flag ambiguous: meanError, rmse, maxError and over2Lsb in LSB.
using Error = facet::ImageError;

/// The five methods on one scene against the reference's perspective-correct truth.
struct Errors {
    Error perspective, sub8, sub16, sub32, affine;
};

Errors measureAll(const facet::Scene& scene, const char* label) {
    facet::RenderSettings settings;
    settings.shader = facet::ShaderKind::Texture;
    settings.filter = facet::TextureFilter::Bilinear;
    settings.interp = facet::Interp::Perspective;
    const facet::reference::Image ref = facet::reference::render(scene, settings).value();
    facet::Renderer renderer;
    facet::Framebuffer frame;
    auto errorOf = [&](facet::Interp interp, int n, const char* name) {
        settings.interp = interp;
        settings.subdivision = n;
        renderer.render(scene, settings, frame);
        const Error e = facet::errorAgainstReference(frame, ref);
        std::printf("[interp-error] %-6s %-14s mean=%.3f rmse=%.3f max=%d over2=%.2f%%\n", label,
                    name, e.meanError, e.rmse, static_cast<int>(e.maxError), 100.0 * e.over2Lsb);
        return e;
    };
    return {errorOf(facet::Interp::Perspective, 16, "perspective"),
            errorOf(facet::Interp::Subdivided, 8, "subdivided:8"),
            errorOf(facet::Interp::Subdivided, 16, "subdivided:16"),
            errorOf(facet::Interp::Subdivided, 32, "subdivided:32"),
            errorOf(facet::Interp::Affine, 16, "affine")};
}

class InterpolationAccuracy : public testing::Test {
  protected:
    void SetUp() override {
        const std::string data = facet::test::sharedData("course/");
        REQUIRE_SHARED_DATA(data + "brick.jpg");
        facet::Result<facet::Scene> loaded = facet::loadScene(data + "example_textured.scene");
        ASSERT_TRUE(loaded.ok()) << loaded.error().what();
        scene = std::move(loaded).value();
        ASSERT_TRUE(facet::loadSceneTexture(scene, data + "brick.jpg"));
    }
    facet::Scene scene;
};

// The course's view: the wall is tilted about the camera's x axis (the y hint is the wall's
// normal), so depth is constant along every row. Affine fails badly; the subdivided mode,
// which corrects along rows, is as exact as the perspective mode here.
TEST_F(InterpolationAccuracy, CourseViewAffineFailsRowSubdivisionIsExact) {
    const Errors e = measureAll(scene, "course");
    // The exact method is exact: 1 LSB is float rounding.
    EXPECT_LE(e.perspective.maxError, 1.0);
    EXPECT_EQ(e.perspective.over2Lsb, 0.0);
    // Affine puts the bricks in the wrong place: most pixels are off by far more than rounding.
    EXPECT_GT(e.affine.meanError, 20.0);
    EXPECT_GT(e.affine.over2Lsb, 0.5);
    EXPECT_GT(e.affine.maxError, 150.0);
    for (const Error& sub : {e.sub8, e.sub16, e.sub32}) {
        EXPECT_LE(sub.maxError, 1.0);
        EXPECT_EQ(sub.over2Lsb, 0.0);
    }
}

// The same wall with the camera rolled by 40°: depth now changes along rows, and the
// subdivided mode's error lies strictly between the two, shrinking with N.
TEST_F(InterpolationAccuracy, RolledViewSubdividedLiesBetween) {
    facet::Camera& cam = scene.camera;
    const glm::dvec3 forward = glm::normalize(cam.look - cam.eye);
    const glm::dvec3 up = glm::normalize(cam.up - glm::dot(cam.up, forward) * forward);
    const glm::dvec3 side = glm::cross(forward, up);
    const double roll = 40.0 * 3.14159265358979 / 180.0;
    cam.up = std::cos(roll) * up + std::sin(roll) * side;
    const Errors e = measureAll(scene, "rolled");
    EXPECT_LE(e.perspective.maxError, 1.0);
    EXPECT_GT(e.affine.meanError, 20.0);
    EXPECT_LT(e.perspective.rmse, e.sub8.rmse);
    EXPECT_LT(e.sub8.rmse, e.sub16.rmse);
    EXPECT_LT(e.sub16.rmse, e.sub32.rmse);
    EXPECT_LT(e.sub32.rmse, e.affine.rmse);
    EXPECT_LT(e.sub8.rmse, 0.25 * e.affine.rmse) << "8-pixel spans cut the error fourfold";
}

}  // namespace
