// The tile-resident frame: a one-batch solid draw clears and draws each 64×64 tile in a
// per-thread tile buffer and writes it to the frame once, and hierarchical depth rejects triangle
// parts wholly behind a tile's far bound. Neither may change a pixel: each image is compared,
// colour and depth, with the same frame drawn with both switched off (a clear pass, then every
// triangle drawn in the frame), on frames whose sides are not multiples of 64 (partial tiles),
// at 1 and 2 threads.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "binning/tiles.hpp"
#include "facet/procedural.hpp"
#include "facet/render.hpp"
#include "test_scenes.hpp"

namespace facet::test {
namespace {

/// Full-frame quads at depths 2, 3, … seen by a 90° camera at the origin looking down +z:
/// drawn front to back when `frontToBack`, else back to front (the bench's overdraw case).
Scene layers(int count, bool frontToBack, int width, int height) {
    Mesh m;
    const double focal = 0.5 * width;
    for (int i = 0; i < count; ++i) {
        const int layer = frontToBack ? i : count - 1 - i;
        const float z = 2.0f + static_cast<float>(layer);
        const float hx = 1.05f * static_cast<float>(0.5 * width / focal) * z;
        const float hy = 1.05f * static_cast<float>(0.5 * height / focal) * z;
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        const float corners[4][2] = {{-1, -1}, {-1, 1}, {1, 1}, {1, -1}};
        for (const auto& c : corners) m.positions.emplace_back(c[0] * hx, c[1] * hy, z);
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return sceneOf(std::move(m), lookAt({0, 0, 0}, {0, 0, 1}, focal, width, height));
}

struct Drawn {
    Framebuffer frame;
    RenderStats stats;
};

/// `scene` rendered with the tile buffer always or never used (whatever the draw's overdraw),
/// and hierarchical depth (tile and block bounds) on or off.
Drawn render(const Scene& scene, const RenderSettings& settings, bool tileBuffer, bool hiZ) {
    detail::useTileBuffer(tileBuffer ? detail::TileBufferUse::Always
                                     : detail::TileBufferUse::Never);
    detail::enableHiZ(hiZ);
    detail::enableBlockHiZ(hiZ);
    Renderer renderer;
    Drawn d;
    d.stats = renderer.render(scene, settings, d.frame).value();
    detail::useTileBuffer(detail::TileBufferUse::Overdrawn);
    detail::enableHiZ(true);
    detail::enableBlockHiZ(false);
    return d;
}

/// Pixels whose colour or depth differ.
std::size_t differences(const Framebuffer& a, const Framebuffer& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.color.size() && i < b.color.size(); ++i)
        n += a.color[i] != b.color[i] || a.depth[i] != b.depth[i] ? 1 : 0;
    return n;
}

std::vector<RenderSettings> configs() {
    std::vector<RenderSettings> all;
    RenderSettings s;
    s.background = 0x336699;
    s.shader = ShaderKind::Painter;
    s.lighting = Lighting::Gouraud;
    all.push_back(s);
    s.lighting = Lighting::Phong;
    all.push_back(s);
    s.shader = ShaderKind::Depth;
    all.push_back(s);
    s.shader = ShaderKind::Simple;
    s.lighting = Lighting::Off;
    all.push_back(s);
    return all;
}

// Meshes small enough for one batch (tile-resident) and one too large for it, framed so that
// some tiles hold no triangle (they get the clear value straight away).
TEST(TileBuffer, GivesTheImageDrawnInTheFrame) {
    const Mesh meshes[] = {colouredByPosition(makeTorusKnot(2, 3, 64, 12)),
                           colouredByPosition(makeUvSphere(12, 20)),
                           colouredByPosition(makeTorusKnot(2, 3, 256, 24))};
    const int sizes[][2] = {{333, 197}, {128, 64}, {70, 300}};
    int compared = 0;
    for (const Mesh& mesh : meshes)
        for (const auto& size : sizes) {
            const Scene scene =
                sceneOf(mesh, lookAt({0.4, 0.3, -4.5}, {0.3, 0.2, 0}, size[0], size[0], size[1]));
            for (RenderSettings settings : configs())
                for (int threads : {1, 2}) {
                    settings.threads = threads;
                    const Drawn on = render(scene, settings, true, true);
                    const Drawn off = render(scene, settings, false, false);
                    ASSERT_GT(off.stats.fragments, 0u);
                    EXPECT_EQ(differences(on.frame, off.frame), 0u)
                        << mesh.indices.size() / 3 << " triangles at " << size[0] << "x" << size[1]
                        << ", shader " << static_cast<int>(settings.shader) << ", threads "
                        << threads;
                    ++compared;
                }
        }
    EXPECT_EQ(compared, 3 * 3 * 4 * 2);
}

// Full-frame layers: back to front every layer is drawn; front to back hierarchical depth
// rejects every layer's parts behind the first, and the image is the one drawn without it.
TEST(TileBuffer, HierarchicalDepthRejectsLayersBehind) {
    for (bool frontToBack : {false, true})
        for (int threads : {1, 2}) {
            const Scene scene = layers(8, frontToBack, 333, 197);
            RenderSettings settings;
            settings.shader = ShaderKind::Painter;
            settings.threads = threads;
            const Drawn on = render(scene, settings, true, true);
            const Drawn noHiZ = render(scene, settings, true, false);
            const Drawn off = render(scene, settings, false, false);
            EXPECT_EQ(differences(on.frame, off.frame), 0u);
            EXPECT_EQ(differences(noHiZ.frame, off.frame), 0u);
            EXPECT_EQ(noHiZ.stats.hiZTriangles, 0u);
            if (frontToBack) {
                // 6 × 4 tiles, each layer's two triangles touching every tile but for the
                // diagonal's corners: most of the 7 layers behind are rejected.
                EXPECT_GT(on.stats.hiZTriangles, 7u * 24u);
                EXPECT_LT(on.stats.fragments, off.stats.fragments);
            } else {
                EXPECT_EQ(on.stats.hiZTriangles, 0u);  // every layer is in front
                EXPECT_EQ(on.stats.fragments, off.stats.fragments);
            }
        }
}

// What the bound must not reject: a flat layer, then triangles just in front of it (0.1 % nearer)
// and just behind; a tilted layer, then a triangle in front of its far part but behind its near
// part (rejected if the bound were the tile's nearest depth instead of its farthest).
TEST(TileBuffer, BoundKeepsWhatIsInFront) {
    const int w = 256, h = 128;
    const double focal = 0.5 * w;
    for (const float tilt : {0.0f, 0.15f}) {
        Mesh m;
        // The layer: one triangle over the frame (so it covers every tile whole; the two of a
        // quad leave the tiles on their diagonal unbounded), on the plane z = 4 + tilt·x.
        const float hx = 6.0f, hy = 3.0f;
        m.positions = {{-hx, -hy, 4.0f - tilt * hx},
                       {-hx, 3.0f * hy, 4.0f - tilt * hx},
                       {3.0f * hx, -hy, 4.0f + 3.0f * tilt * hx}};
        m.indices = {0, 1, 2};
        // Small triangles at x = ±0.5 (in front of the tilted layer's near and far halves),
        // 0.1 % in front of the layer there or 0.1 % behind, each inside one tile.
        for (const float x : {-0.5f, 0.5f})
            for (const float f : {0.999f, 1.001f}) {
                const float z = (4.0f + tilt * x) * f;
                const auto b = static_cast<std::uint32_t>(m.positions.size());
                m.positions.insert(m.positions.end(),
                                   {{x - 0.1f, 0.2f, z}, {x - 0.1f, 0.4f, z}, {x + 0.1f, 0.3f, z}});
                m.indices.insert(m.indices.end(), {b, b + 1, b + 2});
            }
        const Scene scene = sceneOf(std::move(m), lookAt({0, 0, 0}, {0, 0, 1}, focal, w, h));
        for (ShaderKind shader : {ShaderKind::Painter, ShaderKind::Depth}) {
            RenderSettings settings;
            settings.shader = shader;
            settings.threads = 1;
            const Drawn on = render(scene, settings, true, true);
            const Drawn off = render(scene, settings, false, false);
            EXPECT_EQ(differences(on.frame, off.frame), 0u) << "tilt " << tilt;
            // Flat: the two behind are rejected; tilted, the far bounds of their tiles are
            // behind them; the two in front never are.
            EXPECT_LE(on.stats.hiZTriangles, 2u) << "tilt " << tilt;
            if (tilt == 0.0f) {
                EXPECT_EQ(on.stats.hiZTriangles, 2u);
            }
        }
    }
}

/// Appends a grid of nx × ny quads (two triangles each) on the plane z = z0 + tilt·x, covering
/// the screen rectangle [u0, u1] × [v0, v1] of the 90° camera of layers() (u, v in -1 … 1 across
/// the frame's width and height): quads of a few pixels, none covering a 8×8 block.
void addGrid(Mesh& m, float z0, float tilt, int nx, int ny, float u0, float u1, float v0, float v1,
             float aspect) {
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const float u = u0 + (u1 - u0) * static_cast<float>(i) / static_cast<float>(nx);
            const float v = v0 + (v1 - v0) * static_cast<float>(j) / static_cast<float>(ny);
            const float z = z0 / (1.0f - tilt * u);  // on the plane, seen at (u, v)
            m.positions.emplace_back(u * z, v * z * aspect, z);
        }
    const auto at = [&](int i, int j) {
        return base + static_cast<std::uint32_t>(j * (nx + 1) + i);
    };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j),
                                               at(i + 1, j + 1), at(i, j + 1)});
}

// Per-block bounds on a dense mesh (no triangle covers a tile, nor a block): a layer of small
// triangles over the frame, then the same layer behind it, then again at equal depth, then a
// patch 0.001 % in front of it. Every triangle part of the layer behind is rejected (the tile bound
// alone rejects none), blocks cut by the frame's edge included; the patch is drawn; the image is
// the one drawn without hierarchical depth, in the tile buffer and in the frame, at 1 and 2
// threads.
TEST(TileBuffer, BlockBoundsRejectSmallTrianglesBehind) {
    const int w = 333, h = 197;  // tiles and blocks cut by the frame's edges
    const float aspect = static_cast<float>(h) / static_cast<float>(w);
    const int nx = w / 4, ny = h / 4;
    Mesh m;
    addGrid(m, 2.0f, 0.0f, nx, ny, -1.05f, 1.05f, -1.05f, 1.05f, aspect);
    addGrid(m, 3.0f, 0.0f, nx, ny, -1.05f, 1.05f, -1.05f, 1.05f, aspect);
    addGrid(m, 2.0f, 0.0f, nx, ny, -1.05f, 1.05f, -1.05f, 1.05f, aspect);
    addGrid(m, 2.0f * (1.0f - 1e-5f), 0.0f, 8, 8, -0.3f, 0.2f, -0.4f, 0.1f, aspect);
    const std::size_t behind = 2u * static_cast<std::size_t>(nx * ny);
    const Scene scene =
        sceneOf(colouredByPosition(std::move(m)), lookAt({0, 0, 0}, {0, 0, 1}, 0.5 * w, w, h));
    for (ShaderKind shader : {ShaderKind::Painter, ShaderKind::Depth})
        for (bool tileBuffer : {true, false})
            for (int threads : {1, 2}) {
                RenderSettings settings;
                settings.shader = shader;
                settings.threads = threads;
                const Drawn on = render(scene, settings, tileBuffer, true);
                const Drawn off = render(scene, settings, false, false);
                EXPECT_EQ(differences(on.frame, off.frame), 0u)
                    << "buffer " << tileBuffer << ", " << threads << " threads";
                // The layer behind, whole (at equal depth, the margins keep the triangles).
                EXPECT_GE(on.stats.hiZTriangles, behind)
                    << "buffer " << tileBuffer << ", " << threads << " threads";
                EXPECT_LT(on.stats.fragments, off.stats.fragments);
            }
}

// What per-block bounds must not reject: a tilted layer of small triangles, then in every block
// of a region a flat triangle at the layer's depth at the block's centre (in front of the
// block's far part, behind its near part: rejected if a block's bound were its nearest depth),
// and flat triangles 0.001 % in front of a flat layer's depth.
TEST(TileBuffer, BlockBoundsKeepWhatIsInFront) {
    const int w = 256, h = 136;
    const float aspect = static_cast<float>(h) / static_cast<float>(w);
    for (const float tilt : {0.0f, 0.3f}) {
        Mesh m;
        addGrid(m, 4.0f, tilt, w / 3, h / 3, -1.05f, 1.05f, -1.05f, 1.05f, aspect);
        const float nearer = tilt == 0.0f ? 1.0f - 1e-5f : 1.0f;
        for (int by = 2; by < 12; ++by)
            for (int bx = 2; bx < 28; ++bx) {
                // The block's centre pixel, in the camera's screen coordinates (−1 … 1).
                const float u = (8.0f * static_cast<float>(bx) + 4.0f) / (0.5f * w) - 1.0f;
                const float v = (8.0f * static_cast<float>(by) + 4.0f) / (0.5f * h) - 1.0f;
                const float z = 4.0f / (1.0f - tilt * u) * nearer;
                const float du = 3.0f / (0.5f * w), dv = 3.0f / (0.5f * h);
                const auto b = static_cast<std::uint32_t>(m.positions.size());
                m.positions.insert(m.positions.end(), {{(u - du) * z, (v - dv) * z * aspect, z},
                                                       {(u - du) * z, (v + dv) * z * aspect, z},
                                                       {(u + du) * z, v * z * aspect, z}});
                m.indices.insert(m.indices.end(), {b, b + 1, b + 2});
            }
        const Scene scene =
            sceneOf(colouredByPosition(std::move(m)), lookAt({0, 0, 0}, {0, 0, 1}, 0.5 * w, w, h));
        for (ShaderKind shader : {ShaderKind::Painter, ShaderKind::Depth})
            for (int threads : {1, 2}) {
                RenderSettings settings;
                settings.shader = shader;
                settings.threads = threads;
                const Drawn on = render(scene, settings, true, true);
                const Drawn off = render(scene, settings, false, false);
                EXPECT_EQ(differences(on.frame, off.frame), 0u)
                    << "tilt " << tilt << ", " << threads << " threads";
                EXPECT_EQ(on.stats.fragments, off.stats.fragments) << "tilt " << tilt;
            }
    }
}

// The default choice (the buffer only on a frame larger than the caches whose boxes cover it
// twice or more): 8 full-screen layers at 1920×1080 reside, the same layers at 333×197 and a
// torus knot framed in part of the frame are drawn in the frame after a clear; all give the
// image drawn without the buffer.
TEST(TileBuffer, DefaultChoiceGivesTheImageDrawnInTheFrame) {
    const Scene scenes[] = {layers(8, false, 1920, 1080), layers(8, false, 333, 197),
                            sceneOf(colouredByPosition(makeTorusKnot(2, 3, 64, 12)),
                                    lookAt({0.4, 0.3, -9.0}, {0.3, 0.2, 0}, 333, 333, 197))};
    for (const Scene& scene : scenes)
        for (int threads : {1, 2}) {
            RenderSettings settings;
            settings.shader = ShaderKind::Painter;
            settings.background = 0x336699;
            settings.threads = threads;
            Renderer renderer;
            Drawn byDefault;
            byDefault.stats = renderer.render(scene, settings, byDefault.frame).value();
            const Drawn off = render(scene, settings, false, true);
            ASSERT_GT(off.stats.fragments, 0u);
            EXPECT_EQ(differences(byDefault.frame, off.frame), 0u) << threads << " threads";
        }
}

}  // namespace
}  // namespace facet::test
