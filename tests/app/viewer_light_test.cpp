// Direct manipulation without a window: the light's marker lands where the engine projects the
// light, dragging it puts it under the pointer at the same distance from the look-at point,
// Ctrl + drag turns it the way the pointer goes; F frames the model's bounding sphere. And the
// numbers the Compare and Stats panels show: errors over covered pixels, the heat map's scale,
// engine stages from the same frame as their total.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "compare_stats.hpp"
#include "facet/camera.hpp"
#include "facet/colormap.hpp"
#include "facet/scene_io.hpp"
#include "frame_stats.hpp"
#include "framing.hpp"
#include "light_marker.hpp"
#include "render_worker.hpp"
#include "test_scenes.hpp"
#include "viewer_model.hpp"

namespace {

using namespace facet;
using namespace facet::view;

const std::string kDefaultScene = std::string(FACET_ASSETS_DIR) + "/default.scene";

Camera testCamera() {
    return facet::test::lookAt({0.0, 0.0, 5.0}, {0.0, 0.0, 0.0}, 500.0, 640, 480);
}

TEST(LightMarker, APointLightsMarkerIsItsProjection) {
    const Camera c = testCamera();
    const glm::dvec4 light(1.0, 0.5, 2.0, 1.0);
    const LightMarker m = lightMarker(c, light, glm::dvec3(0.0), 5.0);
    EXPECT_FALSE(m.directional);
    EXPECT_TRUE(m.visible);
    const glm::dvec3 p = projectToPixel(c, glm::dvec3(1.0, 0.5, 2.0));
    EXPECT_NEAR(m.pixel.x, p.x, 1e-9);
    EXPECT_NEAR(m.pixel.y, p.y, 1e-9);
    // w = 2: the light sits at xyz / 2.
    const LightMarker half = lightMarker(c, glm::dvec4(2.0, 1.0, 4.0, 2.0), glm::dvec3(0.0), 5.0);
    EXPECT_NEAR(half.pixel.x, p.x, 1e-9);
    // Behind the camera: not visible.
    EXPECT_FALSE(lightMarker(c, glm::dvec4(0.0, 0.0, 9.0, 1.0), glm::dvec3(0.0), 5.0).visible);
}

TEST(LightMarker, ADirectionalLightGetsAHandleTowardsItAndAnArrowToTheTarget) {
    const Camera c = testCamera();
    const glm::dvec3 target(0.0);
    const LightMarker m = lightMarker(c, glm::dvec4(3.0, 0.0, 0.0, 0.0), target, 5.0);
    EXPECT_TRUE(m.directional);
    EXPECT_NEAR(glm::length(m.handle - target), kDirectionalHandle * 5.0, 1e-12);
    EXPECT_NEAR(m.handle.x, kDirectionalHandle * 5.0, 1e-12);  // towards +x, where it comes from
    EXPECT_GT(m.pixel.x, 320.0);  // right of the centre (the camera's right is +x here)
    EXPECT_TRUE(m.aimVisible);
    EXPECT_NEAR(m.aim.x, 320.0, 1e-9);
    EXPECT_NEAR(m.aim.y, 240.0, 1e-9);
}

// The case: the light farther from the look-at point than the camera (the ray through
// the pointer met its sphere only behind the model, and the model went dark). Dragged across
// the centre, it stays on the camera's side: n·l > 0 at the target for the normal facing the
// camera, and it never gets farther than kDragSphere × the camera's distance.
TEST(LightMarker, ADraggedLightStaysOnTheSideTheCameraSees) {
    const Camera c = testCamera();  // eye at distance 5 from the target
    const glm::dvec3 target(0.0);
    const glm::dvec3 facing = glm::normalize(c.eye - target);
    for (const glm::dvec4 start : {glm::dvec4(3.0, 4.0, -3.0, 1.0), glm::dvec4(0.0, 9.0, 9.0, 1.0),
                                   glm::dvec4(-5.2, -0.8, 2.2, 1.0)}) {
        glm::dvec4 light = start;
        for (int i = 0; i <= 20; ++i) {  // from the top border down across the centre
            const glm::dvec2 pointer(300.0 + 2.0 * i, 10.0 + 23.0 * i);
            light = dragLight(c, light, target, 5.0, pointer);
            const glm::dvec3 l = glm::dvec3(light) / light.w - target;
            EXPECT_GT(glm::dot(facing, l), 0.0) << i;
            EXPECT_LE(glm::length(l), kDragSphere * 5.0 + 1e-9) << i;
        }
    }
}

TEST(LightMarker, DraggingPutsTheLightUnderThePointerAtTheSameDistance) {
    const Camera c = testCamera();
    const glm::dvec3 target(0.0);
    const glm::dvec4 light(0.0, 0.0, 2.0, 1.0);  // in front of the target, towards the eye
    for (const glm::dvec2 pointer : {glm::dvec2(400.0, 200.0), glm::dvec2(250.0, 300.0)}) {
        const glm::dvec4 moved = dragLight(c, light, target, 5.0, pointer);
        EXPECT_EQ(moved.w, 1.0);
        EXPECT_NEAR(glm::length(glm::dvec3(moved) - target), 2.0, 1e-9);
        const glm::dvec3 p = projectToPixel(c, glm::dvec3(moved));
        EXPECT_NEAR(p.x, pointer.x, 1e-6);
        EXPECT_NEAR(p.y, pointer.y, 1e-6);
        EXPECT_GT(moved.z, 0.0);  // stayed on the near side, where it was
    }
    // Behind the target, it comes to the side the camera sees (the near point under the pointer).
    const glm::dvec4 back = dragLight(c, glm::dvec4(0.0, 0.0, -2.0, 1.0), target, 5.0, {380, 240});
    EXPECT_GT(back.z, 0.0);
    EXPECT_NEAR(projectToPixel(c, glm::dvec3(back)).x, 380.0, 1e-6);
    // Far outside the sphere's outline: on the outline, the distance kept.
    const glm::dvec4 edge = dragLight(c, light, target, 5.0, {5000.0, 240.0});
    EXPECT_NEAR(glm::length(glm::dvec3(edge)), 2.0, 1e-9);
    // The tangent point seen from the eye at distance 5: (2·sqrt(1 − 4/25), 0, 4/5).
    EXPECT_NEAR(edge.x, 2.0 * std::sqrt(1.0 - 4.0 / 25.0), 1e-9);
    EXPECT_NEAR(edge.z, 0.8, 1e-9);
    EXPECT_NEAR(glm::dot(glm::dvec3(edge) - c.eye, glm::dvec3(edge)), 0.0, 1e-9);  // tangent
    // Directional: the direction follows, |xyz| is kept, w stays 0.
    const glm::dvec4 sun(0.0, 0.0, 10.0, 0.0);
    const glm::dvec4 turned = dragLight(c, sun, target, 5.0, {500.0, 240.0});
    EXPECT_EQ(turned.w, 0.0);
    EXPECT_NEAR(glm::length(glm::dvec3(turned)), 10.0, 1e-9);
    EXPECT_GT(turned.x, 0.0);
    const LightMarker m = lightMarker(c, turned, target, 5.0);
    EXPECT_NEAR(m.pixel.x, 500.0, 1e-6);
    // A non-finite pointer changes nothing.
    EXPECT_EQ(dragLight(c, light, target, 5.0, {NAN, 1.0}), light);
}

TEST(LightMarker, AnOffScreenLightSitsOnTheBorderInItsDirection) {
    const Camera c = testCamera();
    const glm::dvec3 target(0.0);
    // In view: its projection.
    LightMarker m = lightMarker(c, glm::dvec4(0.5, 0.0, 0.0, 1.0), target, 5.0);
    EXPECT_TRUE(markerInFrame(m, 640, 480));
    EXPECT_EQ(markerPlace(m, 640, 480, 16.0), m.pixel);
    // Far right, in front: on the right border, at its height.
    m = lightMarker(c, glm::dvec4(50.0, 0.0, 0.0, 1.0), target, 5.0);
    EXPECT_TRUE(m.visible);
    EXPECT_FALSE(markerInFrame(m, 640, 480));
    glm::dvec2 p = markerPlace(m, 640, 480, 16.0);
    EXPECT_NEAR(p.x, 640.0 - 16.0, 1e-9);
    EXPECT_NEAR(p.y, 240.0, 1e-9);
    // Behind the camera and above it (world +y is image up here): on the top border.
    m = lightMarker(c, glm::dvec4(0.0, 3.0, 9.0, 1.0), target, 5.0);
    EXPECT_FALSE(m.visible);
    p = markerPlace(m, 640, 480, 16.0);
    EXPECT_NEAR(p.y, 16.0, 1e-9);
    EXPECT_NEAR(p.x, 320.0, 1e-9);
    // Dragging it from there brings it into view under the pointer.
    const glm::dvec4 moved = dragLight(c, glm::dvec4(0.0, 3.0, 9.0, 1.0), target, 5.0, p);
    const LightMarker after = lightMarker(c, moved, target, 5.0);
    EXPECT_TRUE(markerInFrame(after, 640, 480));
    EXPECT_NEAR(after.pixel.x, p.x, 1e-6);
    EXPECT_NEAR(after.pixel.y, p.y, 1e-6);
}

TEST(LightMarker, CtrlDragTurnsItTheWayThePointerGoes) {
    const Camera c = testCamera();
    const glm::dvec3 target(0.0);
    const glm::dvec4 light(0.0, 0.0, 2.0, 1.0);
    const double x0 = lightMarker(c, light, target, 5.0).pixel.x;
    const double y0 = lightMarker(c, light, target, 5.0).pixel.y;
    const glm::dvec4 right = turnLight(c, light, target, 5.0, 50.0, 0.0);
    EXPECT_GT(lightMarker(c, right, target, 5.0).pixel.x, x0 + 10.0);
    EXPECT_NEAR(glm::length(glm::dvec3(right)), 2.0, 1e-9);
    const glm::dvec4 down = turnLight(c, light, target, 5.0, 0.0, 50.0);
    EXPECT_GT(lightMarker(c, down, target, 5.0).pixel.y, y0 + 10.0);
    // 450 pixels at 0.4 degrees a pixel: half a turn, to the far side.
    const glm::dvec4 half = turnLight(c, light, target, 5.0, 450.0, 0.0);
    EXPECT_NEAR(half.z, -2.0, 1e-9);
    EXPECT_EQ(turnLight(c, light, target, 5.0, NAN, 0.0), light);
}

TEST(Framing, TheBoundingSphereFitsTheNarrowerFieldOfView) {
    const double d = framingDistance(1.0, 500.0, 640, 480);
    // The sphere's outline subtends kFrameFill of the half angle atan(240 / 500).
    EXPECT_NEAR(std::asin(1.0 / d), kFrameFill * std::atan(240.0 / 500.0), 1e-12);
    EXPECT_EQ(framingDistance(1.0, 500.0, 480, 640), d);

    ViewerModel m;
    ASSERT_TRUE(m.load(kDefaultScene));
    m.prepareFrame(1280, 720);
    m.zoom(-20.0);  // far away
    m.rotate(200.0, 50.0);
    const double yaw = m.orbit.yaw;
    frameModel(m);
    const Sphere s = boundingSphere(*m.scene.mesh);
    EXPECT_GT(s.radius, 0.0);
    EXPECT_NEAR(glm::length(m.orbit.target - s.centre), 0.0, 1e-12);
    EXPECT_EQ(m.orbit.yaw, yaw);  // the view direction stays
    const Camera& cam = m.prepareFrame(1280, 720);
    EXPECT_NEAR(glm::length(cam.eye - s.centre), framingDistance(s.radius, cam.focal, 720, 1280),
                1e-9);
    // Every vertex projects inside the frame.
    for (const glm::vec3& p : m.scene.mesh->positions) {
        const glm::dvec3 px = projectToPixel(cam, glm::dvec3(p));
        ASSERT_GT(px.z, 0.0);
        EXPECT_GE(px.x, 0.0);
        EXPECT_LE(px.x, 1280.0);
        EXPECT_GE(px.y, 0.0);
        EXPECT_LE(px.y, 720.0);
    }
    EXPECT_EQ(boundingSphere(Mesh{}).radius, 0.0);
}

using facet::test::filledFrame;

TEST(CompareStats, ErrorsAverageOverThePixelsEitherSideCovers) {
    // 10x10, the background equal on both sides; a 2x2 object on the left only, a 2x2 one on
    // both sides differing by 30, and one uncovered pixel that differs (a line drawn without
    // depth).
    Framebuffer a = filledFrame(10, 10, packRgba(0, 0, 0));
    Framebuffer b = filledFrame(10, 10, packRgba(0, 0, 0));
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            a.color[a.index(x, y)] = packRgba(90, 0, 0);
            a.depth[a.index(x, y)] = 1.0f;
            a.color[a.index(5 + x, 5 + y)] = packRgba(30, 30, 30);
            a.depth[a.index(5 + x, 5 + y)] = 2.0f;
            b.depth[b.index(5 + x, 5 + y)] = 2.0f;
        }
    b.color[b.index(9, 0)] = packRgba(0, 60, 0);
    const ImageDiff d = diffImages(a, b, nullptr, 0, DiffPixels::covered);
    EXPECT_EQ(d.pixels, 9u);
    EXPECT_EQ(d.pixelsDiffering, 9u);
    EXPECT_EQ(d.maxError, 90);
    EXPECT_DOUBLE_EQ(d.meanError, (4 * 90 + 4 * 30 + 60) / 9.0);
    // The whole frame's mean, for contrast, is the same sum over 100.
    EXPECT_DOUBLE_EQ(diffImages(a, b).meanError, (4 * 90 + 4 * 30 + 60) / 100.0);
    // No depth planes: every pixel counts.
    a.depth.clear();
    EXPECT_EQ(diffImages(a, b, nullptr, 0, DiffPixels::covered).pixels, 100u);
    EXPECT_FALSE(diffImages(a, filledFrame(5, 5, 0), nullptr, 0, DiffPixels::covered).sameSize);
}

TEST(CompareStats, TheColourBarMatchesTheHeatMap) {
    EXPECT_EQ(heatTop(0, 37), 37);
    EXPECT_EQ(heatTop(0, 0), kMinAutoHeat);
    EXPECT_EQ(heatTop(0, 1), kMinAutoHeat);  // one 8-bit step: dark, not the brightest
    EXPECT_EQ(heatTop(64, 37), 64);
    EXPECT_EQ(heatColour(0.0, 37), glm::dvec3(0.0));
    // The heat map's pixel for an error of 20 with 37 brightest is the bar's colour at 20.
    Framebuffer a = filledFrame(2, 1, packRgba(0, 0, 0));
    Framebuffer b = filledFrame(2, 1, packRgba(0, 0, 0));
    b.color[0] = packRgba(20, 0, 0);
    b.color[1] = packRgba(37, 0, 0);
    Framebuffer heat;
    diffImages(a, b, &heat, 0);
    const glm::dvec3 c = heatColour(20.0, heatTop(0, 37));
    EXPECT_EQ(heat.color[0], packRgba(static_cast<std::uint32_t>(std::lround(c.r * 255.0)),
                                      static_cast<std::uint32_t>(std::lround(c.g * 255.0)),
                                      static_cast<std::uint32_t>(std::lround(c.b * 255.0))));
}

TEST(FrameStats, TheEngineStagesComeFromTheFrameOfTheirTotal) {
    FrameHistory h;
    // Totals 10, 30, 20 ms; each frame's stages add up to a bit less than its own total.
    for (const double total : {10.0, 30.0, 20.0}) {
        RenderResult r;
        r.renderMs = total;
        r.stats.clearMs = 0.1 * total;
        r.stats.vertexMs = 0.2 * total;
        r.stats.rasterMs = 0.5 * total;
        r.stats.postMs = 0.1 * total;
        StageTimes t;
        recordEngineTimes(r, t);
        t.total = total + 5.0;
        h.push(t);
    }
    h.push(StageTimes{});  // a frame in which the engine sat out: not counted
    const StageTimes m = h.medianFrameBy(60, &StageTimes::render);
    EXPECT_EQ(m.render, 20.0);
    EXPECT_DOUBLE_EQ(m.engineRaster, 10.0);
    EXPECT_LE(m.engineClear + m.engineVertex + m.engineRaster + m.enginePost, m.render);
    // Compare: both sides' stages, within the total of both renders.
    RenderResult both;
    both.compared = true;
    both.renderMs = 9.0;
    both.stats.rasterMs = 4.0;
    both.rightStats.rasterMs = 4.5;
    StageTimes t;
    recordEngineTimes(both, t);
    EXPECT_EQ(t.engineRaster, 8.5);
    EXPECT_EQ(FrameHistory{}.medianFrameBy(60, &StageTimes::render).render, 0.0);
}

TEST(FrameStats, TheRealEnginesStagesNeverExceedItsTotal) {
    ViewerModel m;
    ASSERT_TRUE(m.load(kDefaultScene));
    m.settings.lighting = Lighting::Phong;
    m.settings.showNormals = true;
    m.prepareFrame(320, 180);
    for (const int ss : {1, 2}) {
        m.settings.supersample = ss;
        const auto t0 = Clock::now();
        m.render();
        const double total = ms(t0, Clock::now());
        const RenderStats& s = m.stats;
        EXPECT_LE(s.clearMs + s.vertexMs + s.rasterMs + s.postMs, total) << ss;
        EXPECT_GT(s.rasterMs, 0.0);
    }
}

}  // namespace
