// Phong's pow without libm (shading/unit_pow.hpp) against pow in double: its error in 8-bit
// steps over x in [0, 1] and exponents up to 1000, and the special cases std::pow defines. Then
// Phong's normalisations without sqrt or division (fastRsqrt, shading/fast_lighting.hpp).

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

#include "shading/fast_lighting.hpp"
#include "shading/unit_pow.hpp"

namespace facet::detail {
namespace {

constexpr float kExponents[] = {0.5f,  1.0f,  2.0f,   3.7f,   8.0f,   10.0f,  20.0f,  32.0f,
                                50.0f, 64.0f, 100.0f, 128.0f, 200.0f, 500.0f, 999.0f, 1000.0f};

/// The largest |unitPow − pow| in units of 1/255 over a dense grid of x, fine near 1 where
/// high exponents have their highlight.
double maxErrorLsb(float s) {
    double worst = 0.0;
    auto check = [&](float x) {
        const double exact = std::pow(static_cast<double>(x), static_cast<double>(s));
        worst = std::max(worst, 255.0 * std::fabs(static_cast<double>(unitPow(x, s)) - exact));
    };
    for (int i = 0; i <= 1 << 20; ++i) check(static_cast<float>(i) / static_cast<float>(1 << 20));
    for (float x = 1.0f; x > 0.98f; x = std::nextafter(x, 0.0f)) check(x);  // every float
    return worst;
}

TEST(UnitPow, WithinAThousandthOfAStepOfTheDoublePow) {
    double overall = 0.0;
    for (const float s : kExponents) {
        const double lsb = maxErrorLsb(s);
        EXPECT_LT(lsb, 1e-3) << "s = " << s;
        overall = std::max(overall, lsb);
    }
    // The largest error, for the log.
    std::printf("unitPow: largest error %.2e of an 8-bit step for s in [0.5, 1000]\n", overall);
}

TEST(UnitPow, SpecialCasesAsStdPow) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(unitPow(1.0f, 1000.0f), 1.0f);
    EXPECT_EQ(unitPow(1.0f, inf), 1.0f);
    EXPECT_EQ(unitPow(0.0f, 0.0f), 1.0f);
    EXPECT_EQ(unitPow(0.5f, 0.0f), 1.0f);
    EXPECT_EQ(unitPow(0.0f, 5.0f), 0.0f);
    EXPECT_EQ(unitPow(0.999f, inf), 0.0f);
    EXPECT_EQ(unitPow(1e-30f, 10.0f), 0.0f);
    EXPECT_TRUE(std::isnan(unitPow(nan, 2.0f)));
    EXPECT_EQ(unitPow(0.5f, 1.0f), 0.5f);
    EXPECT_EQ(unitPow(0.25f, 0.5f), 0.5f);
    // Subnormal bases: scaled into range, not read as 2^-127.
    EXPECT_NEAR(unitPow(1e-40f, 0.01f), std::pow(1e-40, 0.01), 1e-6);
}

// Every 97th float from the smallest subnormal to the largest finite one, and every float in
// [1, 4) (a whole cycle of the guess, which repeats per factor 4).
TEST(FastRsqrt, WithinFiveMillionthsOfTheDoubleEverywhere) {
    double worst = 0.0;
    auto check = [&](float x) {
        const double exact = 1.0 / std::sqrt(static_cast<double>(x));
        const double error = std::fabs(static_cast<double>(fastRsqrt(x)) / exact - 1.0);
        if (!(error <= worst)) worst = error;  // NaN counts
    };
    for (std::uint32_t bits = 1; bits < 0x7F800000u; bits += 97) check(std::bit_cast<float>(bits));
    for (float x = 1.0f; x < 4.0f; x = std::nextafter(x, 4.0f)) check(x);
    EXPECT_LT(worst, 5e-6);
    std::printf("fastRsqrt: largest relative error %.2e\n", worst);
}

TEST(FastRsqrt, InverseLengthMakesUnitVectorsAndZeroOfZero) {
    for (const glm::vec3 v : {glm::vec3(3.0f, 4.0f, 0.0f), glm::vec3(1e-20f, 0.0f, 0.0f),
                              glm::vec3(-1e-3f, 2e-3f, 5.0f), glm::vec3(1e18f, -1e18f, 1e17f)}) {
        const glm::vec3 n = v * inverseLength(v);
        EXPECT_NEAR(glm::dot(n, n), 1.0f, 1e-5f) << v.x << " " << v.y << " " << v.z;
        EXPECT_GT(glm::dot(n, v), 0.0f);
    }
    EXPECT_EQ(inverseLength(glm::vec3(0.0f)), 0.0f);
    EXPECT_EQ(inverseLength(glm::vec3(std::nanf(""), 0.0f, 0.0f)), 0.0f);
}

}  // namespace
}  // namespace facet::detail
