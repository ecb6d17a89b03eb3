// The vector bilinear sampler (bilinearPackedLanes) against the scalar one it copies,
// packColor(sampleBilinear()), bit for bit, on every SIMD target this CPU has: texture sizes down
// to one texel, coordinates on texel centres and edges, across the wrap at the right and bottom
// edges, NaN, infinities and huge values. Vectors whose lanes all read neighbouring texel pairs
// (the 64-bit pair gathers of AVX2 and AVX-512) and vectors with one wrapping lane in every
// position (the per-texel gathers) are both covered. Compiled once per target, like the engine's
// loops (hwy/foreach_target.h re-includes this file).

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "engine/texture_lanes_test.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

#include <hwy/highway.h>

#include "shading/texture_lanes-inl.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {

/// bilinearPackedLanes() over (u, v)[0 … count) (count a multiple of 16) into out.
void bilinearAll(const MipLevel& level, const float* u, const float* v, std::size_t count,
                 std::uint32_t* out) {
    const Df d;
    for (std::size_t i = 0; i < count; i += kLanes)
        hn::StoreU(
            hn::BitCast(Du(), bilinearPackedLanes(level, hn::LoadU(d, u + i), hn::LoadU(d, v + i))),
            Du(), out + i);
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "every_target.hpp"

#include "shading/fragment.hpp"
#include "shading/samplers.hpp"

namespace facet::detail {

HWY_EXPORT(bilinearAll);

namespace {

using test::onEveryTarget;

/// A w × h texture of random texels, alpha included (it must not leak into the colour).
Texture randomTexture(int w, int h, std::mt19937& rng) {
    std::vector<std::uint32_t> px(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (std::uint32_t& p : px) p = static_cast<std::uint32_t>(rng());
    Result<Texture> t = Texture::fromRgba(w, h, std::move(px), "random");
    EXPECT_TRUE(static_cast<bool>(t));
    return std::move(t).value();
}

/// Coordinates for a w × h texture, in groups of 16 lanes.
struct Coords {
    std::vector<float> u, v;
    void add(float a, float b) {
        u.push_back(a);
        v.push_back(b);
    }
    void pad() {
        while (u.size() % 16 != 0) add(0.5f, 0.5f);
    }
};

Coords coordsFor(int w, int h, std::mt19937& rng) {
    const float fw = static_cast<float>(w), fh = static_cast<float>(h);
    Coords c;
    // Whole vectors inside the texture (x0 in [0, w − 2] in every lane), the last one reading the
    // last texel pair of the bottom row: the pair gathers.
    std::uniform_real_distribution<float> inside(0.5f / fw, (fw - 0.5f) / fw);
    std::uniform_real_distribution<float> any(-3.0f, 3.0f);
    for (int i = 0; i < 64 * 16; ++i) c.add(inside(rng), any(rng));
    for (int i = 0; i < 16; ++i) c.add((fw - 1.0f) / fw, (fh - 0.25f) / fh);
    // One lane at the left or right seam in each position of a vector: the wrapping gathers.
    for (const float edge : {0.1f / fw, 1.0f - 0.1f / fw, 0.0f, 1.0f}) {
        for (int lane = 0; lane < 16; ++lane)
            for (int i = 0; i < 16; ++i) c.add(i == lane ? edge : inside(rng), any(rng));
    }
    // Texel centres, corners and the seams of a grid over two periods, negative ones included.
    for (int j = -2 * h; j <= 2 * h; ++j)
        for (int i = -2 * w; i <= 2 * w; ++i) {
            c.add((static_cast<float>(i) + 0.5f) / fw, (static_cast<float>(j) + 0.5f) / fh);
            c.add(static_cast<float>(i) / fw, static_cast<float>(j) / fh);
        }
    // Tiny negatives (wrapCoord rounds them up to 1), zeros of both signs, huge, non-finite.
    const float inf = std::numeric_limits<float>::infinity();
    const float specials[] = {0.0f,   -0.0f,      1.0f,       -1.0f,         -1e-30f,     -1e-7f,
                              1e-30f, 0.9999999f, 8388607.5f, 8388608.0f,    -8388609.0f, 3e9f,
                              -3e9f,  inf,        -inf,       std::nanf(""), 1e38f,       -1e38f};
    for (const float a : specials)
        for (const float b : specials) c.add(a, b);
    for (const float a : specials) c.add(a, inside(rng));
    for (int i = 0; i < 4096; ++i) c.add(any(rng), any(rng));
    c.pad();
    return c;
}

TEST(TextureLanes, BilinearLanesAreTheScalarSamplerOnEveryTarget) {
    std::mt19937 rng(22);
    const int sizes[][2] = {{1, 1}, {1, 5}, {5, 1}, {2, 2}, {3, 7}, {37, 29}, {64, 64}};
    for (const auto& s : sizes) {
        const Texture tex = randomTexture(s[0], s[1], rng);
        const Coords c = coordsFor(s[0], s[1], rng);
        std::vector<std::uint32_t> expected(c.u.size()), out(c.u.size());
        for (std::size_t i = 0; i < c.u.size(); ++i)
            expected[i] = packColor(sampleBilinear(tex, {c.u[i], c.v[i]}, 0));
        onEveryTarget([&](const char* name) {
            HWY_DYNAMIC_DISPATCH(bilinearAll)
            (tex.level(0), c.u.data(), c.v.data(), c.u.size(), out.data());
            std::size_t differ = 0, first = 0;
            for (std::size_t i = 0; i < out.size(); ++i)
                if (out[i] != expected[i] && differ++ == 0) first = i;
            EXPECT_EQ(differ, 0u) << name << ", " << s[0] << "x" << s[1] << ", first at uv ("
                                  << c.u[first] << ", " << c.v[first] << ")";
        });
    }
}

}  // namespace
}  // namespace facet::detail
#endif  // HWY_ONCE
