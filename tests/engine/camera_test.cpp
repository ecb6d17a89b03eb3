// Camera transforms against values computed by hand for the course's example0 camera:
// eye (1.2, 2, 2), look-at the origin, y hint (0, -1, 0), f = 512, 512 × 512.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "facet/camera.hpp"
#include "test_scenes.hpp"

namespace facet {
namespace {

Camera example0() {
    return test::lookAt({1.2, 2.0, 2.0}, {0.0, 0.0, 0.0}, 512.0, 512, 512);
}

// By hand: z = (-1.2, -2, -2)/√9.44; x = up × z = (2, 0, -1.2)/√5.44 (after normalising);
// y = z × x = (2.4, -5.44, 4)/√(9.44·5.44).
const double kZn = std::sqrt(9.44), kXn = std::sqrt(5.44), kYn = std::sqrt(9.44 * 5.44);
const glm::dvec3 kX{2.0 / kXn, 0.0, -1.2 / kXn};
const glm::dvec3 kY{2.4 / kYn, -5.44 / kYn, 4.0 / kYn};
const glm::dvec3 kZ{-1.2 / kZn, -2.0 / kZn, -2.0 / kZn};

TEST(Camera, Example0CameraFromWorldHasHandComputedRows) {
    const glm::dmat4 m = cameraFromWorld(example0());
    const glm::dvec3 eye{1.2, 2.0, 2.0};
    const glm::dvec3 rows[3] = {kX, kY, kZ};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(m[c][r], rows[r][c], 1e-12) << "row " << r << " col " << c;
        EXPECT_NEAR(m[3][r], -glm::dot(rows[r], eye), 1e-12) << "translation row " << r;
        EXPECT_EQ(m[r][3], 0.0);
    }
    EXPECT_EQ(m[3][3], 1.0);
}

TEST(Camera, ClipFromCameraIsTheCalibrationWithDepthKept) {
    const glm::dmat4 k = clipFromCamera(example0());
    const glm::dvec4 clip = k * glm::dvec4(0.5, -0.25, 2.0, 1.0);
    EXPECT_DOUBLE_EQ(clip.x, 512.0 * 0.5 + 256.0 * 2.0);
    EXPECT_DOUBLE_EQ(clip.y, 512.0 * -0.25 + 256.0 * 2.0);
    EXPECT_DOUBLE_EQ(clip.z, 2.0);
    EXPECT_DOUBLE_EQ(clip.w, 2.0);
}

TEST(Camera, Example0ProjectsHandComputedPixels) {
    const Camera cam = example0();
    // The look-at point lands on the image centre at the eye's distance.
    const glm::dvec3 centre = projectToPixel(cam, {0.0, 0.0, 0.0});
    EXPECT_NEAR(centre.x, 256.0, 1e-9);
    EXPECT_NEAR(centre.y, 256.0, 1e-9);
    EXPECT_NEAR(centre.z, kZn, 1e-12);

    // Cube corner (1, 0, 0): p − eye = (−0.2, −2, −2).
    const glm::dvec3 d{-0.2, -2.0, -2.0};
    const double X = glm::dot(kX, d), Y = glm::dot(kY, d), Z = glm::dot(kZ, d);
    EXPECT_NEAR(Z, 8.24 / kZn, 1e-12);
    const glm::dvec3 p = projectToPixel(cam, {1.0, 0.0, 0.0});
    EXPECT_NEAR(p.x, 512.0 * X / Z + 256.0, 1e-9);
    EXPECT_NEAR(p.y, 512.0 * Y / Z + 256.0, 1e-9);
    EXPECT_NEAR(p.x, 419.7040, 1e-3);  // the same numbers worked out on paper
    EXPECT_NEAR(p.y, 319.9373, 1e-3);
}

TEST(Camera, WorldUpIsUpOnScreenWithTheCourseYHint) {
    const Camera cam = example0();
    const glm::dvec3 origin = projectToPixel(cam, {0.0, 0.0, 0.0});
    const glm::dvec3 above = projectToPixel(cam, {0.0, 0.5, 0.0});
    EXPECT_LT(above.y, origin.y);  // row 0 is the top
}

TEST(Camera, PointsBehindTheCameraHaveNegativeDepth) {
    const Camera cam = example0();
    EXPECT_LT(projectToPixel(cam, {2.4, 4.0, 4.0}).z, 0.0);
}

TEST(Camera, CheckCameraRejectsDegenerateSetups) {
    Camera c = example0();
    EXPECT_EQ(checkCamera(c), "");
    c.look = c.eye;
    EXPECT_NE(checkCamera(c).find("equals"), std::string::npos);
    c = example0();
    c.up = c.look - c.eye;
    EXPECT_NE(checkCamera(c).find("parallel"), std::string::npos);
    c = example0();
    c.focal = 0.0;
    EXPECT_NE(checkCamera(c).find("focal"), std::string::npos);
    c = example0();
    c.eye.x = std::nan("");
    EXPECT_NE(checkCamera(c).find("finite"), std::string::npos);
    c = example0();
    c.width = 0;
    EXPECT_NE(checkCamera(c).find("size"), std::string::npos);
    c = example0();
    c.height = kMaxImageSide + 1;
    EXPECT_EQ(checkCamera(c), "image size must be 1..16384 pixels in each direction");
    c.height = kMaxImageSide;
    EXPECT_EQ(checkCamera(c), "");
}

// One resize rule for every caller: the pose stays, f follows the kept axis, and an n-times image
// (supersampling, ground truth) gets exactly n·f, so its sample grid is exact.
TEST(Camera, ResizedKeepsThePoseAndOneFieldOfView) {
    const Camera c = example0();
    const Camera wide = resizedCamera(c, 1024, 256);
    EXPECT_EQ(wide.eye, c.eye);
    EXPECT_EQ(wide.look, c.look);
    EXPECT_EQ(wide.up, c.up);
    EXPECT_EQ(wide.width, 1024);
    EXPECT_EQ(wide.height, 256);
    EXPECT_EQ(wide.focal, 1024.0);  // the width doubled: the horizontal field of view stays
    EXPECT_EQ(resizedCamera(c, 1024, 256, KeepFov::Vertical).focal, 256.0);
    EXPECT_NE(wide, c);
    EXPECT_EQ(resizedCamera(c, c.width, c.height), c);

    Camera odd = c;
    odd.focal = 0.1 + 0.2;  // not a round number
    odd.width = 301;
    odd.height = 197;
    for (const int n : {2, 3, 4, 8}) {
        const Camera big = resizedCamera(odd, odd.width * n, odd.height * n);
        EXPECT_EQ(big.focal, odd.focal * n) << n;
        EXPECT_EQ(big.width, 301 * n);
        EXPECT_EQ(big.height, 197 * n);
    }
}

}  // namespace
}  // namespace facet
