// Phong's lane functions against the scalar ones they copy, bit for bit, on every SIMD target this
// CPU has: unitPowLanes() against unitPow() and rsqrtLanes() against fastRsqrt(), over dense
// grids of inputs (the images in simd_targets_test only reach the values a scene produces).
// Compiled once per target, like the engine's loops (hwy/foreach_target.h re-includes this file).

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "engine/lighting_lanes_test.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

#include <hwy/highway.h>

#include "shading/lanes-inl.hpp"
#include "shading/unit_pow-inl.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {

/// unitPowLanes() over x[0 … count) (count a multiple of 16) into out.
void unitPowAll(const float* x, std::size_t count, float s, float* out) {
    const Df d;
    for (std::size_t i = 0; i < count; i += kLanes)
        hn::StoreU(unitPowLanes(hn::LoadU(d, x + i), s), d, out + i);
}

/// rsqrtLanes() over x[0 … count), x > 0 (count a multiple of 16), into out.
void rsqrtAll(const float* x, std::size_t count, float* out) {
    const Df d;
    for (std::size_t i = 0; i < count; i += kLanes)
        hn::StoreU(rsqrtLanes(hn::LoadU(d, x + i)), d, out + i);
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "every_target.hpp"

#include "shading/fast_lighting.hpp"
#include "shading/unit_pow.hpp"

namespace facet::detail {

HWY_EXPORT(unitPowAll);
HWY_EXPORT(rsqrtAll);

namespace {

/// The inputs padded with ones to a multiple of 16 lanes.
void pad(std::vector<float>& x) {
    while (x.size() % 16 != 0) x.push_back(1.0f);
}

using test::onEveryTarget;

std::uint32_t bitsOf(float v) {
    return std::bit_cast<std::uint32_t>(v);
}

// x over [0, 1] on a 2^-20 grid, every float in (0.98, 1], subnormals, zero, NaN and a negative
// value; the exponents of unit_pow_test, zero and infinity. Not x > 1: outside unitPow's domain
// (the loops clamp n·h to [0, 1] first), where s·log2 x overflows the exponent's integer.
TEST(LightingLanes, UnitPowLanesIsUnitPowOnEveryTarget) {
    std::vector<float> x;
    for (int i = 0; i <= 1 << 20; ++i) x.push_back(static_cast<float>(i) / (1 << 20));
    for (float v = 1.0f; v > 0.98f; v = std::nextafter(v, 0.0f)) x.push_back(v);
    for (std::uint32_t bits = 1; bits < 0x00800000u; bits += 4099)
        x.push_back(std::bit_cast<float>(bits));
    x.insert(x.end(), {0.0f, -0.0f, 1e-30f, 1.17549435e-38f, std::nanf(""), -0.5f});
    pad(x);
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<float> out(x.size());
    onEveryTarget([&](const char* name) {
        for (const float s : {0.0f, 0.5f, 1.0f, 3.7f, 20.0f, 30.0f, 128.0f, 1000.0f, inf}) {
            HWY_DYNAMIC_DISPATCH(unitPowAll)(x.data(), x.size(), s, out.data());
            std::size_t differ = 0;
            for (std::size_t i = 0; i < x.size(); ++i)
                if (bitsOf(out[i]) != bitsOf(unitPow(x[i], s)) &&
                    !(std::isnan(out[i]) && std::isnan(unitPow(x[i], s))))
                    ++differ;
            EXPECT_EQ(differ, 0u) << name << ", s = " << s;
        }
    });
}

// Every 97th positive float, subnormals included, and every float in [1, 4).
TEST(LightingLanes, RsqrtLanesIsFastRsqrtOnEveryTarget) {
    std::vector<float> x;
    for (std::uint32_t bits = 1; bits < 0x7F800000u; bits += 97)
        x.push_back(std::bit_cast<float>(bits));
    for (float v = 1.0f; v < 4.0f; v = std::nextafter(v, 4.0f)) x.push_back(v);
    pad(x);
    std::vector<float> out(x.size());
    onEveryTarget([&](const char* name) {
        HWY_DYNAMIC_DISPATCH(rsqrtAll)(x.data(), x.size(), out.data());
        std::size_t differ = 0;
        for (std::size_t i = 0; i < x.size(); ++i)
            if (bitsOf(out[i]) != bitsOf(fastRsqrt(x[i]))) ++differ;
        EXPECT_EQ(differ, 0u) << name;
    });
}

// specularSkip()'s claim: on a lit lane with n·h ≤ maxNh and diffuse a ≥ minDiffuse, the float
// sum a + specular·unitPow(n·h, s) is a, so the vector loops may leave the power out. Checked at
// the smallest a allowed and at the float below the next power of two (where a float step is
// smallest relative to a), for every float up to 2^12 steps below maxNh and a grid under it.
TEST(LightingLanes, SpecularSkipLeavesTheSumUnchanged) {
    std::size_t enabled = 0, nonzero = 0;
    for (const float diffuse : {0.63f, 1.0f, 0.01f, 1e-20f})
        for (const float specular : {0.27f, 1.0f, 100.0f, 1e-3f})
            for (const float s : {0.25f, 1.0f, 5.0f, 30.0f, 128.0f, 1000.0f, 10000.0f}) {
                const SpecularSkip skip = specularSkip(diffuse, specular, s);
                if (skip.maxNh < 0.0f) continue;
                ++enabled;
                ASSERT_GE(skip.minDiffuse, diffuse / 16.0f);
                const float nextPower = std::exp2(std::floor(std::log2(skip.minDiffuse)) + 1.0f);
                const float as[] = {skip.minDiffuse, std::nextafter(nextPower, 0.0f),
                                    skip.minDiffuse * 1.5f};
                std::vector<float> x;
                float v = std::min(skip.maxNh, 1.0f);
                for (int i = 0; i < 4096 && v > 0.0f; ++i, v = std::nextafter(v, 0.0f))
                    x.push_back(v);
                for (int i = 0; i <= 1 << 14; ++i)
                    x.push_back(std::min(skip.maxNh, 1.0f) * static_cast<float>(i) / (1 << 14));
                std::size_t differ = 0;
                for (const float a : as)
                    for (const float nh : x) {
                        const float b = specular * unitPow(nh, s);
                        if (b > 0.0f) ++nonzero;
                        if (bitsOf(a + b) != bitsOf(a)) ++differ;
                    }
                EXPECT_EQ(differ, 0u) << "diffuse " << diffuse << ", specular " << specular
                                      << ", s = " << s << ", maxNh " << skip.maxNh;
            }
    EXPECT_GT(enabled, 50u);
    EXPECT_GT(nonzero, 1000000u);  // the sums checked are not all a + 0
    // Spot's lighting (Id·Kd 0.63, Id·Ks 0.27, s = 30): the power is left out below n·h ≈ 0.53.
    EXPECT_GT(specularSkip(0.63f, 0.27f, 30.0f).maxNh, 0.4f);
    // Nothing skipped where the bound does not hold or means nothing.
    EXPECT_LT(specularSkip(0.0f, 0.27f, 30.0f).maxNh, 0.0f);
    EXPECT_LT(specularSkip(0.63f, 0.0f, 30.0f).maxNh, 0.0f);
    EXPECT_LT(specularSkip(0.63f, 0.27f, 0.0f).maxNh, 0.0f);
    EXPECT_LT(specularSkip(0.63f, 0.27f, std::nanf("")).maxNh, 0.0f);
}

}  // namespace
}  // namespace facet::detail
#endif  // HWY_ONCE
