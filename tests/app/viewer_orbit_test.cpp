// The viewer's orbit camera: yaw/pitch/distance round trips, the scene's own view reproduced,
// finite poses at the poles, pan moving eye and look-at together, zoom that never crosses the
// look-at point, and drags that turn the object the way the mouse goes.

#include <cmath>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "facet/camera.hpp"
#include "orbit.hpp"
#include "test_scenes.hpp"

namespace {

using facet::Camera;
using namespace facet::view;

Camera courseCamera() {
    return facet::test::lookAt({1.6, 1.4, 2.6}, {0.1, -0.2, 0.3}, 1100.0, 1280, 720);
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// The camera an orbit gives, with the intrinsics of `base`.
Camera posed(const Orbit& o, Camera base = courseCamera()) {
    applyPose(o, base);
    return base;
}

TEST(ViewerOrbit, YawPitchDistanceRoundTrip) {
    const Orbit basis = orbitFromCamera(courseCamera());
    for (double yaw : {-179.0, -90.0, -12.5, 0.0, 33.0, 135.0, 180.0})
        for (double pitch : {-89.0, -45.0, 0.0, 10.0, 88.9})
            for (double distance : {0.01, 1.0, 250.0}) {
                Orbit o = basis;
                o.yaw = yaw;
                o.pitch = pitch;
                o.distance = distance;
                const Pose p = orbitPose(o);
                const Orbit back = orbitMeasure(basis, p.eye, p.look);
                // 180 and −180 are one direction: compare angles modulo 360.
                EXPECT_NEAR(std::remainder(back.yaw - yaw, 360.0), 0.0, 1e-9)
                    << yaw << " " << pitch;
                EXPECT_NEAR(back.pitch, pitch, 1e-9) << yaw << " " << pitch;
                EXPECT_NEAR(back.distance, distance, 1e-12 * distance + 1e-12);
            }
}

TEST(ViewerOrbit, SceneCameraIsYawZeroAndTheSameView) {
    const Camera scene = courseCamera();
    const Orbit o = orbitFromCamera(scene);
    EXPECT_EQ(o.yaw, 0.0);
    EXPECT_NEAR(o.distance, glm::length(scene.eye - scene.look), 1e-12);
    const Camera c = posed(o);
    EXPECT_NEAR(glm::length(c.eye - scene.eye), 0.0, 1e-12);
    // The y hint differs (it is built perpendicular to the view) but the camera frame is equal.
    const glm::dmat4 a = facet::clipFromWorld(scene);
    const glm::dmat4 b = facet::clipFromWorld(c);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) EXPECT_NEAR(a[i][j], b[i][j], 1e-9) << i << "," << j;
}

TEST(ViewerOrbit, PolesStayFiniteAndNeverFlip) {
    Orbit o = orbitFromCamera(courseCamera());
    for (double dy : {1e4, -1e4, 1e9, -1e9}) {
        orbitRotate(o, 0.0, dy);
        EXPECT_LE(std::abs(o.pitch), kMaxPitch);
        const Camera c = posed(o);
        EXPECT_TRUE(finite(c.eye) && finite(c.up));
        EXPECT_EQ(facet::checkCamera(c), "") << "pitch " << o.pitch;
        // The screen's up keeps leaning towards the world's vertical: no flip over the pole.
        glm::dvec3 right, screenUp;
        orbitAxes(o, right, screenUp);
        EXPECT_GT(glm::dot(screenUp, o.vertical), 0.0);
        const glm::dmat4 m = facet::clipFromWorld(c);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(m[i][j]));
    }
}

TEST(ViewerOrbit, PanMovesEyeAndLookTogetherAndTheSceneFollowsTheMouse) {
    Orbit o = orbitFromCamera(courseCamera());
    const Camera before = posed(o);
    const glm::dvec3 target = o.target;
    orbitPan(o, 40.0, -25.0, before.focal);
    const Camera after = posed(o);
    EXPECT_NEAR(glm::length((after.eye - after.look) - (before.eye - before.look)), 0.0, 1e-12);
    EXPECT_GT(glm::length(after.look - before.look), 0.0);
    // The old look-at point, which sat in the centre, is now where the mouse went.
    const glm::dvec3 p = facet::projectToPixel(after, target);
    EXPECT_NEAR(p.x, after.width / 2.0 + 40.0, 1e-6);
    EXPECT_NEAR(p.y, after.height / 2.0 - 25.0, 1e-6);
}

TEST(ViewerOrbit, ZoomNeverCrossesTheLookAtPoint) {
    Orbit o = orbitFromCamera(courseCamera());
    const glm::dvec3 dir = glm::normalize(orbitPose(o).eye - o.target);
    for (int i = 0; i < 400; ++i) {
        orbitZoom(o, 3.0);
        const Pose p = orbitPose(o);
        ASSERT_GT(o.distance, 0.0);
        ASSERT_GE(o.distance, o.minDistance);
        ASSERT_GT(glm::dot(p.eye - p.look, dir), 0.0) << "step " << i;
    }
    EXPECT_EQ(o.distance, o.minDistance);
    for (int i = 0; i < 400; ++i) orbitZoom(o, -3.0);
    EXPECT_EQ(o.distance, o.maxDistance);
    orbitZoom(o, 1.0);
    EXPECT_LT(o.distance, o.maxDistance);
}

TEST(ViewerOrbit, DragsTurnTheObjectWithTheMouse) {
    const Orbit start = orbitFromCamera(courseCamera());
    // A point between the eye and the look-at point projects to the centre; after a drag to
    // the right it must have moved right, after a drag down it must have moved down.
    const Pose p0 = orbitPose(start);
    const glm::dvec3 front = 0.5 * (p0.eye + p0.look);
    Orbit right = start;
    orbitRotate(right, 50.0, 0.0);
    EXPECT_LT(right.yaw, start.yaw);
    const glm::dvec3 pr = facet::projectToPixel(posed(right), front);
    EXPECT_GT(pr.x, 640.0 + 10.0);  // (it also moves vertically: the camera looks down on it)
    Orbit down = start;
    orbitRotate(down, 0.0, 50.0);
    EXPECT_GT(down.pitch, start.pitch);
    const glm::dvec3 pd = facet::projectToPixel(posed(down), front);
    EXPECT_GT(pd.y, 360.0 + 10.0);
    EXPECT_NEAR(pd.x, 640.0, 1e-6);
}

TEST(ViewerOrbit, NonFiniteInputChangesNothingAndYawWraps) {
    Orbit o = orbitFromCamera(courseCamera());
    const Orbit before = o;
    orbitRotate(o, NAN, 1.0);
    orbitRotate(o, 1.0, INFINITY);
    orbitPan(o, NAN, 0.0, 1000.0);
    orbitPan(o, 1.0, 0.0, 0.0);
    orbitZoom(o, NAN);
    EXPECT_EQ(o.yaw, before.yaw);
    EXPECT_EQ(o.pitch, before.pitch);
    EXPECT_EQ(o.distance, before.distance);
    EXPECT_EQ(o.target, before.target);
    o.yaw = 190.0;
    orbitClamp(o);
    EXPECT_NEAR(o.yaw, -170.0, 1e-12);
    o.yaw = -180.0;
    orbitClamp(o);
    EXPECT_EQ(o.yaw, 180.0);
    o.pitch = NAN;
    o.distance = -1.0;
    orbitClamp(o);
    EXPECT_EQ(o.pitch, 0.0);
    EXPECT_EQ(o.distance, o.minDistance);
}

TEST(ViewerOrbit, AViewAlongTheUpHintStillGivesABasis) {
    Camera c = courseCamera();
    c.eye = {0.0, 5.0, 1e-9};  // almost straight above the look-at point
    c.look = {0.0, 0.0, 0.0};
    const Orbit o = orbitFromCamera(c);
    EXPECT_NEAR(glm::length(o.reference), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(o.reference, o.vertical), 0.0, 1e-12);
    EXPECT_LE(o.pitch, kMaxPitch);
    EXPECT_EQ(facet::checkCamera(posed(o)), "");
}

}  // namespace
