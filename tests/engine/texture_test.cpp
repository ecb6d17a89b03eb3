// Textures (spec §7): wrapping of extreme and non-finite coordinates, exactness of
// filtering at texel centres and borders, the mip chain's sizes and contents, the level of
// detail, fast samplers against the double-precision reference, and loading (good files, the
// shared data, and every kind of bad file).
//
// tests/data/tex_* were written by a throwaway script; their contents are spelled out where
// tests rely on them:
//   tex_4x4.png       RGBA, texel (x, y) = (40x + 10y, 255 − 60x, 80y, 255), alpha 128 at (3, 3)
//   tex_gray_3x2.png  8-bit grey, rows 0 51 102 / 153 204 255
//   tex_5x3.bmp       24-bit, bottom-up rows, texel (x, y) = (50x, 100y, 7)
//   tex_2x2.tga       32-bit, bottom-up rows: top red green, bottom blue white
//   tex_truncated.png the first 65 bytes of tex_4x4.png (cut inside the image data)
//   tex_huge.png      a valid header claiming 20000×20000
//   tex_wide.png      a valid header claiming 16385×1
//   tex_zero_width.png a header claiming 0×4

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "facet/camera.hpp"
#include "facet/framebuffer.hpp"
#include "facet/texture.hpp"
#include "reference/samplers.hpp"
#include "shading/samplers.hpp"
#include "shared_data.hpp"
#include "test_files.hpp"

namespace facet {
namespace {

using facet::test::sharedData;
using facet::test::testData;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kLsb = 1.0 / 255.0;

/// A texture whose texel (x, y) is fn(x, y), packed RGBA.
template <class Fn>
Texture makeTexture(int w, int h, Fn fn) {
    std::vector<std::uint32_t> px;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) px.push_back(fn(x, y));
    Result<Texture> t = Texture::fromRgba(w, h, std::move(px), "test");
    EXPECT_TRUE(t.ok()) << t.error().what();
    return std::move(t).value();
}

/// Every texel distinct in some channel; values spread over 0..255.
Texture distinctTexture(int w, int h) {
    return makeTexture(w, h, [](int x, int y) {
        return packRgba(static_cast<std::uint32_t>(37 * x + 11 * y) % 256,
                        static_cast<std::uint32_t>(5 * x + 71 * y + 3) % 256,
                        static_cast<std::uint32_t>(x * y * 13 + 100) % 256);
    });
}

Texture randomTexture(int w, int h, std::uint32_t seed) {
    std::mt19937 rng(seed);
    return makeTexture(w, h,
                       [&](int, int) { return static_cast<std::uint32_t>(rng()) | 0xFF000000u; });
}

/// The 8-bit channel values of an RGBA-packed texel.
glm::vec3 bytes(std::uint32_t p) {
    return {static_cast<float>(p & 0xFF), static_cast<float>((p >> 8) & 0xFF),
            static_cast<float>((p >> 16) & 0xFF)};
}

::testing::AssertionResult sameColor(glm::vec3 a, glm::vec3 b) {
    if (a == b) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                         << b.x << ", " << b.y << ", " << b.z << ")";
}

::testing::AssertionResult nearColor(glm::vec3 a, glm::dvec3 b, double tol) {
    const double d = std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
    if (d <= tol) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "(" << a.x << ", " << a.y << ", " << a.z << ") vs ("
                                         << b.x << ", " << b.y << ", " << b.z << "), off by " << d;
}

// ---- Wrapping -------------------------------------------------------------------------------

TEST(TextureWrap, RepeatsWithFloor) {
    EXPECT_EQ(wrapCoord(0.0f), 0.0f);
    EXPECT_EQ(wrapCoord(1.0f), 0.0f);
    EXPECT_EQ(wrapCoord(2.5f), 0.5f);
    EXPECT_EQ(wrapCoord(-0.25f), 0.75f);
    EXPECT_EQ(wrapCoord(-3.0f), 0.0f);
    EXPECT_EQ(wrapCoord(-0.0f), 0.0f);
    EXPECT_EQ(wrapCoord(1e6f), 0.0f);
    EXPECT_EQ(wrapCoord(1e6f + 0.25f), 0.25f);  // 1000000.25 is a float: the fraction survives
    EXPECT_EQ(wrapCoord(-1e6f - 0.25f), 0.75f);
    // A tiny negative coordinate is just left of the seam; in float it rounds to exactly 1.
    EXPECT_EQ(wrapCoord(-1e-9f), 1.0f);
}

TEST(TextureWrap, NonFiniteAndHugeGiveZero) {
    for (float t : {kNaN, -kNaN, kInf, -kInf, 1e30f, -1e30f, 8388608.0f, -8388609.0f,
                    std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest()}) {
        EXPECT_EQ(wrapCoord(t), 0.0f) << t;
        EXPECT_EQ(reference::wrapCoord(static_cast<double>(t)), 0.0) << t;
    }
}

TEST(TextureWrap, StaysInUnitIntervalEverywhere) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> any(-1e7f, 1e7f);
    std::uniform_real_distribution<float> small(-2.0f, 2.0f);
    for (int i = 0; i < 100000; ++i) {
        for (float t : {any(rng), small(rng)}) {
            const float w = wrapCoord(t);
            ASSERT_GE(w, 0.0f) << t;
            ASSERT_LE(w, 1.0f) << t;
            // The same single rounding of t − ⌊t⌋ as in double.
            ASSERT_EQ(w, static_cast<float>(reference::wrapCoord(static_cast<double>(t)))) << t;
        }
    }
}

// ---- Nearest --------------------------------------------------------------------------------

TEST(TextureNearest, SpecialCoordinates) {
    const Texture tex = distinctTexture(4, 4);
    const MipLevel& l = tex.level(0);
    EXPECT_TRUE(sameColor(sampleNearest(tex, {0.0f, 0.0f}), texelColor(l, 0, 0)));
    EXPECT_TRUE(sameColor(sampleNearest(tex, {1.0f, 1.0f}), texelColor(l, 0, 0)));  // wraps
    EXPECT_TRUE(sameColor(sampleNearest(tex, {-0.25f, 0.0f}), texelColor(l, 3, 0)));
    EXPECT_TRUE(sameColor(sampleNearest(tex, {0.0f, -0.25f}), texelColor(l, 0, 3)));
    EXPECT_TRUE(sameColor(sampleNearest(tex, {1e6f, 1e6f}), texelColor(l, 0, 0)));
    EXPECT_TRUE(sameColor(sampleNearest(tex, {1e6f + 0.5f, 0.25f}), texelColor(l, 2, 1)));
    EXPECT_TRUE(sameColor(sampleNearest(tex, {1e30f, -1e30f}), texelColor(l, 0, 0)));
    // NaN and infinities are documented to read as 0 on their axis.
    EXPECT_TRUE(sameColor(sampleNearest(tex, {kNaN, 0.6f}), texelColor(l, 0, 2)));
    EXPECT_TRUE(sameColor(sampleNearest(tex, {0.6f, kNaN}), texelColor(l, 2, 0)));
    EXPECT_TRUE(sameColor(sampleNearest(tex, {kInf, -kInf}), texelColor(l, 0, 0)));
    // u' rounds to exactly 1 here: the clamp keeps it on the last column, left of the seam.
    EXPECT_TRUE(sameColor(sampleNearest(tex, {-1e-9f, -1e-9f}), texelColor(l, 3, 3)));
}

TEST(TextureNearest, PicksTheTexelAtBorders) {
    for (int w : {4, 5, 7}) {
        const Texture tex = distinctTexture(w, 3);
        const MipLevel& l = tex.level(0);
        for (int i = 0; i < w; ++i) {
            // A border belongs to the texel on its right; just below it, to the one on its left.
            const float border = static_cast<float>(i) / static_cast<float>(w);
            const float below = std::nextafter(border, -1.0f);
            const int at =
                std::min(static_cast<int>(std::floor(border * static_cast<float>(w))), w - 1);
            EXPECT_TRUE(sameColor(sampleNearest(tex, {border, 0.0f}), texelColor(l, at, 0)))
                << "w=" << w << " i=" << i;
            EXPECT_TRUE(sameColor(sampleNearest(tex, {below, 0.0f}),
                                  texelColor(l, i == 0 ? w - 1 : at - 1, 0)))
                << "w=" << w << " i=" << i;
            // Texel centres are unambiguous.
            const float centre = (static_cast<float>(i) + 0.5f) / static_cast<float>(w);
            EXPECT_TRUE(sameColor(sampleNearest(tex, {centre, 0.0f}), texelColor(l, i, 0)));
        }
    }
}

// ---- Bilinear -------------------------------------------------------------------------------

TEST(TextureBilinear, TexelCentresReturnTexelsExactly) {
    // Power-of-two sides make every centre (i + ½)/W a float, also after adding whole tiles.
    const Texture tex = distinctTexture(8, 4);
    for (int level = 0; level < tex.levelCount(); ++level) {
        const MipLevel& l = tex.level(level);
        for (int j = 0; j < l.height; ++j) {
            for (int i = 0; i < l.width; ++i) {
                const float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(l.width);
                const float v = (static_cast<float>(j) + 0.5f) / static_cast<float>(l.height);
                for (float tile : {0.0f, 1.0f, -2.0f, 4096.0f}) {
                    const glm::vec3 c = sampleBilinear(tex, {u + tile, v - tile}, level);
                    ASSERT_TRUE(sameColor(c, texelColor(l, i, j)))
                        << "level " << level << " texel " << i << "," << j << " tile " << tile;
                    // ...and that colour is the stored byte, to the last bit of rounding.
                    const glm::vec3 b = bytes(l.at(i, j));
                    EXPECT_EQ(glm::vec3(std::round(c.x * 255.0f), std::round(c.y * 255.0f),
                                        std::round(c.z * 255.0f)),
                              b);
                }
                EXPECT_TRUE(sameColor(sampleTrilinear(tex, {u, v}, static_cast<float>(level)),
                                      texelColor(l, i, j)));
            }
        }
    }
}

TEST(TextureBilinear, TexelCentresOfOddSizesWithinRounding) {
    // (i + ½)/W is rounded for other sides; the error is a float ulp, far below one 8-bit step.
    const Texture tex = distinctTexture(7, 5);
    const MipLevel& l = tex.level(0);
    for (int j = 0; j < 5; ++j) {
        for (int i = 0; i < 7; ++i) {
            const glm::vec2 uv((static_cast<float>(i) + 0.5f) / 7.0f,
                               (static_cast<float>(j) + 0.5f) / 5.0f);
            EXPECT_TRUE(nearColor(sampleBilinear(tex, uv), reference::texelColor(l, i, j), 1e-5));
        }
    }
}

TEST(TextureBilinear, FullTexelsMapToZeroAndOne) {
    // Filtering works on bytes and scales once by 1/255: 255 must give exactly 1, and every
    // byte must come back from the float colour.
    const Texture tex = makeTexture(16, 16, [](int x, int y) {
        const auto b = static_cast<std::uint32_t>(16 * y + x);
        return packRgba(b, 255 - b, b);
    });
    for (int b = 0; b < 256; ++b) {
        const glm::vec3 c = texelColor(tex.level(0), b % 16, b / 16);
        EXPECT_EQ(std::lround(c.x * 255.0f), b);
        EXPECT_EQ(std::lround(c.y * 255.0f), 255 - b);
        EXPECT_LE(c.x, 1.0f);
    }
    EXPECT_EQ(texelColor(tex.level(0), 15, 15).x, 1.0f);
    EXPECT_EQ(texelColor(tex.level(0), 0, 0).y, 1.0f);
}

TEST(TextureBilinear, BlendsAcrossTheSeam) {
    // Columns: 0 is black, the last is white, the rest grey; rows likewise for green.
    const int w = 4, h = 4;
    const Texture tex = makeTexture(w, h, [](int x, int y) {
        return packRgba(x == 0 ? 0 : x == 3 ? 255 : 100, y == 0 ? 0 : y == 3 ? 255 : 100, 0);
    });
    // u = 0 is the border between the last and the first column: half of each.
    EXPECT_NEAR(sampleBilinear(tex, {0.0f, 0.5f}).x, 0.5f, 1e-6f);
    EXPECT_NEAR(sampleBilinear(tex, {1.0f, 0.5f}).x, 0.5f, 1e-6f);
    // Slightly below 1: mostly the last column, a quarter of the first.
    const float u = 1.0f - 0.25f / w;  // a quarter texel left of the seam
    EXPECT_NEAR(sampleBilinear(tex, {u, 0.5f}).x, 0.75f, 1e-6f);
    EXPECT_NEAR(sampleBilinear(tex, {u - 3.0f, 0.5f}).x, 0.75f, 1e-6f);
    // Slightly above 0: mostly the first column.
    EXPECT_NEAR(sampleBilinear(tex, {0.25f / w, 0.5f}).x, 0.25f, 1e-6f);
    // The same along v.
    EXPECT_NEAR(sampleBilinear(tex, {0.5f, 1.0f - 0.25f / h}).y, 0.75f, 1e-6f);
    EXPECT_NEAR(sampleBilinear(tex, {0.5f, -0.25f / h}).y, 0.75f, 1e-6f);
    // Exactly on the last and first centres: no bleeding from the other side.
    EXPECT_EQ(sampleBilinear(tex, {0.875f, 0.5f}).x, 1.0f);
    EXPECT_EQ(sampleBilinear(tex, {0.125f, 0.5f}).x, 0.0f);
    // Non-finite coordinates read as 0: the seam blend.
    EXPECT_TRUE(sameColor(sampleBilinear(tex, {kNaN, kInf}), sampleBilinear(tex, {0.0f, 0.0f})));
    EXPECT_TRUE(sameColor(sampleBilinear(tex, {1e30f, -1e30f}), sampleBilinear(tex, {0, 0})));
    EXPECT_TRUE(sameColor(sampleBilinear(tex, {1e6f, 1e6f}), sampleBilinear(tex, {0, 0})));
}

TEST(TextureBilinear, LevelIsClampedToTheChain) {
    const Texture tex = distinctTexture(8, 8);
    const glm::vec2 uv(0.3f, 0.7f);
    EXPECT_TRUE(sameColor(sampleBilinear(tex, uv, -5), sampleBilinear(tex, uv, 0)));
    EXPECT_TRUE(sameColor(sampleBilinear(tex, uv, 99), sampleBilinear(tex, uv, 3)));
}

TEST(TextureBilinear, OneTexelTexture) {
    const Texture tex = makeTexture(1, 1, [](int, int) { return packRgba(10, 20, 30); });
    EXPECT_EQ(tex.levelCount(), 1);
    for (glm::vec2 uv : {glm::vec2(0, 0), glm::vec2(0.999f, 0.5f), glm::vec2(-7.3f, kNaN)}) {
        EXPECT_TRUE(sameColor(sampleBilinear(tex, uv), texelColor(tex.level(0), 0, 0)));
        EXPECT_TRUE(sameColor(sampleNearest(tex, uv), texelColor(tex.level(0), 0, 0)));
        EXPECT_TRUE(sameColor(sampleTrilinear(tex, uv, 3.0f), texelColor(tex.level(0), 0, 0)));
    }
}

TEST(TextureBilinear, DefaultTextureIsWhite) {
    const Texture tex;
    EXPECT_EQ(tex.width(), 1);
    EXPECT_EQ(tex.height(), 1);
    EXPECT_EQ(sampleBilinear(tex, {0.3f, 0.9f}), glm::vec3(1.0f));
    EXPECT_EQ(sampleNearest(tex, {kNaN, 2.0f}), glm::vec3(1.0f));
    EXPECT_EQ(sampleTrilinear(tex, {0.1f, 0.1f}, {1.0f, 0.0f}, {0.0f, 1.0f}), glm::vec3(1.0f));
}

// ---- Mip chain ------------------------------------------------------------------------------

TEST(TextureMips, ChainOfAKnownImage) {
    const Result<Texture> t = loadTexture(testData("tex_4x4.png"));
    ASSERT_TRUE(t.ok()) << t.error().what();
    ASSERT_EQ(t->levelCount(), 3);
    const MipLevel& l0 = t->level(0);
    const MipLevel& l1 = t->level(1);
    const MipLevel& l2 = t->level(2);
    EXPECT_EQ(l0.width, 4);
    EXPECT_EQ(l1.width, 2);
    EXPECT_EQ(l1.height, 2);
    EXPECT_EQ(l2.width, 1);
    EXPECT_EQ(l2.height, 1);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_EQ(l0.at(x, y),
                      packRgba(static_cast<std::uint32_t>(40 * x + 10 * y),
                               static_cast<std::uint32_t>(255 - 60 * x),
                               static_cast<std::uint32_t>(80 * y), x == 3 && y == 3 ? 128 : 255));
    // Each level-1 texel is the mean of a 2×2 block: R = 80i + 20j + 25, G = 225 − 120i,
    // B = 160j + 40; alpha (3·255 + 128)/4 = 223.25 rounds to 223 in the last block.
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
            EXPECT_EQ(l1.at(i, j), packRgba(static_cast<std::uint32_t>(80 * i + 20 * j + 25),
                                            static_cast<std::uint32_t>(225 - 120 * i),
                                            static_cast<std::uint32_t>(160 * j + 40),
                                            i == 1 && j == 1 ? 223 : 255))
                << i << "," << j;
    // The 1×1 level averages level 1: (75, 165, 120), alpha (3·255 + 223)/4 = 247.
    EXPECT_EQ(l2.at(0, 0), packRgba(75, 165, 120, 247));
}

TEST(TextureMips, RoundsHalfUp) {
    const Texture tex = makeTexture(2, 2, [](int x, int y) {
        return packRgba(x + y == 0 ? 1 : 0, 3 * static_cast<std::uint32_t>(x + 2 * y), 255);
    });
    // R: 1/4 → 0; G: (0 + 3 + 6 + 9)/4 = 4.5 → 5.
    EXPECT_EQ(tex.level(1).at(0, 0), packRgba(0, 5, 255));
}

TEST(TextureMips, SizesForNonPowerOfTwo) {
    struct Case {
        int w, h;
        std::vector<std::pair<int, int>> sizes;
    };
    const std::vector<Case> cases = {
        {5, 3, {{5, 3}, {2, 1}, {1, 1}}}, {8, 2, {{8, 2}, {4, 1}, {2, 1}, {1, 1}}},
        {1, 7, {{1, 7}, {1, 3}, {1, 1}}}, {3, 3, {{3, 3}, {1, 1}}},
        {6, 6, {{6, 6}, {3, 3}, {1, 1}}}, {1, 1, {{1, 1}}},
    };
    for (const Case& c : cases) {
        const Texture tex = distinctTexture(c.w, c.h);
        ASSERT_EQ(tex.levelCount(), static_cast<int>(c.sizes.size())) << c.w << "x" << c.h;
        EXPECT_EQ(tex.levelCount(),
                  1 + static_cast<int>(std::floor(std::log2(std::max(c.w, c.h)))));
        for (std::size_t i = 0; i < c.sizes.size(); ++i) {
            EXPECT_EQ(tex.level(static_cast<int>(i)).width, c.sizes[i].first);
            EXPECT_EQ(tex.level(static_cast<int>(i)).height, c.sizes[i].second);
            EXPECT_EQ(tex.level(static_cast<int>(i)).texels.size(),
                      static_cast<std::size_t>(c.sizes[i].first * c.sizes[i].second));
        }
    }
}

TEST(TextureMips, OddSidesAreAreaWeighted) {
    // tex_5x3.bmp: R = 50x, G = 100y, B = 7. Level 1 is 2×1: texel 0 covers x ∈ [0, 2.5) with
    // weights 1, 1, ½ → R = (0 + 50 + 50)/2.5 = 40; texel 1 covers [2.5, 5) → (50 + 150 + 200)/2.5
    // = 160. Every texel covers all three rows: G = 100. Nothing is skipped or counted twice, so
    // level 2 is the mean of the image, (100, 100, 7).
    const Result<Texture> t = loadTexture(testData("tex_5x3.bmp"));
    ASSERT_TRUE(t.ok()) << t.error().what();
    ASSERT_EQ(t->levelCount(), 3);
    EXPECT_EQ(t->level(1).at(0, 0), packRgba(40, 100, 7));
    EXPECT_EQ(t->level(1).at(1, 0), packRgba(160, 100, 7));
    EXPECT_EQ(t->level(2).at(0, 0), packRgba(100, 100, 7));
}

TEST(TextureMips, EveryLevelKeepsTheMean) {
    // A box filter over exact footprints preserves the mean (up to half a step of rounding per
    // level); a reduction that dropped or doubled the odd row or column would drift from it.
    const Texture tex = makeTexture(37, 23, [](int x, int y) {
        return packRgba(x < 18 ? 250u : 5u, y == 22 ? 255u : 0u, static_cast<std::uint32_t>(x * 7));
    });
    const auto mean = [](const MipLevel& l) {
        glm::dvec3 s(0.0);
        for (std::uint32_t p : l.texels) s += glm::dvec3(bytes(p));
        return s / static_cast<double>(l.texels.size());
    };
    const glm::dvec3 m0 = mean(tex.level(0));
    for (int i = 1; i < tex.levelCount(); ++i) {
        const glm::dvec3 m = mean(tex.level(i));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(m[c], m0[c], 0.5 * i) << "level " << i;
    }
}

// ---- Level of detail ------------------------------------------------------------------------

TEST(TextureLod, FromDerivatives) {
    const Texture tex = distinctTexture(256, 256);  // 9 levels
    ASSERT_EQ(tex.levelCount(), 9);
    const float t = 1.0f / 256.0f;                             // one texel in uv
    EXPECT_EQ(mipLevel(tex, {t, 0}, {0, t}), 0.0f);            // 1 texel per pixel
    EXPECT_EQ(mipLevel(tex, {4 * t, 0}, {0, 4 * t}), 2.0f);    // 4 texels per pixel
    EXPECT_EQ(mipLevel(tex, {0, 8 * t}, {8 * t, 0}), 3.0f);    // swapped axes
    EXPECT_FLOAT_EQ(mipLevel(tex, {2 * t, 0}, {0, 0}), 1.0f);  // the larger direction decides
    EXPECT_FLOAT_EQ(mipLevel(tex, {0, 0}, {0, 16 * t}), 4.0f);
    // Length, not the larger component: a rotated footprint has the same level.
    EXPECT_FLOAT_EQ(mipLevel(tex, {4 * t * 0.6f, 4 * t * 0.8f}, {-4 * t * 0.8f, 4 * t * 0.6f}),
                    2.0f);
    EXPECT_NEAR(mipLevel(tex, {3 * t, 0}, {0, 3 * t}), std::log2(3.0f), 1e-6f);
    // Clamped to the chain.
    EXPECT_EQ(mipLevel(tex, {t / 8, 0}, {0, t / 8}), 0.0f);  // magnified
    EXPECT_EQ(mipLevel(tex, {0, 0}, {0, 0}), 0.0f);          // log2 0 = −inf
    EXPECT_EQ(mipLevel(tex, {1e4f, 0}, {0, 1e4f}), 8.0f);    // minified past 1×1
    EXPECT_EQ(mipLevel(tex, {1e30f, 1e30f}, {0, 0}), 8.0f);  // squares overflow to inf
    EXPECT_EQ(mipLevel(tex, {kInf, 0}, {0, 0}), 8.0f);
    EXPECT_EQ(mipLevel(tex, {kNaN, 0}, {0, 4 * t}), 0.0f);  // NaN anywhere → 0
    EXPECT_EQ(mipLevel(tex, {4 * t, 0}, {0, kNaN}), 0.0f);
    EXPECT_EQ(reference::mipLevel(tex, {kNaN, 0}, {0, 4 * t}), 0.0);
    EXPECT_EQ(reference::mipLevel(tex, {4 * t, 0}, {0, kNaN}), 0.0);
    // Non-square textures scale u by W and v by H.
    const Texture wide = distinctTexture(64, 16);
    EXPECT_EQ(mipLevel(wide, {4.0f / 64, 0}, {0, 1.0f / 16}), 2.0f);
    EXPECT_EQ(mipLevel(wide, {1.0f / 64, 0}, {0, 4.0f / 16}), 2.0f);
}

TEST(TextureLod, PlaneAtKnownDistance) {
    // A plane facing the camera at depth Z, focal length f pixels, uv = world (x, y) / S: one
    // pixel step spans Z/f world units, so ∂u/∂x = Z/(f·S) and the texels per pixel are
    // W·Z/(f·S). The derivatives come from unprojecting neighbouring pixel centres.
    const Texture tex = distinctTexture(256, 256);
    const double f = 512.0, S = 1.0;
    const auto uvAt = [&](double z, double px, double py) {
        const double w = 640.0, h = 480.0;
        return glm::dvec2((px - w / 2) * z / f / S, (py - h / 2) * z / f / S);
    };
    for (const auto& [z, expected] : std::vector<std::pair<double, float>>{
             {2.0, 0.0f}, {4.0, 1.0f}, {8.0, 2.0f}, {32.0, 4.0f}, {1.0, 0.0f}, {1e6, 8.0f}}) {
        const glm::dvec2 c = uvAt(z, 100.5, 200.5);
        const glm::vec2 dx(uvAt(z, 101.5, 200.5) - c);
        const glm::vec2 dy(uvAt(z, 100.5, 201.5) - c);
        EXPECT_NEAR(mipLevel(tex, dx, dy), expected, 1e-5f) << "Z = " << z;
    }
}

TEST(TextureLod, FastMatchesReference) {
    const Texture tex = distinctTexture(300, 120);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> d(-0.05f, 0.05f);
    for (int i = 0; i < 20000; ++i) {
        const glm::vec2 dx(d(rng), d(rng));
        const glm::vec2 dy(d(rng), d(rng));
        ASSERT_NEAR(mipLevel(tex, dx, dy), reference::mipLevel(tex, dx, dy), 1e-5);
    }
}

// ---- Trilinear ------------------------------------------------------------------------------

TEST(TextureTrilinear, IntegerLevelsAreBilinear) {
    const Texture tex = randomTexture(64, 32, 3);
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> c(-3.0f, 3.0f);
    for (int i = 0; i < 2000; ++i) {
        const glm::vec2 uv(c(rng), c(rng));
        // λ ≤ 0 (and NaN) is level 0, bit for bit.
        for (float lod : {0.0f, -0.0f, -1.0f, -kInf, kNaN})
            ASSERT_TRUE(sameColor(sampleTrilinear(tex, uv, lod), sampleBilinear(tex, uv, 0)));
        for (int level = 0; level < tex.levelCount(); ++level)
            ASSERT_TRUE(sameColor(sampleTrilinear(tex, uv, static_cast<float>(level)),
                                  sampleBilinear(tex, uv, level)));
        // Beyond the chain: the 1×1 level.
        ASSERT_TRUE(sameColor(sampleTrilinear(tex, uv, 50.0f), sampleBilinear(tex, uv, 6)));
        ASSERT_TRUE(sameColor(sampleTrilinear(tex, uv, kInf), sampleBilinear(tex, uv, 6)));
    }
}

TEST(TextureTrilinear, BlendsNeighbouringLevels) {
    const Texture tex = randomTexture(64, 64, 9);
    const glm::vec2 uv(0.37f, 0.81f);
    for (float lod : {0.25f, 1.5f, 2.75f, 5.5f}) {
        const int l0 = static_cast<int>(lod);
        const float f = lod - static_cast<float>(l0);
        const glm::vec3 want =
            (1.0f - f) * sampleBilinear(tex, uv, l0) + f * sampleBilinear(tex, uv, l0 + 1);
        const glm::vec3 got = sampleTrilinear(tex, uv, lod);
        EXPECT_NEAR(got.x, want.x, 1e-6f);
        EXPECT_NEAR(got.y, want.y, 1e-6f);
        EXPECT_NEAR(got.z, want.z, 1e-6f);
    }
    // The derivative overload is the λ overload at mipLevel().
    const glm::vec2 dx(0.05f, 0.01f), dy(-0.01f, 0.03f);
    EXPECT_TRUE(sameColor(sampleTrilinear(tex, uv, dx, dy),
                          sampleTrilinear(tex, uv, mipLevel(tex, dx, dy))));
}

// ---- Fast against reference -----------------------------------------------------------------

struct Sizes {
    int w, h;
};

TEST(TextureFastVsReference, BilinearAndTrilinearWithinOneStep) {
    for (const Sizes s : {Sizes{64, 64}, Sizes{37, 23}, Sizes{1, 5}, Sizes{512, 256}}) {
        const Texture tex = randomTexture(s.w, s.h, static_cast<std::uint32_t>(s.w * 1000 + s.h));
        std::mt19937 rng(static_cast<std::uint32_t>(s.w + s.h));
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        std::uniform_real_distribution<float> wide(-50.0f, 50.0f);
        std::uniform_real_distribution<float> far(-1e4f, 1e4f);
        std::uniform_real_distribution<float> lodDist(-1.0f, 12.0f);
        double worst = 0.0;
        for (int i = 0; i < 50000; ++i) {
            const int kind = i % 3;
            const auto pick = [&] {
                return kind == 0 ? unit(rng) : kind == 1 ? wide(rng) : far(rng);
            };
            const glm::vec2 uv(pick(), pick());
            const glm::dvec2 duv(uv);
            const int level = i % tex.levelCount();
            const float lod = lodDist(rng);
            const glm::vec3 fb = sampleBilinear(tex, uv, level);
            const glm::dvec3 rb = reference::sampleBilinear(tex, duv, level);
            const glm::vec3 ft = sampleTrilinear(tex, uv, lod);
            const glm::dvec3 rt = reference::sampleTrilinear(tex, duv, lod);
            ASSERT_TRUE(nearColor(fb, rb, kLsb)) << uv.x << ", " << uv.y << " level " << level;
            ASSERT_TRUE(nearColor(ft, rt, kLsb)) << uv.x << ", " << uv.y << " lod " << lod;
            for (int c = 0; c < 3; ++c) {
                worst = std::max({worst, std::abs(fb[c] - rb[c]), std::abs(ft[c] - rt[c])});
                ASSERT_GE(fb[c], 0.0f);
                ASSERT_LE(fb[c], 1.0f);
            }
        }
        std::printf("[texture] %dx%d bilinear/trilinear max |fast - reference| = %.3g LSB\n", s.w,
                    s.h, worst * 255.0);
    }
}

TEST(TextureFastVsReference, NearestAgreesAwayFromBorders) {
    // Float and double may round a coordinate to different sides of a texel border; elsewhere
    // the texel must be the same one.
    const Texture tex = randomTexture(37, 23, 1);
    std::mt19937 rng(2);
    std::uniform_real_distribution<float> wide(-20.0f, 20.0f);
    int skipped = 0;
    for (int i = 0; i < 100000; ++i) {
        const glm::vec2 uv(wide(rng), wide(rng));
        const double x = reference::wrapCoord(uv.x) * 37.0;
        const double y = reference::wrapCoord(uv.y) * 23.0;
        if (std::abs(x - std::round(x)) < 1e-4 || std::abs(y - std::round(y)) < 1e-4) {
            ++skipped;
            continue;
        }
        const glm::dvec3 r = reference::sampleNearest(tex, glm::dvec2(uv));
        ASSERT_TRUE(nearColor(sampleNearest(tex, uv), r, 1e-6)) << uv.x << ", " << uv.y;
    }
    EXPECT_LT(skipped, 500);
}

TEST(TextureFastVsReference, ExtremeCoordinatesAgree) {
    const Texture tex = randomTexture(16, 8, 4);
    const float values[] = {0.0f,   1.0f, -0.25f, 1e6f,  -1e6f,  1e30f,
                            -1e30f, kNaN, kInf,   -kInf, -1e-9f, 0.999999f};
    for (float u : values) {
        for (float v : values) {
            const glm::vec2 uv(u, v);
            const glm::dvec2 duv(static_cast<double>(u), static_cast<double>(v));
            EXPECT_TRUE(
                nearColor(sampleBilinear(tex, uv), reference::sampleBilinear(tex, duv), kLsb))
                << u << ", " << v;
            EXPECT_TRUE(nearColor(sampleTrilinear(tex, uv, 1.5f),
                                  reference::sampleTrilinear(tex, duv, 1.5), kLsb))
                << u << ", " << v;
        }
    }
}

// ---- Loading --------------------------------------------------------------------------------

TEST(TextureLoad, FormatsAndOrientation) {
    // Grey expands to r = g = b with opaque alpha; 3×2 reduces to 1×1, the mean 127.5 → 128.
    const Result<Texture> grey = loadTexture(testData("tex_gray_3x2.png"));
    ASSERT_TRUE(grey.ok()) << grey.error().what();
    EXPECT_EQ(grey->width(), 3);
    EXPECT_EQ(grey->height(), 2);
    EXPECT_EQ(grey->level(0).at(1, 0), packRgba(51, 51, 51));
    EXPECT_EQ(grey->level(0).at(2, 1), packRgba(255, 255, 255));
    EXPECT_EQ(grey->level(1).at(0, 0), packRgba(128, 128, 128));
    EXPECT_EQ(grey->name(), testData("tex_gray_3x2.png"));

    // BMP and TGA are stored bottom-up; row 0 must still be the top of the picture (v = 0).
    const Result<Texture> bmp = loadTexture(testData("tex_5x3.bmp"));
    ASSERT_TRUE(bmp.ok()) << bmp.error().what();
    EXPECT_EQ(bmp->width(), 5);
    EXPECT_EQ(bmp->height(), 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 5; ++x)
            EXPECT_EQ(bmp->level(0).at(x, y), packRgba(static_cast<std::uint32_t>(50 * x),
                                                       static_cast<std::uint32_t>(100 * y), 7));

    const Result<Texture> tga = loadTexture(testData("tex_2x2.tga"));
    ASSERT_TRUE(tga.ok()) << tga.error().what();
    EXPECT_EQ(tga->level(0).at(0, 0), packRgba(255, 0, 0));
    EXPECT_EQ(tga->level(0).at(1, 0), packRgba(0, 255, 0));
    EXPECT_EQ(tga->level(0).at(0, 1), packRgba(0, 0, 255));
    EXPECT_EQ(tga->level(0).at(1, 1), packRgba(255, 255, 255));
    EXPECT_TRUE(sameColor(sampleNearest(*tga, {0.25f, 0.25f}), glm::vec3(1, 0, 0)));  // v=0 top
}

TEST(TextureLoad, SharedImages) {
    REQUIRE_SHARED_DATA(sharedData("course"));
    struct Want {
        std::string file;
        int w, h, levels;
    };
    for (const Want& want :
         {Want{"course/brick.jpg", 512, 512, 10}, Want{"course/world_map.jpg", 512, 256, 10},
          Want{"models/spot_texture.png", 1024, 1024, 11}}) {
        const Result<Texture> t = loadTexture(sharedData(want.file));
        ASSERT_TRUE(t.ok()) << t.error().what();
        EXPECT_EQ(t->width(), want.w) << want.file;
        EXPECT_EQ(t->height(), want.h) << want.file;
        EXPECT_EQ(t->levelCount(), want.levels) << want.file;
        EXPECT_EQ(t->level(t->levelCount() - 1).width, 1);
        // An image, not a blank: the texels vary.
        const auto& px = t->level(0).texels;
        EXPECT_NE(*std::min_element(px.begin(), px.end()), *std::max_element(px.begin(), px.end()));
    }
}

/// The load failed with an Error that names exactly `path` and whose message holds `part`.
::testing::AssertionResult failsWith(const std::string& path, std::string_view part) {
    const Result<Texture> t = loadTexture(path);
    if (t.ok()) return ::testing::AssertionFailure() << path << " loaded";
    const Error& e = t.error();
    if (e.loc.file != path) return ::testing::AssertionFailure() << "names " << e.loc.file;
    if (e.what().rfind(path + ": ", 0) != 0)
        return ::testing::AssertionFailure()
               << "message does not start with the file: " << e.what();
    if (e.message.find(part) == std::string::npos)
        return ::testing::AssertionFailure() << "lacks \"" << part << "\": " << e.what();
    return ::testing::AssertionSuccess() << e.what();
}

TEST(TextureLoad, BadFilesGiveClearErrors) {
    EXPECT_TRUE(failsWith(testData("tex_no_such_file.png"), "cannot open"));
    EXPECT_TRUE(failsWith(testData("tex_empty.png"), "empty"));
    EXPECT_TRUE(failsWith(testData("tex_truncated.png"), "damaged or truncated"));
    EXPECT_TRUE(
        failsWith(testData("tex_not_an_image.png"), "not a readable PNG, JPEG, BMP or TGA"));
    EXPECT_TRUE(failsWith(testData("tex_zero_width.png"), "0x4 pixels"));
    EXPECT_TRUE(failsWith(testData("tex_huge.png"), "20000x20000 pixels"));  // stb's refusal
    EXPECT_TRUE(failsWith(testData("tex_wide.png"), "16385x1 pixels"));      // the engine's limit
    EXPECT_TRUE(failsWith(testData("tex_wide.png"), "1 to 16384"));
    EXPECT_TRUE(failsWith(std::string(FACET_TEST_DATA), "folder"));
    // A mesh is not an image either.
    EXPECT_TRUE(failsWith(testData("mesh_square.off"), "not a readable"));
    // The messages are printable for the log.
    std::printf("[texture] %s\n",
                loadTexture(testData("tex_truncated.png")).error().what().c_str());
    std::printf("[texture] %s\n",
                loadTexture(testData("tex_not_an_image.png")).error().what().c_str());
}

TEST(TextureLoad, FromRgbaChecksItsInput) {
    EXPECT_FALSE(Texture::fromRgba(0, 4, {}, "x").ok());
    EXPECT_FALSE(Texture::fromRgba(4, -1, {}, "x").ok());
    EXPECT_FALSE(Texture::fromRgba(kMaxImageSide + 1, 1, {}, "x").ok());
    const Result<Texture> mismatch = Texture::fromRgba(2, 2, std::vector<std::uint32_t>(3), "x");
    ASSERT_FALSE(mismatch.ok());
    EXPECT_NE(mismatch.error().message.find("does not match"), std::string::npos);
    EXPECT_EQ(mismatch.error().loc.file, "x");
}

}  // namespace
}  // namespace facet
