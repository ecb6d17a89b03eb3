// The front end's vertex pass (ScreenVertex, computed once per vertex by the tile renderer) must
// hand the rasterizer exactly what the per-corner front end does, bit for bit: the same
// coverage setups, the same planes, the same counters, on random triangles and on the cases
// where the stages decide something (degenerate, sub-pixel, near-plane crossing, beyond the
// guard band, off screen, non-finite). And the tile renderer's binning (compact records, sorted
// into tiles) must hand each tile exactly what the front end emitted, restricted to the tile.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "binning/tiles.hpp"
#include "frontend/front_end.hpp"

namespace facet::detail {
namespace {

constexpr int kWidth = 320, kHeight = 200;
constexpr float kNear = 0.01f;

/// What reached the rasterizer, as bytes: the setup, the planes up to their varyings and the
/// `varyings` varyings of the layout (the rest of a Planes is never written).
struct Recorder {
    int varyings = 0;
    std::vector<std::byte> bytes;
    std::size_t calls = 0;
};

std::size_t record(void* context, const CoverageSetup& setup, const Planes& planes) {
    auto& r = *static_cast<Recorder*>(context);
    auto put = [&](const void* p, std::size_t n) {
        const auto* b = static_cast<const std::byte*>(p);
        r.bytes.insert(r.bytes.end(), b, b + n);
    };
    put(&setup, sizeof setup);
    put(&planes, offsetof(Planes, a0));
    const auto n = sizeof(float) * static_cast<std::size_t>(r.varyings);
    put(planes.a0, n);
    put(planes.d1, n);
    put(planes.d2, n);
    ++r.calls;
    return 1;
}

/// Random clip positions of every kind the front end tells apart, one triangle each three.
struct Mesh {
    std::vector<glm::vec4> clip;
    std::vector<glm::vec3> colors;
    std::vector<std::uint32_t> indices;

    void add(glm::vec4 a, glm::vec4 b, glm::vec4 c) {
        for (const glm::vec4& p : {a, b, c}) {
            indices.push_back(static_cast<std::uint32_t>(clip.size()));
            clip.push_back(p);
            colors.emplace_back(p.x * 0.001f, p.y * 0.002f, p.w);
        }
    }
    DrawInput input() const {
        DrawInput in;
        in.clip = clip;
        in.colors = colors;
        in.indices = indices;
        in.nearPlane = kNear;
        return in;
    }
};

/// A clip position that projects to screen point (x, y) at depth w.
glm::vec4 at(double x, double y, float w) {
    return {static_cast<float>(x * w), static_cast<float>(y * w), 0.0f, w};
}

Mesh cases() {
    Mesh m;
    std::mt19937 rng(20261124);
    std::uniform_real_distribution<double> onScreen(-20.0, 340.0), depth(0.5, 40.0),
        jitter(-3.0, 3.0), unit(0.0, 1.0);
    auto w = [&] { return static_cast<float>(depth(rng)); };
    for (int i = 0; i < 400; ++i) {  // ordinary triangles a few pixels across, both windings
        const double x = onScreen(rng), y = onScreen(rng) * 0.6;
        m.add(at(x, y, w()), at(x + jitter(rng), y + jitter(rng), w()),
              at(x + jitter(rng), y + jitter(rng), w()));
    }
    for (int i = 0; i < 400; ++i) {  // tiny: most cover no pixel centre
        const double x = onScreen(rng), y = onScreen(rng) * 0.6, d = 0.01 + unit(rng);
        m.add(at(x, y, w()), at(x + d, y + d * unit(rng), w()), at(x + d * unit(rng), y - d, w()));
    }
    for (int i = 0; i < 100; ++i) {  // vertices on pixel centres and edges: the top-left rule
        const double x = std::floor(onScreen(rng)) + 0.5, y = std::floor(onScreen(rng) * 0.6);
        m.add(at(x, y, 2.0f), at(x + 4.0, y, 2.0f), at(x, y + 4.0, 2.0f));
        m.add(at(x + 4.0, y, 2.0f), at(x + 4.0, y + 4.0, 2.0f), at(x, y + 4.0, 2.0f));
    }
    for (int i = 0; i < 100; ++i) {  // huge: reach past the guard band, some all of it
        const double s = 1e4 * std::pow(10.0, 3.0 * unit(rng));
        m.add(at(-s, -s * unit(rng), w()), at(s, -s, w()), at(s * unit(rng), s, w()));
    }
    for (int i = 0; i < 100; ++i) {  // crossing the near plane, or wholly behind it
        const float wa = static_cast<float>(unit(rng) * 0.03), wb = static_cast<float>(unit(rng));
        m.add({onScreen(rng) * wa, onScreen(rng) * wa, 0.0f, wa},
              glm::vec4(at(onScreen(rng), onScreen(rng), wb)), at(onScreen(rng), 50.0, 3.0f));
    }
    // Degenerate: collinear, a repeated vertex, every vertex on one point.
    m.add(at(10, 10, 1), at(20, 20, 2), at(40, 40, 3));
    m.add(at(10.3, 10.7, 1), at(10.3, 10.7, 1), at(90, 40, 3));
    m.add(at(5, 5, 1), at(5, 5, 1), at(5, 5, 1));
    // Off one side of the image, each side; a vertex exactly on the near plane.
    m.add(at(-30, 10, 1), at(-5, 50, 1), at(-1, 5, 1));
    m.add(at(330, 10, 1), at(400, 50, 1), at(321, 5, 1));
    m.add(at(30, -10, 1), at(50, -50, 1), at(10, -1, 1));
    m.add(at(30, 210, 1), at(50, 250, 1), at(10, 201, 1));
    m.add(at(30, 30, kNear), at(60, 40, 1), at(40, 90, 2));
    // On the guard band's edge exactly, and just past it.
    const double g = kGuardBand;
    m.add(at(-g, 10, 1), at(100, 20, 1), at(50, 90, 1));
    m.add(at(std::nextafter(-g, -1e9), 10, 1), at(100, 20, 1), at(50, 90, 1));
    m.add(at(kWidth + g, 10, 1), at(100, 20, 1), at(50, 90, 1));
    // Non-finite positions.
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    m.add({inf, 10, 0, 1}, at(100, 20, 1), at(50, 90, 1));
    m.add({10, nan, 0, 1}, at(100, 20, 1), at(50, 90, 1));
    m.add(at(10, 10, 1), {100, 20, 0, inf}, at(50, 90, 1));
    return m;
}

struct DrawResult {
    Recorder out;
    RenderStats stats;
};

DrawResult draw(const DrawInput& in, const VaryingLayout& layout, bool cull, int bits, int reach,
                std::size_t t, const ScreenVertex* screen) {
    DrawResult r;
    r.out.varyings = layout.count();
    drawTriangles(in, layout, cull, kWidth, kHeight, t, t + 1, &record, &r.out, r.stats, bits,
                  reach, screen);
    return r;
}

struct Config {
    bool cull;
    int bits;
    int reach;
    bool color;
};

class VertexPass : public testing::TestWithParam<Config> {};

TEST_P(VertexPass, HandsOnWhatThePerCornerFrontEndDoes) {
    const Config c = GetParam();
    const Mesh mesh = cases();
    const DrawInput in = mesh.input();
    const VaryingLayout layout{c.color, false, false};
    const ScreenSpace space = ScreenSpace::of(kWidth, kHeight, kNear, c.bits);
    std::vector<ScreenVertex> screen;
    for (const glm::vec4& p : mesh.clip) screen.push_back(space.vertex(p));

    const std::size_t triangles = mesh.indices.size() / 3;
    std::size_t emitted = 0, clipped = 0, culled = 0, rejected = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
        const DrawResult a = draw(in, layout, c.cull, c.bits, c.reach, t, nullptr);
        const DrawResult b = draw(in, layout, c.cull, c.bits, c.reach, t, screen.data());
        ASSERT_EQ(a.out.calls, b.out.calls) << "triangle " << t;
        ASSERT_TRUE(a.out.bytes == b.out.bytes) << "triangle " << t;
        EXPECT_EQ(a.stats.trianglesIn, b.stats.trianglesIn) << "triangle " << t;
        EXPECT_EQ(a.stats.trianglesClipped, b.stats.trianglesClipped) << "triangle " << t;
        EXPECT_EQ(a.stats.trianglesCulled, b.stats.trianglesCulled) << "triangle " << t;
        EXPECT_EQ(a.stats.trianglesRasterized, b.stats.trianglesRasterized) << "triangle " << t;
        emitted += a.out.calls;
        clipped += a.stats.trianglesClipped;
        culled += a.stats.trianglesCulled;
        rejected += a.stats.trianglesRasterized == 0 ? 1 : 0;
    }
    // The cases reach every stage: none of the comparisons above was vacuous.
    EXPECT_GT(emitted, 300u);
    EXPECT_GT(clipped, 100u);
    EXPECT_GT(rejected, 50u);
    if (c.cull) {
        EXPECT_GT(culled, 100u);
    }
}

/// What reached one tile's rasterizer, as bytes: the coverage (edges, steps, box; not area2,
/// which no rasterizer reads) and the planes the layout's loops read: the base and the depth
/// plane, and with varyings the weights' planes and the varyings (a record without varyings
/// carries no weights: they only interpolate varyings).
struct TileRecorder {
    int varyings = 0;
    int tilesX = 0;
    std::vector<std::vector<std::byte>> tiles;
    std::size_t calls = 0;  // counted in the one-thread reference only
};

void putTile(std::vector<std::byte>& out, int varyings, const CoverageSetup& setup,
             const Planes& p) {
    auto put = [&](const void* data, std::size_t n) {
        const auto* b = static_cast<const std::byte*>(data);
        out.insert(out.end(), b, b + n);
    };
    put(setup.e0, sizeof setup.e0);
    put(setup.stepX, sizeof setup.stepX);
    put(setup.stepY, sizeof setup.stepY);
    put(&setup.box, sizeof setup.box);
    put(&p.baseX, sizeof p.baseX);
    put(&p.baseY, sizeof p.baseY);
    put(p.q, sizeof p.q);
    if (varyings == 0) return;
    put(p.l1, sizeof p.l1);
    put(p.l2, sizeof p.l2);
    put(p.u1, sizeof p.u1);
    put(p.u2, sizeof p.u2);
    const auto n = sizeof(float) * static_cast<std::size_t>(varyings);
    put(p.a0, n);
    put(p.d1, n);
    put(p.d2, n);
}

/// The tile renderer's rasterizer: its setups are already restricted to one tile.
std::size_t recordTile(void* context, const CoverageSetup& setup, const Planes& planes) {
    auto& r = *static_cast<TileRecorder*>(context);
    const int tile = setup.box.y0 / kTileSize * r.tilesX + setup.box.x0 / kTileSize;
    putTile(r.tiles[static_cast<std::size_t>(tile)], r.varyings, setup, planes);
    return 1;
}

/// The front end's rasterizer, cutting each setup at the tiles as binning does.
std::size_t recordCut(void* context, const CoverageSetup& setup, const Planes& planes) {
    auto& r = *static_cast<TileRecorder*>(context);
    for (std::size_t tile = 0; tile < r.tiles.size(); ++tile) {
        const int x0 = static_cast<int>(tile) % r.tilesX * kTileSize;
        const int y0 = static_cast<int>(tile) / r.tilesX * kTileSize;
        const PixelRect rect{x0, y0, std::min(x0 + kTileSize, kWidth) - 1,
                             std::min(y0 + kTileSize, kHeight) - 1};
        const CoverageSetup cut = restrictSetup(setup, rect);
        if (cut.box.empty()) continue;
        putTile(r.tiles[tile], r.varyings, cut, planes);
        ++r.calls;
    }
    return 0;
}

class Binning : public testing::TestWithParam<Config> {};

TEST_P(Binning, HandsEachTileWhatTheFrontEndEmitted) {
    const Config c = GetParam();
    Mesh mesh = cases();
    // Triangles over several tiles, and one over all of them, besides the cases' small ones.
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> x(-40.0f, 360.0f), y(-40.0f, 240.0f);
    for (int i = 0; i < 60; ++i) {
        const float w = 1.0f + static_cast<float>(i % 5);
        mesh.add({x(rng) * w, y(rng) * w, 0.0f, w}, {x(rng) * w, y(rng) * w, 0.0f, w},
                 {x(rng) * w, y(rng) * w, 0.0f, w});
    }
    const DrawInput in = mesh.input();
    const VaryingLayout layout{c.color, false, false};
    const int tilesX = (kWidth + kTileSize - 1) / kTileSize;
    const int tiles = tilesX * ((kHeight + kTileSize - 1) / kTileSize);
    auto recorder = [&] {
        TileRecorder r;
        r.varyings = layout.count();
        r.tilesX = tilesX;
        r.tiles.resize(static_cast<std::size_t>(tiles));
        return r;
    };

    TileRecorder expected = recorder();
    RenderStats frontStats;
    drawTriangles(in, layout, c.cull, kWidth, kHeight, 0, mesh.indices.size() / 3, &recordCut,
                  &expected, frontStats, c.bits, c.reach);
    EXPECT_GT(expected.calls, 400u);  // not vacuous: many triangles, some over several tiles
    std::size_t multiTile = 0;
    for (const auto& t : expected.tiles) multiTile += t.empty() ? 0 : 1;
    EXPECT_EQ(multiTile, static_cast<std::size_t>(tiles));

    for (const int threads : {1, 2}) {
        TileRecorder binned = recorder();
        RenderStats stats;
        TileRenderer renderer;
        renderer.draw(in, layout, c.cull, kWidth, kHeight, &recordTile, &binned, threads, c.bits,
                      stats, c.reach);
        for (std::size_t t = 0; t < expected.tiles.size(); ++t)
            EXPECT_TRUE(binned.tiles[t] == expected.tiles[t])
                << "tile " << t << ", " << threads << " threads";
        EXPECT_EQ(stats.trianglesIn, frontStats.trianglesIn);
        EXPECT_EQ(stats.trianglesClipped, frontStats.trianglesClipped);
        EXPECT_EQ(stats.trianglesCulled, frontStats.trianglesCulled);
        EXPECT_EQ(stats.trianglesRasterized, frontStats.trianglesRasterized);
        // The per-stage clocks are filled (their values are not asserted: speed never is).
        EXPECT_GT(stats.frontEndMs, 0.0);
        EXPECT_GT(stats.binningMs, 0.0);
    }
}

std::string configName(const testing::TestParamInfo<Config>& param) {
    const Config& c = param.param;
    return std::string(c.cull ? "cull" : "nocull") + "_bits" + std::to_string(c.bits) + "_reach" +
           std::to_string(c.reach) + (c.color ? "_rgb" : "");
}

INSTANTIATE_TEST_SUITE_P(Configs, VertexPass,
                         testing::Values(Config{false, 8, 0, false}, Config{true, 8, 0, true},
                                         Config{false, 4, 0, true}, Config{false, 8, 96, false}),
                         configName);
INSTANTIATE_TEST_SUITE_P(Configs, Binning,
                         testing::Values(Config{false, 8, 0, false}, Config{true, 8, 0, true},
                                         Config{false, 4, 0, true}, Config{false, 8, 96, false}),
                         configName);

// The snapped positions of the vertex pass are the grid's rounding of the screen position,
// written in 32 bits without loss: checked against SnapGrid on positions up to the guard band's
// edge, where the values are largest, and at halves, where the rounding decides.
TEST(ScreenVertex, SnapsAsTheGridDoes) {
    const ScreenSpace space = ScreenSpace::of(kWidth, kHeight, kNear, kSubPixelBits);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> band(-kGuardBand, kWidth + kGuardBand);
    std::size_t checked = 0;
    for (int i = 0; i < 20000; ++i) {
        double x = band(rng), y = band(rng) * 0.5;
        if (i % 4 == 0) x = std::floor(x * 256.0) / 256.0 + 0.5 / 256.0;  // a half: rounds away
        const float w = i % 3 == 0 ? 1.0f : 3.0f;
        const glm::vec4 p = at(x, y, w);
        const ScreenVertex v = space.vertex(p);
        const glm::dvec2 s = screenPosition(p);
        if (!space.inGuard(s)) {
            EXPECT_EQ(v.flags & ScreenVertex::kInGuard, 0u);
            continue;
        }
        ASSERT_NE(v.flags & ScreenVertex::kInGuard, 0u);
        EXPECT_EQ(v.gx, space.grid(s.x)) << s.x;
        EXPECT_EQ(v.gy, space.grid(s.y)) << s.y;
        ++checked;
    }
    EXPECT_GT(checked, 15000u);
    // The band's corners themselves are inside, and snap to ±(32768 + size)·256.
    const ScreenVertex corner = space.vertex(at(kWidth + kGuardBand, -kGuardBand, 1.0f));
    ASSERT_NE(corner.flags & ScreenVertex::kInGuard, 0u);
    EXPECT_EQ(corner.gx, (kWidth + 32768) * 256);
    EXPECT_EQ(corner.gy, -32768 * 256);
}

}  // namespace
}  // namespace facet::detail
