// Lighting (spec §6) against hand-computed values, both versions: ambient, diffuse at 60°,
// specular at and off the half vector, a light behind the surface, w = 0 and w scaling, the
// edge exponents and undefined directions (documented in lighting.hpp), and float vs double.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/advanced/fast_lighting.hpp"
#include "facet/scene.hpp"
#include "shading/fast_lighting.hpp"

namespace {

using facet::LightingParams;

constexpr double kInf = std::numeric_limits<double>::infinity();

LightingParams params(double ia, glm::dvec4 light, double id, double ka, double kd, double ks,
                      double s) {
    LightingParams p;
    p.ambient = ia;
    p.light.position = light;
    p.light.intensity = id;
    p.material = facet::Material{ka, kd, ks, s};
    return p;
}

double lightD(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& eye,
              const LightingParams& params) {
    return facet::lightIntensity(p, n, eye, params);
}

double lightF(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& eye,
              const LightingParams& params) {
    return facet::lightIntensity(glm::vec3(p), glm::vec3(n), glm::vec3(eye),
                                 facet::prepareLighting(params));
}

// Both versions give `expected`: the double one to 1e-12, the float one to 1e-6.
void expectBoth(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec3& eye,
                const LightingParams& params, double expected) {
    const double d = lightD(p, n, eye, params);
    const double f = lightF(p, n, eye, params);
    EXPECT_TRUE(std::isfinite(d));
    EXPECT_TRUE(std::isfinite(f));
    EXPECT_NEAR(d, expected, 1e-12);
    EXPECT_NEAR(f, expected, 1e-6);
}

const glm::dvec3 kOrigin(0.0);
const glm::dvec3 kUp(0.0, 0.0, 1.0);

TEST(Lighting, AmbientOnly) {
    // Ia·Ka = 0.7 · 0.4 with Kd = Ks = 0, whatever the geometry.
    const LightingParams p = params(0.7, {0, 0, 5, 1}, 3.0, 0.4, 0.0, 0.0, 5.0);
    expectBoth(kOrigin, kUp, {0, 0, 3}, p, 0.28);
    expectBoth({1, 2, 3}, glm::normalize(glm::dvec3(1, -1, 2)), {-4, 0, 1}, p, 0.28);
}

TEST(Lighting, ZeroNormalIsAmbientOnly) {
    const LightingParams p = params(0.7, {0, 0, 5, 1}, 3.0, 0.4, 0.9, 0.9, 0.0);
    expectBoth(kOrigin, glm::dvec3(0.0), {0, 0, 3}, p, 0.28);
}

TEST(Lighting, DiffuseAtSixtyDegrees) {
    // Light at (√3, 0, 1), |·| = 2: l = (√3/2, 0, 1/2), n·l = cos 60° = 0.5.
    // I = Ia·Ka + Id·Kd·0.5 = 0.5·0.1 + 2·0.6·0.5 = 0.05 + 0.6.
    const LightingParams p = params(0.5, {std::sqrt(3.0), 0, 1, 1}, 2.0, 0.1, 0.6, 0.0, 1.0);
    expectBoth(kOrigin, kUp, {0, 0, 10}, p, 0.65);
}

TEST(Lighting, SpecularAtTheHalfVector) {
    // l = (1,0,1)/√2, v = (−1,0,1)/√2: h = (0,0,1) = n, so n·h = 1 and the specular term is
    // Id·Ks = 1.5 · 0.3 = 0.45 for any s. Diffuse: Id·Kd·(1/√2) = 1.5 · 0.2/√2 = 0.3/√2.
    const LightingParams spec = params(1.0, {1, 0, 1, 1}, 1.5, 0.0, 0.0, 0.3, 7.0);
    expectBoth(kOrigin, kUp, {-3, 0, 3}, spec, 0.45);
    const LightingParams both = params(1.0, {1, 0, 1, 1}, 1.5, 0.0, 0.2, 0.3, 7.0);
    expectBoth(kOrigin, kUp, {-3, 0, 3}, both, 0.45 + 0.3 / std::sqrt(2.0));
}

TEST(Lighting, SpecularOffTheHalfVector) {
    // l at 45° from n, v = n: h bisects them, n·h = cos 22.5°, and with s = 2
    // cos² 22.5° = (1 + cos 45°)/2 = (1 + 1/√2)/2.
    const LightingParams p = params(1.0, {1, 0, 1, 1}, 1.0, 0.0, 0.0, 1.0, 2.0);
    expectBoth(kOrigin, kUp, {0, 0, 1}, p, (1.0 + 1.0 / std::sqrt(2.0)) / 2.0);
}

TEST(Lighting, LightBehindTheSurfaceAddsNothing) {
    // l = (5,0,−1)/√26: n·l < 0. v = (−1,0,5)/√26, so l + v = (4,0,4)/√26 and n·h = 1/√2 > 0:
    // the course code would add a highlight; §6 says ambient only, Ia·Ka = 0.5 · 0.2.
    const glm::dvec4 light(5, 0, -1, 1);
    const glm::dvec3 eye(-1, 0, 5);
    const glm::dvec3 h =
        glm::normalize(facet::directionToLight(kOrigin, light) + glm::normalize(eye - kOrigin));
    ASSERT_GT(glm::dot(kUp, h), 0.7);
    for (const double s : {0.0, 1.0, 50.0}) {
        SCOPED_TRACE(s);
        expectBoth(kOrigin, kUp, eye, params(0.5, light, 1.0, 0.2, 1.0, 1.0, s), 0.1);
    }
}

TEST(Lighting, GrazingLightAddsNothing) {
    // A directional light along +x over a surface facing +z: n·l = 0 exactly.
    expectBoth(kOrigin, kUp, {0, 0, 1}, params(0.5, {1, 0, 0, 0}, 1.0, 0.2, 1.0, 1.0, 0.0), 0.1);
}

TEST(Lighting, DirectionalLightIgnoresPosition) {
    // w = 0: l = (1,2,3)/√14 everywhere; n = (1,1,2)/√6, n·l = 9/√84.
    const LightingParams p = params(1.0, {1, 2, 3, 0}, 1.0, 0.0, 1.0, 0.0, 1.0);
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 1, 2));
    expectBoth(kOrigin, n, {5, 5, 5}, p, 9.0 / std::sqrt(84.0));
    expectBoth({-30, 12, 7}, n, {5, 5, 5}, p, 9.0 / std::sqrt(84.0));
    // The direction's length does not matter.
    expectBoth({-30, 12, 7}, n, {5, 5, 5}, params(1.0, {10, 20, 30, 0}, 1.0, 0.0, 1.0, 0.0, 1.0),
               9.0 / std::sqrt(84.0));
}

TEST(Lighting, DirectionalMatchesFarPointLight) {
    const glm::dvec3 p(0.3, -0.2, 0.5);
    const glm::dvec3 n = glm::normalize(glm::dvec3(1, 1, 2));
    const glm::dvec3 eye(2, 1, 4);
    const auto with = [](glm::dvec4 light) { return params(0.3, light, 1.2, 0.5, 0.6, 0.7, 12.0); };
    const double directional = lightD(p, n, eye, with({1, 2, 3, 0}));
    // A point 1e6 away in the same direction, written with w = 1 and with w = 1e-6.
    EXPECT_NEAR(lightD(p, n, eye, with({1e6, 2e6, 3e6, 1})), directional, 1e-5);
    EXPECT_NEAR(lightD(p, n, eye, with({1, 2, 3, 1e-6})), directional, 1e-5);
    EXPECT_NEAR(lightF(p, n, eye, with({1e6, 2e6, 3e6, 1})), directional, 1e-5);
    EXPECT_NEAR(lightF(p, n, eye, with({1, 2, 3, 1e-6})), directional, 1e-5);
    // Beyond float range (and beyond where |xyz/w|² fits a double): still the limit, to the
    // double's rounding and to the float's (I ≈ 1.7 here).
    EXPECT_NEAR(lightD(p, n, eye, with({1e200, 2e200, 3e200, 1})), directional, 1e-12);
    EXPECT_NEAR(lightF(p, n, eye, with({1e200, 2e200, 3e200, 1})), directional, 1e-5);
    EXPECT_NEAR(lightF(p, n, eye, with({1, 2, 3, 1e-60})), directional, 1e-5);
}

TEST(Lighting, FiveNumberLightDividesByW) {
    // (2, 0, 4, w = 2) is the point (1, 0, 2), straight above p = (1, 0, 0): n·l = 1 and
    // I = Id·Kd = 1.25 · 0.8 = 1. Ignoring w (a point at (2,0,4)) would give 4/√17 instead.
    const glm::dvec3 p(1, 0, 0);
    const auto with = [](glm::dvec4 light) { return params(1.0, light, 1.25, 0.0, 0.8, 0.0, 1.0); };
    expectBoth(p, kUp, {1, 0, 9}, with({2, 0, 4, 2}), 1.0);
    expectBoth(p, kUp, {1, 0, 9}, with({1, 0, 2, 1}), 1.0);
    // A negative w names the same point.
    expectBoth(p, kUp, {1, 0, 9}, with({-2, 0, -4, -2}), 1.0);
    // w scales the point, so a light at (4,0,2)/2 = (2,0,1) is 45° off: n·l = 1/√2.
    expectBoth(p, kUp, {1, 0, 9}, with({4, 0, 2, 2}), 1.0 / std::sqrt(2.0));
}

TEST(Lighting, ZeroExponentIsKsWhereLit) {
    // 0^0 = 1: with s = 0 the specular term is Id·Ks wherever n·l > 0.
    // Off the half vector (n·h = cos 22.5°): 2 · 0.3.
    expectBoth(kOrigin, kUp, {0, 0, 1}, params(1.0, {1, 0, 1, 1}, 2.0, 0.0, 0.0, 0.3, 0.0), 0.6);
    // n·h < 0 but n·l = 0.1/√1.01 > 0 (light low on one side, eye below on the other):
    // Id·(Kd·n·l + Ks) = 0.5·0.1/√1.01 + 0.3; with s = 1 the highlight vanishes.
    const glm::dvec4 light(1, 0, 0.1, 0);
    const glm::dvec3 eye(-2, 0, -1);
    const glm::dvec3 h =
        glm::normalize(facet::directionToLight(kOrigin, light) + glm::normalize(eye - kOrigin));
    ASSERT_LT(glm::dot(kUp, h), 0.0);
    const double nl = 0.1 / std::sqrt(1.01);
    expectBoth(kOrigin, kUp, eye, params(1.0, light, 1.0, 0.0, 0.5, 0.3, 0.0), 0.5 * nl + 0.3);
    expectBoth(kOrigin, kUp, eye, params(1.0, light, 1.0, 0.0, 0.5, 0.3, 1.0), 0.5 * nl);
}

TEST(Lighting, HugeExponentsStayFinite) {
    // Light, eye and normal all along +z: n·h = 1 exactly and 1^s = 1 for every s, including
    // +inf: I = Id·(Kd + Ks) = 1·(0.25 + 0.5).
    for (const double s : {1e6, 1e30, kInf}) {
        SCOPED_TRACE(s);
        expectBoth(kOrigin, kUp, {0, 0, 3}, params(1.0, {0, 0, 5, 1}, 1.0, 0.0, 0.25, 0.5, s),
                   0.75);
        // n·h = cos 22.5°: the highlight underflows to 0, leaving the diffuse Kd/√2.
        expectBoth(kOrigin, kUp, {0, 0, 1}, params(1.0, {1, 0, 1, 1}, 1.0, 0.0, 0.25, 0.5, s),
                   0.25 / std::sqrt(2.0));
    }
}

TEST(Lighting, NearlyAlignedHalfVectorNeverExceedsOne) {
    // Rounding may give n·h = 1 + ε; unclamped, (1 + ε)^1e30 would be +inf.
    for (int i = 0; i < 200; ++i) {
        const double a = 0.01 * i;
        const glm::dvec3 l(std::cos(a), 0.0, std::sin(a));
        const glm::dvec3 eye(-std::cos(a), 0.0, std::sin(a));  // mirror image: h = +z
        const LightingParams p = params(1.0, glm::dvec4(l, 0.0), 1.0, 0.0, 0.0, 1.0, 1e30);
        const double d = lightD(kOrigin, kUp, eye, p);
        const double f = lightF(kOrigin, kUp, eye, p);
        EXPECT_TRUE(d >= 0.0 && d <= 1.0) << d;
        EXPECT_TRUE(f >= 0.0 && f <= 1.0) << f;
    }
}

TEST(Lighting, HugeIntensityStaysFiniteInFloat) {
    // Id·Ks = 1e300 does not fit a float; it saturates rather than becoming inf, so where the
    // highlight is 0 (n·h = cos 22.5°, s = +inf) the result is 0 (Ka = Kd = 0), not NaN.
    const double f =
        lightF(kOrigin, kUp, {0, 0, 1}, params(1.0, {1, 0, 1, 1}, 1e300, 0.0, 0.0, 1.0, kInf));
    EXPECT_EQ(f, 0.0);
}

TEST(Lighting, LightOppositeTheEyeHasNoHalfVector) {
    // l = (0,0,1), v = (0,0,−1): l + v = 0, h undefined → n·h taken as 0, no NaN.
    // s > 0: I = Ia·Ka + Id·Kd·n·l = 0.5·0.2 + 0.4. s = 0: plus Id·Ks = 0.7 (0^0 = 1).
    const glm::dvec4 light(0, 0, 1, 1);
    const glm::dvec3 eye(0, 0, -1);
    expectBoth(kOrigin, kUp, eye, params(0.5, light, 1.0, 0.2, 0.4, 0.7, 10.0), 0.5);
    expectBoth(kOrigin, kUp, eye, params(0.5, light, 1.0, 0.2, 0.4, 0.7, kInf), 0.5);
    expectBoth(kOrigin, kUp, eye, params(0.5, light, 1.0, 0.2, 0.4, 0.7, 0.0), 1.2);
    // Tilted normal: n·l = 1/√2.
    expectBoth(kOrigin, glm::normalize(glm::dvec3(1, 0, 1)), eye,
               params(0.5, light, 1.0, 0.2, 0.4, 0.7, 10.0), 0.1 + 0.4 / std::sqrt(2.0));
}

TEST(Lighting, PointAtTheEyeOrAtTheLight) {
    // Eye at the point: v = 0, so h = l = n and the highlight is full: 0.5·0.2 + 0.4 + 0.7.
    const LightingParams p = params(0.5, {0, 0, 2, 1}, 1.0, 0.2, 0.4, 0.7, 10.0);
    expectBoth(kOrigin, kUp, kOrigin, p, 1.2);
    // Light at the point: l = 0, ambient only.
    expectBoth({0, 0, 2}, kUp, {0, 0, 5}, p, 0.1);
    // A directional light with no direction: ambient only.
    expectBoth(kOrigin, kUp, {0, 0, 5}, params(0.5, {0, 0, 0, 0}, 1.0, 0.2, 0.4, 0.7, 10.0), 0.1);
}

TEST(Lighting, FloatMatchesDoubleOnRandomInputs) {
    // std::mt19937's output is fixed by the standard; the distributions are not, so map by hand.
    std::mt19937 rng(20240611u);
    const auto uniform = [&rng](double lo, double hi) {
        return lo + (hi - lo) * (static_cast<double>(rng()) / 4294967296.0);
    };
    const auto inCube = [&uniform](double r) {
        return glm::dvec3(uniform(-r, r), uniform(-r, r), uniform(-r, r));
    };
    int checked = 0;
    double worst = 0.0;
    while (checked < 20000) {
        // Inputs rounded to float first, so both versions see the same numbers.
        const glm::dvec3 p(glm::vec3(inCube(2.0)));
        const glm::dvec3 eye(glm::vec3(inCube(10.0)));
        glm::dvec3 n = inCube(1.0);
        if (glm::length(n) < 0.1) continue;
        n = glm::dvec3(glm::vec3(glm::normalize(n)));
        const double kinds[] = {0.0, 1.0, 0.5, -2.0, uniform(0.1, 3.0)};
        const double w = kinds[rng() % 5];
        const glm::dvec4 light(glm::vec4(glm::dvec4(inCube(10.0), w)));
        const LightingParams lp = params(uniform(0, 1), light, uniform(0, 1), uniform(0, 1),
                                         uniform(0, 1), uniform(0, 1), uniform(0, 16));
        // Skip near-singular geometry, where float rounding of a direction is amplified.
        if (glm::length(eye - p) < 1.0) continue;
        if (w != 0.0 && glm::length(glm::dvec3(light) / w - p) < 1.0) continue;
        if (w == 0.0 && glm::length(glm::dvec3(light)) < 1.0) continue;
        const glm::dvec3 l = facet::directionToLight(p, light);
        if (glm::length(l + glm::normalize(eye - p)) < 0.1) continue;

        const double d = lightD(p, n, eye, lp);
        const double f = lightF(p, n, eye, lp);
        ASSERT_TRUE(std::isfinite(f));
        worst = std::max(worst, std::abs(d - f));
        ++checked;
    }
    EXPECT_LT(worst, 1e-5);
}

TEST(Lighting, ShadeClampsToUnitRange) {
    const glm::dvec3 d = facet::shade(glm::dvec3(0.5, 1.0, 0.2), 1.5);
    EXPECT_DOUBLE_EQ(d.x, 0.75);
    EXPECT_DOUBLE_EQ(d.y, 1.0);
    EXPECT_DOUBLE_EQ(d.z, 0.3);
    const glm::vec3 f = facet::shade(glm::vec3(0.5f, 1.0f, 0.2f), 1.5f);
    EXPECT_FLOAT_EQ(f.x, 0.75f);
    EXPECT_FLOAT_EQ(f.y, 1.0f);
    EXPECT_FLOAT_EQ(f.z, 0.3f);
    EXPECT_EQ(facet::shade(glm::vec3(0.5f), -1.0f), glm::vec3(0.0f));
}

TEST(Lighting, FastConstantsFoldTheSceneLighting) {
    facet::Scene scene;
    scene.lighting.ambient = 0.25;
    scene.lighting.light.position = {1, 2, 3, 0};
    scene.lighting.light.intensity = 2.0;
    scene.lighting.material = facet::Material{0.1, 0.2, 0.3, 40.0};
    EXPECT_EQ(scene.lighting, params(0.25, {1, 2, 3, 0}, 2.0, 0.1, 0.2, 0.3, 40.0));
    EXPECT_NE(scene.lighting, params(0.25, {1, 2, 3, 0}, 2.0, 0.1, 0.2, 0.3, 41.0));

    // Folded constants: Ia·Ka, Id·Kd, Id·Ks, s, and the light rescaled to max |component| 1.
    const facet::FastLighting f = facet::prepareLighting(scene.lighting);
    EXPECT_FLOAT_EQ(f.ambientTerm, 0.025f);
    EXPECT_FLOAT_EQ(f.diffuse, 0.4f);
    EXPECT_FLOAT_EQ(f.specular, 0.6f);
    EXPECT_FLOAT_EQ(f.shininess, 40.0f);
    EXPECT_FLOAT_EQ(f.light.x, 1.0f / 3.0f);
    EXPECT_FLOAT_EQ(f.light.z, 1.0f);
    EXPECT_EQ(f.light.w, 0.0f);
    const facet::FastLighting g =
        facet::prepareLighting(params(1.0, {-2, 0, -4, -2}, 1.0, 0.0, 0.0, 0.0, 1.0));
    EXPECT_EQ(g.light, glm::vec4(0.5f, 0.0f, 1.0f, 0.5f));
}

}  // namespace
