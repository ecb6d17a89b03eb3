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

#include "facet/framebuffer.hpp"
#include "facet/reference.hpp"
#include "facet/render.hpp"
#include "facet/scene_io.hpp"
#include "image_compare.hpp"
#include "shared_data.hpp"

#include <glm/geometric.hpp>

namespace {

struct Error {
    double mean = 0.0;   ///< mean absolute channel error over covered pixels, in LSB
    double rmse = 0.0;   ///< root mean square channel error, in LSB
    int max = 0;         ///< largest channel error
    double over2 = 0.0;  ///< share of covered pixels with some channel more than 2 LSB off
};

Error measure(const facet::Framebuffer& fast, const std::vector<std::uint32_t>& truth,
              const facet::reference::Image& ref) {
    Error e;
    double sum = 0.0, sum2 = 0.0;
    std::size_t covered = 0, over2 = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
        if (!std::isfinite(ref.depth[i]) || ref.ambiguous[i]) continue;
        ++covered;
        int worst = 0;
        for (int shift = 0; shift < 24; shift += 8) {
            const int d = std::abs(static_cast<int>((fast.color[i] >> shift) & 0xFF) -
                                   static_cast<int>((truth[i] >> shift) & 0xFF));
            sum += d;
            sum2 += static_cast<double>(d) * d;
            worst = std::max(worst, d);
        }
        e.max = std::max(e.max, worst);
        over2 += worst > 2 ? 1 : 0;
    }
    if (covered == 0) return e;
    e.mean = sum / (3.0 * static_cast<double>(covered));
    e.rmse = std::sqrt(sum2 / (3.0 * static_cast<double>(covered)));
    e.over2 = static_cast<double>(over2) / static_cast<double>(covered);
    return e;
}

/// The five methods on one scene against the reference's perspective-correct truth.
struct Errors {
    Error perspective, sub8, sub16, sub32, affine;
};

Errors measureAll(const facet::Scene& scene, const char* label) {
    facet::RenderSettings settings;
    settings.shader = facet::ShaderKind::Texture;
    settings.filter = facet::TextureFilter::Bilinear;
    settings.interp = facet::Interp::Perspective;
    const facet::reference::Image ref = facet::reference::render(scene, settings);
    const std::vector<std::uint32_t> truth = ref.toRgba();
    facet::Renderer renderer;
    facet::Framebuffer frame;
    auto errorOf = [&](facet::Interp interp, int n, const char* name) {
        settings.interp = interp;
        settings.subdivision = n;
        renderer.render(scene, settings, frame);
        const Error e = measure(frame, truth, ref);
        std::printf("[interp-error] %-6s %-14s mean=%.3f rmse=%.3f max=%d over2=%.2f%%\n", label,
                    name, e.mean, e.rmse, e.max, 100.0 * e.over2);
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
        ASSERT_FALSE(facet::loadSceneTexture(scene, data + "brick.jpg").has_value());
    }
    facet::Scene scene;
};

// The course's view: the wall is tilted about the camera's x axis (the y hint is the wall's
// normal), so depth is constant along every row. Affine fails badly; the subdivided mode,
// which corrects along rows, is as exact as the perspective mode here.
TEST_F(InterpolationAccuracy, CourseViewAffineFailsRowSubdivisionIsExact) {
    const Errors e = measureAll(scene, "course");
    // The exact method is exact: 1 LSB is float rounding.
    EXPECT_LE(e.perspective.max, 1);
    EXPECT_EQ(e.perspective.over2, 0.0);
    // Affine puts the bricks in the wrong place: most pixels are off by far more than rounding.
    EXPECT_GT(e.affine.mean, 20.0);
    EXPECT_GT(e.affine.over2, 0.5);
    EXPECT_GT(e.affine.max, 150);
    for (const Error& sub : {e.sub8, e.sub16, e.sub32}) {
        EXPECT_LE(sub.max, 1);
        EXPECT_EQ(sub.over2, 0.0);
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
    EXPECT_LE(e.perspective.max, 1);
    EXPECT_GT(e.affine.mean, 20.0);
    EXPECT_LT(e.perspective.rmse, e.sub8.rmse);
    EXPECT_LT(e.sub8.rmse, e.sub16.rmse);
    EXPECT_LT(e.sub16.rmse, e.sub32.rmse);
    EXPECT_LT(e.sub32.rmse, e.affine.rmse);
    EXPECT_LT(e.sub8.rmse, 0.25 * e.affine.rmse) << "8-pixel spans cut the error fourfold";
}

}  // namespace
