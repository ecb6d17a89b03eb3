// The front end's vertex pass (ScreenVertex, computed once per vertex by the tile renderer) must
// hand the rasterizer exactly what the per-corner front end does, bit for bit: the same
// coverage setups, the same planes, the same counters, on random triangles and on the cases
// where the stages decide something (degenerate, sub-pixel, near-plane crossing, beyond the
// guard band, off screen, non-finite). The lanes stage (laneSetup()) must give the scalar front
// end's output too, on every SIMD target, in submission order. And the tile renderer's binning
// (compact records, sorted into tiles) must hand each tile exactly what the front end emitted,
// restricted to the tile.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include "binning/tiles.hpp"
#include "frontend/front_end.hpp"
#include "frontend/front_end_loop.hpp"
#include "pipeline/span_targets.hpp"

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
    // The cases reach every stage: none of the comparisons above was vacuous. (Triangles whose
    // small box holds no pixel centre are no longer emitted: 280 of the cases are in the Clang
    // sanitizer build; the GCC build emits over 300.)
    EXPECT_GT(emitted, 200u);
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
        DrawJob job;
        job.in = &in;
        job.layout = layout;
        job.cull = c.cull;
        job.width = kWidth;
        job.height = kHeight;
        job.subPixelBits = c.bits;
        job.sampleReach = c.reach;
        renderer.draw(
            job,
            [&](const CoverageSetup& setup, const Planes& planes, const PixelTarget&) {
                return recordTile(&binned, setup, planes);
            },
            threads, stats);
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

/// Small triangles of every kind the lanes stage decides, mixed with ones it leaves to the
/// scalar path (so that the order of the two is checked): vertices on pixel centres and corners
/// (edges through centres: the top-left rule, boxes starting or ending on a centre), random
/// sub-pixel positions, both windings, degenerate ones, boxes just under, at and over
/// kLaneExtent, partly off the image, crossing the near plane and with invalid indices.
Mesh laneCases(std::vector<std::uint32_t>& invalid) {
    Mesh m;
    std::mt19937 rng(20261126);
    std::uniform_real_distribution<double> px(-8.0, kWidth + 8.0), py(-8.0, kHeight + 8.0),
        unit(0.0, 1.0), depth(0.5, 20.0);
    std::uniform_int_distribution<int> kind(0, 3), step(-6, 6), pick(0, 9);
    auto w = [&] { return static_cast<float>(depth(rng)); };
    // A coordinate near `c`: on a pixel centre, a pixel corner, a grid point or anywhere.
    auto place = [&](double c) {
        switch (kind(rng)) {
            case 0:
                return std::floor(c) + 0.5;
            case 1:
                return std::floor(c);
            case 2:
                return std::floor(c * 256.0) / 256.0;
            default:
                return c;
        }
    };
    for (int i = 0; i < 6000; ++i) {
        const double x = px(rng), y = py(rng);
        const int what = pick(rng);
        if (what < 6) {  // a few pixels across, either winding
            const double s = what < 3 ? 0.7 : 3.0;
            m.add(at(place(x), place(y), w()),
                  at(place(x + s * step(rng)), place(y + s * step(rng)), w()),
                  at(place(x + s * step(rng)), place(y + s * step(rng)), w()));
        } else if (what == 6) {  // right angles on centres: edges through centres both ways
            const double cx = std::floor(x) + 0.5, cy = std::floor(y) + 0.5;
            const double a = step(rng), b = step(rng);
            m.add(at(cx, cy, 2.0f), at(cx + a, cy, 2.0f), at(cx, cy + b, 2.0f));
        } else if (what == 7) {  // degenerate: collinear or a repeated vertex
            const double dx = step(rng) * 0.25, dy = step(rng) * 0.25;
            m.add(at(x, y, 1.0f), at(x + dx, y + dy, 2.0f), at(x + 2 * dx, y + 2 * dy, 3.0f));
            m.add(at(x, y, 1.0f), at(x, y, 1.0f), at(x + dy, y + dx, 1.0f));
        } else if (what == 8) {  // boxes at the lanes' 32-bit limit, in grid units
            const std::int32_t e = kLaneExtent + step(rng) / 3;  // − 2 … + 2
            const double s = e / 256.0;
            const double ox = std::floor(x * 256.0) / 256.0 - s / 2;
            const double oy = std::floor(y * 256.0) / 256.0 - s / 2;
            if (rng() & 1)
                m.add(at(ox, oy, 1.0f), at(ox + s, oy, 1.0f), at(ox, oy + s, 1.0f));
            else
                m.add(at(ox + s, oy + s, 1.0f), at(ox + s, oy, 1.0f),
                      at(ox, oy + unit(rng) * s, 1.0f));
        } else {  // the scalar path's: across the near plane, beyond the guard band
            if (rng() & 1) {
                const float wa = static_cast<float>(unit(rng) * 0.02);
                m.add({x * wa, y * wa, 0.0f, wa}, at(x + 3, y, 1.0f), at(x, y + 3, 2.0f));
            } else {
                m.add(at(x, y, 1.0f), at(x + 1e5, y, 1.0f), at(x, y + 2, 1.0f));
            }
        }
    }
    // Invalid indices here and there (the triangle is skipped, uncounted).
    for (std::size_t t = 5; t < m.indices.size() / 3; t += 97) {
        m.indices[3 * t + t % 3] = static_cast<std::uint32_t>(m.clip.size() + t);
        invalid.push_back(static_cast<std::uint32_t>(t));
    }
    return m;
}

/// The snapped triangles the lanes stage settles itself, over [first, end).
std::size_t laneSurvivors(LaneSetupFn lanes, const LaneInput& in, std::size_t first,
                          std::size_t end, std::size_t& settled) {
    std::size_t survivors = 0;
    LaneChunk chunk;
    for (std::size_t c = first; c < end; c += LaneChunk::kSize) {
        lanes(in, c, std::min(end, c + LaneChunk::kSize), chunk);
        for (std::uint32_t e = 0; e < chunk.count; ++e)
            survivors += (chunk.at[e] & LaneChunk::kScalar) == 0 ? 1 : 0;
        settled += chunk.trianglesIn;
    }
    return survivors;
}

class LaneSetup : public testing::TestWithParam<Config> {};

TEST_P(LaneSetup, EmitsWhatTheScalarFrontEndEmitsOnEveryTarget) {
    const Config c = GetParam();
    std::vector<std::uint32_t> invalid;
    const Mesh mesh = laneCases(invalid);
    const DrawInput in = mesh.input();
    const VaryingLayout layout{c.color, false, false};
    const ScreenSpace space = ScreenSpace::of(kWidth, kHeight, kNear, c.bits);
    std::vector<ScreenVertex> screen;
    for (const glm::vec4& p : mesh.clip) screen.push_back(space.vertex(p));
    const std::size_t triangles = mesh.indices.size() / 3;
    auto run = [&](std::size_t first, std::size_t end, DrawResult& r) {
        r.out.varyings = layout.count();
        drawTriangles(in, layout, c.cull, kWidth, kHeight, first, end, &record, &r.out, r.stats,
                      c.bits, c.reach, screen.data());
    };
    // Whole chunks and vectors, and ranges that start and end inside them.
    const std::size_t ranges[][2] = {{0, triangles}, {5, triangles - 3}, {250, 263}, {7, 8}};

    hwy::SetSupportedTargetsForTest(0);
    const std::int64_t targets = spanTargetsCompiled() & hwy::SupportedTargets();
    std::size_t tested = 0;
    for (std::int64_t rest = targets; rest != 0; rest &= rest - 1) {
        const std::int64_t target = rest & -rest;
        for (const auto& range : ranges) {
            enableLaneSetup(false);
            DrawResult scalar;
            run(range[0], range[1], scalar);
            enableLaneSetup(true);
            hwy::SetSupportedTargetsForTest(target);
            ASSERT_NE(laneSetup(), nullptr);
            DrawResult lanes;
            run(range[0], range[1], lanes);
            const std::string where = std::string(hwy::TargetName(target)) + ", triangles " +
                                      std::to_string(range[0]) + "…" + std::to_string(range[1]);
            EXPECT_EQ(scalar.out.calls, lanes.out.calls) << where;
            EXPECT_TRUE(scalar.out.bytes == lanes.out.bytes) << where;
            EXPECT_EQ(scalar.stats.trianglesIn, lanes.stats.trianglesIn) << where;
            EXPECT_EQ(scalar.stats.trianglesClipped, lanes.stats.trianglesClipped) << where;
            EXPECT_EQ(scalar.stats.trianglesCulled, lanes.stats.trianglesCulled) << where;
            EXPECT_EQ(scalar.stats.trianglesRasterized, lanes.stats.trianglesRasterized) << where;
            hwy::SetSupportedTargetsForTest(0);
        }
        // Not vacuous: on this target the lanes settle most triangles and emit most of what is
        // emitted; the scalar path still takes some (the order of the two is checked above).
        hwy::SetSupportedTargetsForTest(target);
        const LaneInput lanesIn{in.indices.data(), in.clip.size(), screen.data(), kWidth,
                                kHeight,           c.reach,        c.cull};
        std::size_t settled = 0;
        const std::size_t survivors = laneSurvivors(laneSetup(), lanesIn, 0, triangles, settled);
        hwy::SetSupportedTargetsForTest(0);
        DrawResult all;
        enableLaneSetup(false);
        run(0, triangles, all);
        enableLaneSetup(true);
        EXPECT_GT(settled, all.stats.trianglesIn * 8 / 10) << hwy::TargetName(target);
        EXPECT_GT(survivors, all.out.calls * 7 / 10) << hwy::TargetName(target);
        EXPECT_LT(survivors, all.out.calls) << hwy::TargetName(target);
        EXPECT_GT(all.out.calls, 2000u);
        if (c.cull) {
            EXPECT_GT(all.stats.trianglesCulled, 1000u);
        }
        std::printf("lanes front end checked on %s\n", hwy::TargetName(target));
        ++tested;
    }
    EXPECT_GE(tested, 1u);
    EXPECT_FALSE(invalid.empty());
}

INSTANTIATE_TEST_SUITE_P(Configs, LaneSetup,
                         testing::Values(Config{false, 8, 0, false}, Config{true, 8, 0, true},
                                         Config{false, 4, 0, true}, Config{true, 8, 96, false}),
                         configName);

/// Small triangles for the lanes' planes: depths over four decades (so 1/w and the weights span
/// every exponent the pixel loops see), thin ones, ones partly off the image (the base clamped),
/// and pairs exactly collinear in double whose snapped vertices are not (twice the area 0 in
/// double: makePlanes() refuses them, the coverage stage does not), each pair placed so that one
/// of the two covers a pixel centre and reaches the planes.
Mesh planeCases() {
    Mesh m;
    std::mt19937 rng(20261126);
    std::uniform_real_distribution<double> px(-6.0, kWidth + 6.0), py(-6.0, kHeight + 6.0),
        size(-5.0, 5.0), exponent(-1.5, 2.5), thin(-0.02, 0.02);
    auto w = [&] { return static_cast<float>(std::pow(10.0, exponent(rng))); };
    for (int i = 0; i < 6000; ++i) {
        const double x = px(rng), y = py(rng);
        if (i % 4 == 3) {  // a sliver along a random direction
            const double dx = size(rng), dy = size(rng);
            m.add(at(x, y, w()), at(x + dx, y + dy, w()),
                  at(x + dx / 2 + thin(rng), y + dy / 2 + thin(rng), w()));
        } else {
            m.add(at(x, y, w()), at(x + size(rng), y + size(rng), w()),
                  at(x + size(rng), y + size(rng), w()));
        }
    }
    for (int i = 0; i < 40; ++i) {
        // On the line y = 2x + 0.5 through the centre (10.5, 21.5) + (i, i): A and C on the grid,
        // B a little along the line, off the grid; B snaps to one side of AC, or the other.
        const double ox = 10.0 + 3 * i, oy = 20.5 + 3 * i + 3 * i;
        const double bx = ox + 0.5, by = oy + 1.0;
        m.add(at(ox, oy, 1.0f), at(bx + 1.0 / 1024, by + 1.0 / 512, 1.0f),
              at(ox + 1.0, oy + 2.0, 1.0f));
        m.add(at(ox, oy, 1.0f), at(bx + 1.0 / 512, by + 1.0 / 256, 1.0f),
              at(ox + 1.0, oy + 2.0, 1.0f));
    }
    return m;
}

/// Varying streams for planeCases(): every vertex its own values, of every sign and of
/// exponents over six decades, so that the lanes' differences d1 and d2 round as the scalar
/// path's do only if each lane subtracts its own triangle's values in float.
struct PlaneStreams {
    std::vector<glm::vec3> colors, normals, positions;
    std::vector<glm::vec2> uvs;
    explicit PlaneStreams(std::size_t vertices) {
        std::mt19937 rng(112026);
        std::uniform_real_distribution<double> mantissa(-1.0, 1.0), exponent(-3.0, 3.0);
        auto f = [&] { return static_cast<float>(mantissa(rng) * std::pow(10.0, exponent(rng))); };
        for (std::size_t i = 0; i < vertices; ++i) {
            colors.emplace_back(f(), f(), f());
            uvs.emplace_back(f(), f());
            normals.emplace_back(f(), f(), f());
            positions.emplace_back(f(), f(), f());
        }
    }
};

/// A layout of the lanes' plane test and which of its streams the mesh lacks.
struct PlaneLayout {
    const char* name;
    VaryingLayout layout;
    bool withUvs = true;  ///< false: the uv stream is missing (fetchVaryings()' fill)
};

// The lanes' planes (LaneChunk::planes), survivor by survivor, against the scalar stages
// (screenPosition(), planeBase(), makePlanes(), fetchVaryings()) bit for bit, on every SIMD
// target and for the layouts the draws use (none, rgb, uv, normal and position, uv with them,
// all, and uv without the mesh's uvs); their edges against edgesOf() of their own snapped
// triangle. Not vacuous: a value changed in one lane of the chunk is reported.
TEST(LanePlanes, EqualMakePlanesBitForBitOnEveryTarget) {
    const Mesh mesh = planeCases();
    const PlaneStreams streams(mesh.clip.size());
    const ScreenSpace space = ScreenSpace::of(kWidth, kHeight, kNear, kSubPixelBits);
    std::vector<ScreenVertex> screen;
    for (const glm::vec4& p : mesh.clip) screen.push_back(space.vertex(p));
    const std::size_t triangles = mesh.indices.size() / 3;
    const PlaneLayout layouts[] = {{"none", {false, false, false}},
                                   {"rgb", {true, false, false}},
                                   {"uv", {false, true, false}},
                                   {"normal", {false, false, true}},
                                   {"normal uv", {false, true, true}},
                                   {"rgb normal uv", {true, true, true}},
                                   {"missing uv", {true, true, false}, false}};

    hwy::SetSupportedTargetsForTest(0);
    const std::int64_t targets = spanTargetsCompiled() & hwy::SupportedTargets();
    std::size_t tested = 0;
    for (std::int64_t rest = targets; rest != 0; rest &= rest - 1) {
        const std::int64_t target = rest & -rest;
        hwy::SetSupportedTargetsForTest(target);
        const LaneSetupFn lanes = laneSetup();
        hwy::SetSupportedTargetsForTest(0);
        ASSERT_NE(lanes, nullptr);
        for (const PlaneLayout& pl : layouts) {
            DrawInput in = mesh.input();
            in.colors = streams.colors;
            in.normals = streams.normals;
            in.positions = streams.positions;
            if (pl.withUvs) in.uvs = streams.uvs;
            const VaryingLayout layout = pl.layout;
            const int count = layout.count();
            const LaneInput lanesIn{in.indices.data(),
                                    in.clip.size(),
                                    screen.data(),
                                    kWidth,
                                    kHeight,
                                    0,
                                    false,
                                    in.clip.data(),
                                    varyingStreams(in, layout)};
            const std::string name = std::string(hwy::TargetName(target)) + ", varyings " + pl.name;
            std::size_t checked = 0, refused = 0, mismatched = 0, tried = 0, caught = 0;
            auto chunk = std::make_unique<LaneChunk>();
            // Survivor j (triangle c + k) of the chunk against the scalar stages.
            auto same = [&](std::size_t c, std::uint32_t k, std::uint32_t j) {
                const std::size_t t = 3 * (c + k);
                glm::dvec2 s[3];
                ClipVertex v[3];
                for (int m = 0; m < 3; ++m) {
                    v[m] = fetchVertex(in, layout, in.indices[t + m]);
                    s[m] = screenPosition(v[m].pos);
                }
                int baseX = 0, baseY = 0;
                front::planeBase(s, space.W, space.H, baseX, baseY);
                Planes p;
                const bool usable = makePlanes(s, v, count, baseX, baseY, p);
                const std::int32_t laneBaseX = chunk->base[0][j];
                bool ok = usable == (laneBaseX >= 0);
                auto bits = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
                if (usable && ok) {
                    const float* want[5] = {p.l1, p.l2, p.u1, p.u2, p.q};
                    ok = baseX == laneBaseX && baseY == chunk->base[1][j];
                    for (int i = 0; i < 5; ++i)
                        for (int m = 0; m < 3; ++m)
                            ok = ok && bits(want[i][m], chunk->plane[3 * i + m][j]);
                }
                if (usable) {
                    for (int r = 0; r < count; ++r) {
                        ok = ok && bits(p.a0[r], chunk->varying[r][j]) &&
                             bits(p.d1[r], chunk->varying[kMaxVaryings + r][j]) &&
                             bits(p.d2[r], chunk->varying[2 * kMaxVaryings + r][j]);
                    }
                }
                SnappedTriangle tri;
                for (int m = 0; m < 3; ++m) {
                    tri.x[m] = chunk->x[m][k];
                    tri.y[m] = chunk->y[m][k];
                }
                tri.box = {chunk->box[0][k], chunk->box[1][k], chunk->box[2][k], chunk->box[3][k]};
                tri.area2 = chunk->area2[k];
                CoverageSetup edges;
                edgesOf(tri, edges);
                for (int m = 0; m < 3; ++m) ok = ok && edges.e0[m] == chunk->e0[m][k];
                return ok;
            };
            // Starting at 3: chunks that do not start on a whole vector of triangles.
            for (std::size_t c = 3; c < triangles; c += LaneChunk::kSize) {
                lanes(lanesIn, c, std::min(triangles, c + LaneChunk::kSize), *chunk);
                ASSERT_TRUE(chunk->planes) << name;
                std::uint32_t j = 0;
                for (std::uint32_t e = 0; e < chunk->count; ++e) {
                    if (chunk->at[e] & LaneChunk::kScalar) continue;
                    const std::uint32_t k = chunk->at[e];
                    const bool usable = chunk->base[0][j] >= 0;
                    if (!same(c, k, j) && ++mismatched <= 5)
                        ADD_FAILURE() << name << ": triangle " << c + k << " differs";
                    // The check itself: one varying float of this lane a little off (one
                    // unit in the last place), each row in turn, must be reported.
                    if (usable && count > 0 && j % 3 == 1) {
                        const std::uint32_t row = (j / 3) % count + kMaxVaryings * ((j / 7) % 3);
                        float& f = chunk->varying[row][j];
                        const float kept = f;
                        f = std::nextafter(f, std::numeric_limits<float>::infinity());
                        ++tried;
                        caught += same(c, k, j) ? 0 : 1;
                        f = kept;
                    }
                    refused += usable ? 0 : 1;
                    ++checked;
                    ++j;
                }
            }
            EXPECT_EQ(mismatched, 0u) << name;
            EXPECT_GT(checked, 3000u) << name;  // not vacuous: most triangles reach the planes
            EXPECT_GE(refused, 20u) << name;    // and the collinear pairs reach makePlanes' refusal
            if (count > 0) {
                EXPECT_GT(tried, 500u) << name;
                EXPECT_EQ(caught, tried) << name << ": a changed lane went unseen";
            }
            std::printf("lanes' planes checked on %s: %zu triangles, %zu refused\n", name.c_str(),
                        checked, refused);
        }
        ++tested;
    }
    EXPECT_GE(tested, 1u);
}

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
