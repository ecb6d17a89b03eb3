// Unit tests of the reference path: the rules it is the specification of, each checked against
// an answer worked out by hand (pixel counts, analytic depths and colours), not against itself.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "facet/colormap.hpp"
#include "facet/framebuffer.hpp"
#include "facet/lighting.hpp"
#include "facet/normals.hpp"
#include "facet/procedural.hpp"
#include "facet/reference.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"
#include "facet/texture.hpp"
#include "reference/samplers.hpp"

namespace {

using facet::DrawMode;
using facet::Interp;
using facet::Lighting;
using facet::RenderSettings;
using facet::ShaderKind;
using facet::reference::draw;
using facet::reference::Image;
using facet::reference::Input;

// A vertex already in screen space: w = 1, so pixel = (x, y) and depth = 1.
glm::dvec4 screen(double x, double y) {
    return {x, y, 1.0, 1.0};
}

// Camera-space point (X, Y, Z) in clip space for focal f and principal point (cx, cy).
glm::dvec4 camera(double x, double y, double z, double f, double cx, double cy) {
    return {f * x + cx * z, f * y + cy * z, z, z};
}

RenderSettings settingsFor(DrawMode mode, ShaderKind shader = ShaderKind::Painter,
                           Interp interp = Interp::Perspective) {
    RenderSettings s;
    s.mode = mode;
    s.shader = shader;
    s.interp = interp;
    return s;
}

Image drawClip(const std::vector<glm::dvec4>& clip, const std::vector<std::uint32_t>& indices,
               const RenderSettings& settings, int width, int height,
               const std::vector<glm::dvec3>& colors = {}, double nearPlane = 1e-3) {
    Input input;
    input.clip = clip;
    input.colors = colors;
    input.indices = indices;
    input.nearPlane = nearPlane;
    return draw(input, settings, width, height);
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b) {
    EXPECT_NEAR(a.r, b.r, 1e-9);
    EXPECT_NEAR(a.g, b.g, 1e-9);
    EXPECT_NEAR(a.b, b.b, 1e-9);
}

bool covered(const Image& img, int x, int y) {
    return std::isfinite(img.depth[static_cast<std::size_t>(y * img.width + x)]);
}

int coveredCount(const Image& img) {
    int n = 0;
    for (const double d : img.depth) n += std::isfinite(d) ? 1 : 0;
    return n;
}

const glm::dvec3& colorAt(const Image& img, int x, int y) {
    return img.color[static_cast<std::size_t>(y * img.width + x)];
}

// Adds 1 per pixel each triangle covers, drawing every triangle on its own image, so a pixel
// claimed by two triangles counts 2 even though the image would hide it.
std::vector<int> coverageCounts(const std::vector<glm::dvec4>& clip,
                                const std::vector<std::uint32_t>& indices, int width, int height) {
    std::vector<int> counts(static_cast<std::size_t>(width * height), 0);
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const Image img = drawClip(clip, {indices[t], indices[t + 1], indices[t + 2]},
                                   settingsFor(DrawMode::Solid), width, height);
        for (std::size_t i = 0; i < counts.size(); ++i) {
            counts[i] += std::isfinite(img.depth[i]) ? 1 : 0;
        }
    }
    return counts;
}

TEST(Reference, Direct3DFillRuleExamples) {
    const RenderSettings s = settingsFor(DrawMode::Solid);
    // (0,0),(5,0),(5,5): the top edge and the diagonal (a left edge) are in, the right edge out.
    const std::vector<glm::dvec4> a{screen(0, 0), screen(5, 0), screen(5, 5)};
    for (const auto& idx : {std::vector<std::uint32_t>{0, 1, 2}, {0, 2, 1}}) {
        const Image img = drawClip(a, idx, s, 8, 8);
        EXPECT_EQ(coveredCount(img), 15);
        for (int y = 0; y < 8; ++y) {
            for (int x = 0; x < 8; ++x) EXPECT_EQ(covered(img, x, y), x < 5 && y <= x);
        }
    }
    // (0,5),(0,0),(5,5): the left edge is in, the diagonal and the bottom edge out.
    const std::vector<glm::dvec4> b{screen(0, 5), screen(0, 0), screen(5, 5)};
    for (const auto& idx : {std::vector<std::uint32_t>{0, 1, 2}, {0, 2, 1}}) {
        const Image img = drawClip(b, idx, s, 8, 8);
        EXPECT_EQ(coveredCount(img), 10);
        for (int y = 0; y < 8; ++y) {
            for (int x = 0; x < 8; ++x) EXPECT_EQ(covered(img, x, y), y < 5 && y > x);
        }
    }
}

TEST(Reference, SplitSquareCoversEveryPixelOnce) {
    // Square [0.5, 8.5]² with edges and diagonals through pixel centres, split along either
    // diagonal, both windings: the halves must tile the 8×8 pixels whose centres are in
    // [0.5, 8.5)² exactly once.
    const std::vector<glm::dvec4> v{screen(0.5, 0.5), screen(8.5, 0.5), screen(8.5, 8.5),
                                    screen(0.5, 8.5)};
    const std::vector<std::vector<std::uint32_t>> splits{{0, 1, 2, 0, 2, 3}, {0, 2, 1, 0, 3, 2},
                                                         {1, 2, 3, 1, 3, 0}, {1, 3, 2, 1, 0, 3},
                                                         {0, 1, 2, 0, 3, 2}, {3, 1, 0, 3, 2, 1}};
    for (const auto& idx : splits) {
        const std::vector<int> counts = coverageCounts(v, idx, 10, 10);
        for (int y = 0; y < 10; ++y) {
            for (int x = 0; x < 10; ++x) {
                const int expected = (x < 8 && y < 8) ? 1 : 0;
                EXPECT_EQ(counts[static_cast<std::size_t>(y * 10 + x)], expected)
                    << "pixel " << x << "," << y;
            }
        }
    }
}

TEST(Reference, JitteredGridMeshCoversEveryPixelOnce) {
    // A grid mesh whose inner vertices sit on pixel centres, corners and odd fractions, split
    // along alternating diagonals with alternating windings: no cracks and no double coverage
    // anywhere inside its border [0.5, 24.5)².
    constexpr int kCells = 6;
    std::vector<glm::dvec4> v;
    const double jitter[] = {0.0, 0.5, -0.5, 0.25, 1.0 / 3.0, -0.75, 0.125};
    int j = 0;
    for (int gy = 0; gy <= kCells; ++gy) {
        for (int gx = 0; gx <= kCells; ++gx) {
            double x = 0.5 + 4.0 * gx;
            double y = 0.5 + 4.0 * gy;
            if (gx > 0 && gx < kCells && gy > 0 && gy < kCells) {
                x += jitter[j++ % 7];
                y += jitter[j++ % 7];
            }
            v.push_back(screen(x, y));
        }
    }
    std::vector<std::uint32_t> idx;
    for (int gy = 0; gy < kCells; ++gy) {
        for (int gx = 0; gx < kCells; ++gx) {
            const auto at = [&](int x, int y) {
                return static_cast<std::uint32_t>(y * (kCells + 1) + x);
            };
            const std::uint32_t a = at(gx, gy), b = at(gx + 1, gy), c = at(gx + 1, gy + 1),
                                d = at(gx, gy + 1);
            if ((gx + gy) % 2 == 0) {
                idx.insert(idx.end(), {a, b, c, a, d, c});
            } else {
                idx.insert(idx.end(), {b, c, d, b, a, d});
            }
        }
    }
    const std::vector<int> counts = coverageCounts(v, idx, 28, 28);
    for (int y = 0; y < 28; ++y) {
        for (int x = 0; x < 28; ++x) {
            EXPECT_EQ(counts[static_cast<std::size_t>(y * 28 + x)], (x < 24 && y < 24) ? 1 : 0)
                << "pixel " << x << "," << y;
        }
    }
}

TEST(Reference, CullingDropsExactlyTheBackFace) {
    // On the y-down screen a front face (counter-clockwise from outside, y up) has A < 0.
    const std::vector<glm::dvec4> v{screen(0, 0),  screen(5, 5),  screen(5, 0),
                                    screen(10, 0), screen(15, 0), screen(15, 5)};
    const std::vector<std::uint32_t> idx{0, 1, 2, 3, 4, 5};  // front at left, back at right
    RenderSettings s = settingsFor(DrawMode::Solid);
    EXPECT_EQ(coveredCount(drawClip(v, idx, s, 16, 8)), 30);
    s.cullBackFaces = true;
    const Image culled = drawClip(v, idx, s, 16, 8);
    EXPECT_EQ(coveredCount(culled), 15);
    EXPECT_TRUE(covered(culled, 4, 0));
    EXPECT_FALSE(covered(culled, 14, 0));
}

TEST(Reference, ProjectedFrontFaceSurvivesCulling) {
    // The course camera (up = (0,-1,0)) looking along +z: a triangle whose outside faces the
    // camera (normal -z) must be kept, its reverse culled; world +Y must point up on screen.
    facet::Scene scene;
    scene.camera = {{0.0, 0.0, -5.0}, {0.0, 0.0, 0.0}, {0.0, -1.0, 0.0}, 100.0, 64, 64};
    facet::Mesh mesh;
    mesh.positions = {{0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {1.0f, 0.0f, 0.0f}};
    mesh.indices = {0, 1, 2};
    scene.mesh = std::make_shared<const facet::Mesh>(mesh);
    const std::vector<glm::dvec4> clip = facet::reference::projectScene(scene);
    ASSERT_EQ(clip.size(), 3u);
    EXPECT_DOUBLE_EQ(clip[0].x / clip[0].w, 32.0);  // the look-at point is the image centre
    EXPECT_DOUBLE_EQ(clip[0].y / clip[0].w, 32.0);
    EXPECT_DOUBLE_EQ(clip[0].w, 5.0);
    EXPECT_DOUBLE_EQ(clip[1].y / clip[1].w, 12.0);  // +Y is up: smaller row
    EXPECT_LT(clip[2].x / clip[2].w, 32.0);         // seen from -z, world +X is on the left

    RenderSettings s = settingsFor(DrawMode::Solid);
    s.cullBackFaces = true;
    s.nearPlane = 0.01;
    EXPECT_GT(coveredCount(facet::reference::render(scene, s).value()), 100);
    mesh.indices = {0, 2, 1};
    scene.mesh = std::make_shared<const facet::Mesh>(mesh);
    EXPECT_EQ(coveredCount(facet::reference::render(scene, s).value()), 0);
}

// Camera-space triangles on the floor plane Y = 1 that cross the camera plane Z = 0: every pixel
// must match the analytic projection of the part in front of the near plane.
TEST(Reference, NearClippingMatchesAnalyticRegion) {
    constexpr double f = 16.0, c = 32.0, nearPlane = 0.01;
    struct Case {
        std::vector<glm::dvec4> v;
        // Region of pixel centres, as a signed margin (> 0 inside) in pixels.
        double (*margin)(double x, double y);
    };
    const std::vector<Case> cases{
        // One vertex behind: a quad after clipping. Rows below the far edge (Z = 4, y = c + f/4),
        // between the images of the side edges |x - c| = 2(y - c) + f/2.
        {{camera(-4, 1, 4, f, c, c), camera(4, 1, 4, f, c, c), camera(0, 1, -4, f, c, c)},
         [](double x, double y) {
             return std::min(y - (c + f / 4), 2 * (y - c) + f / 2 - std::abs(x - c));
         }},
        // Two vertices behind: a triangle after clipping, apex at (c, c + f/4).
        {{camera(0, 1, 4, f, c, c), camera(-4, 1, -4, f, c, c), camera(4, 1, -4, f, c, c)},
         [](double x, double y) { return 2 * (y - c) - f / 2 - std::abs(x - c); }},
    };
    for (const Case& k : cases) {
        for (const auto& idx : {std::vector<std::uint32_t>{0, 1, 2}, {1, 2, 0}, {2, 1, 0}}) {
            const Image img =
                drawClip(k.v, idx, settingsFor(DrawMode::Solid), 64, 64, {}, nearPlane);
            int inside = 0;
            for (int y = 0; y < 64; ++y) {
                for (int x = 0; x < 64; ++x) {
                    const glm::dvec3& col = colorAt(img, x, y);
                    ASSERT_FALSE(std::isnan(col.r) || std::isnan(col.g) || std::isnan(col.b));
                    const double m = k.margin(x + 0.5, y + 0.5);
                    if (std::abs(m) < 1e-9) continue;  // on the boundary: the fill rule decides
                    EXPECT_EQ(covered(img, x, y), m > 0) << "pixel " << x << "," << y;
                    if (m <= 0) continue;
                    ++inside;
                    // Perspective-correct depth of the floor: Z = f / (y - c).
                    const double depth = img.depth[static_cast<std::size_t>(y * 64 + x)];
                    EXPECT_NEAR(depth, f / (y + 0.5 - c), 1e-9);
                }
            }
            EXPECT_GT(inside, 300);
        }
    }
}

TEST(Reference, ClippedSharedEdgeHasNoCracks) {
    // A floor quad crossing the camera plane, split along a diagonal that is itself clipped, in
    // both windings: the two clipped halves still cover each pixel exactly once, and together
    // exactly the visible part of the quad (|x - c| within the two side edges, below Z = 4).
    constexpr double f = 16.0, c = 32.0;
    const std::vector<glm::dvec4> v{camera(-4, 1, 4, f, c, c), camera(4, 1, 4, f, c, c),
                                    camera(4, 1, -4, f, c, c), camera(-4, 1, -4, f, c, c)};
    for (const auto& idx :
         {std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}, {1, 3, 0, 1, 2, 3}, {2, 1, 0, 3, 2, 0}}) {
        const std::vector<int> counts = coverageCounts(v, idx, 64, 64);
        int inside = 0;
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                const int n = counts[static_cast<std::size_t>(y * 64 + x)];
                EXPECT_LE(n, 1) << "pixel " << x << "," << y;
                // Visible part: Z in [near, 4], so y - c >= f/4, and |X| <= 4: |x - c| <= 4·f/Z.
                const double dy = y + 0.5 - c, dx = x + 0.5 - c;
                const double m = std::min(dy - f / 4, 4 * dy - std::abs(dx));
                if (std::abs(m) < 1e-9) continue;
                EXPECT_EQ(n, m > 0 ? 1 : 0) << "pixel " << x << "," << y;
                inside += n;
            }
        }
        EXPECT_GT(inside, 1000);
    }
}

TEST(Reference, PerspectiveAndAffineColours) {
    // A floor quad from Z = 2 (red) to Z = 8 (green): perspective-correct green is exactly
    // (Z - 2) / 6 at every pixel, affine is not.
    constexpr double f = 32.0, c = 32.0;
    const std::vector<glm::dvec4> v{camera(-2, 1, 2, f, c, c), camera(2, 1, 2, f, c, c),
                                    camera(2, 1, 8, f, c, c), camera(-2, 1, 8, f, c, c)};
    const std::vector<glm::dvec3> col{{1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0}};
    const std::vector<std::uint32_t> idx{0, 1, 2, 0, 2, 3};
    const Image persp = drawClip(v, idx, settingsFor(DrawMode::Solid), 64, 64, col);
    const Image affine = drawClip(
        v, idx, settingsFor(DrawMode::Solid, ShaderKind::Painter, Interp::Affine), 64, 64, col);
    double maxDiff = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < persp.depth.size(); ++i) {
        ASSERT_EQ(std::isfinite(persp.depth[i]), std::isfinite(affine.depth[i]));
        if (!std::isfinite(persp.depth[i])) continue;
        ++n;
        EXPECT_NEAR(persp.color[i].g, (persp.depth[i] - 2.0) / 6.0, 1e-9);
        EXPECT_NEAR(persp.color[i].r + persp.color[i].g, 1.0, 1e-9);
        EXPECT_EQ(persp.depth[i], affine.depth[i]);  // depth is perspective-correct in both
        maxDiff = std::max(maxDiff, std::abs(persp.color[i].g - affine.color[i].g));
    }
    EXPECT_GT(n, 200);
    EXPECT_GT(maxDiff, 0.1);

    // With equal w the two agree.
    std::vector<glm::dvec4> flat;
    for (const glm::dvec4& p : v) flat.push_back({3.0 * p.x / p.w, 3.0 * p.y / p.w, 3.0, 3.0});
    const Image a = drawClip(flat, idx, settingsFor(DrawMode::Solid), 64, 64, col);
    const Image b = drawClip(
        flat, idx, settingsFor(DrawMode::Solid, ShaderKind::Painter, Interp::Affine), 64, 64, col);
    for (std::size_t i = 0; i < a.color.size(); ++i) {
        EXPECT_NEAR(a.color[i].r, b.color[i].r, 1e-12);
        EXPECT_NEAR(a.color[i].g, b.color[i].g, 1e-12);
    }
}

// A single edge drawn through wireframe mode: triangle (0, 1, 1) has just the edge {0, 1}.
Image drawLine(glm::dvec2 a, glm::dvec2 b, int size, glm::dvec3 ca = {1, 0, 0},
               glm::dvec3 cb = {0, 0, 1}) {
    return drawClip({screen(a.x, a.y), screen(b.x, b.y)}, {0, 1, 1},
                    settingsFor(DrawMode::Wireframe, ShaderKind::Simple), size, size, {ca, cb});
}

int colouredCount(const Image& img) {
    int n = 0;
    for (const glm::dvec3& c : img.color) n += (c.r + c.b > 0.99) ? 1 : 0;
    return n;
}

TEST(Reference, SteepLineInterpolatesAlongItsLength) {
    // 3 across, 19 down: 20 pixels, one per row, endpoints included, red fading to blue by row.
    const Image img = drawLine({2.5, 1.5}, {5.5, 20.5}, 24);
    EXPECT_EQ(colouredCount(img), 20);
    EXPECT_EQ(colorAt(img, 2, 1), glm::dvec3(1, 0, 0));
    EXPECT_EQ(colorAt(img, 5, 20), glm::dvec3(0, 0, 1));
    for (int y = 1; y <= 20; ++y) {
        int inRow = 0;
        for (int x = 0; x < 24; ++x) {
            const glm::dvec3& c = colorAt(img, x, y);
            if (c.r + c.b < 0.99) continue;
            ++inRow;
            EXPECT_NEAR(c.b, (y - 1) / 19.0, 1e-12) << "row " << y;
        }
        EXPECT_EQ(inRow, 1) << "row " << y;
    }
}

TEST(Reference, LineMinorStepRoundsToNearestTiesUp) {
    // From pixel (4, 4): 4 across and 2 up or down. Pixel k has minor offset round(k·dy/4) with
    // ties (k = 1, 3) going towards +y whichever the direction.
    for (const int dy : {2, -2}) {
        const Image img = drawLine({4.5, 4.5}, {8.5, 4.5 + dy}, 12);
        const int expected[] = {0, dy > 0 ? 1 : 0, dy / 2, dy > 0 ? 2 : -1, dy};
        for (int k = 0; k <= 4; ++k) {
            const glm::dvec3& c = colorAt(img, 4 + k, 4 + expected[k]);
            EXPECT_NEAR(c.b, k / 4.0, 1e-12) << "dy " << dy << " k " << k;
        }
        EXPECT_EQ(colouredCount(img), 5);
    }
}

TEST(Reference, LinesInEveryOctantHaveMaxDeltaPlusOnePixels) {
    // Both directions of each segment draw n + 1 pixels, n = max(|dx|, |dy|) in pixels.
    const glm::dvec2 centre{16.25, 16.75};
    const std::vector<glm::dvec2> ends{{28.5, 20.5}, {20.5, 29.5}, {12.5, 29.5}, {3.5, 21.5},
                                       {3.5, 12.5},  {13.5, 2.5},  {19.5, 3.5},  {29.5, 9.5},
                                       {28.5, 16.5}, {16.5, 2.5},  {28.5, 28.5}, {4.5, 4.5}};
    for (const glm::dvec2& e : ends) {
        const int n = std::max(std::abs(static_cast<int>(std::floor(e.x)) - 16),
                               std::abs(static_cast<int>(std::floor(e.y)) - 16));
        EXPECT_EQ(colouredCount(drawLine(centre, e, 32)), n + 1) << e.x << "," << e.y;
        EXPECT_EQ(colouredCount(drawLine(e, centre, 32)), n + 1) << e.x << "," << e.y;
    }
    // A zero-length segment is one pixel.
    EXPECT_EQ(colouredCount(drawLine({7.2, 7.9}, {7.8, 7.1}, 16)), 1);
}

TEST(Reference, HugeClippedLineStaysCheapAndCorrect) {
    // A segment millions of pixels long: only the pixels inside the image are drawn, on the line.
    const Image img = drawLine({-3.0e6 + 0.5, 5.5}, {3.0e6 + 0.5, 5.5}, 16);
    EXPECT_EQ(colouredCount(img), 16);
    for (int x = 0; x < 16; ++x) EXPECT_GT(colorAt(img, x, 5).r + colorAt(img, x, 5).b, 0.99);
}

TEST(Reference, DepthShaderMapsNearToViridisZeroAndFarToOne) {
    // Two overlapping screen triangles at w = 2 and w = 6, the far one drawn second.
    std::vector<glm::dvec4> v;
    for (const double w : {2.0, 6.0}) {
        for (const glm::dvec2 p : {glm::dvec2{1, 1}, glm::dvec2{12, 2}, glm::dvec2{3, 14}}) {
            const glm::dvec2 q = w == 2.0 ? p : p + glm::dvec2{3, 3};
            v.push_back({q.x * w, q.y * w, w, w});
        }
    }
    RenderSettings s = settingsFor(DrawMode::Solid, ShaderKind::Depth);
    s.background = 0x102030;
    const Image img = drawClip(v, {0, 1, 2, 3, 4, 5}, s, 20, 20);
    // Constant w interpolates to within rounding of itself, hence NEAR rather than EQ.
    expectNear(colorAt(img, 2, 2), facet::viridis(0.0));   // only the near one
    expectNear(colorAt(img, 5, 5), facet::viridis(0.0));   // both: the near one wins
    expectNear(colorAt(img, 14, 5), facet::viridis(1.0));  // only the far one
    EXPECT_EQ(colorAt(img, 19, 19), glm::dvec3(0x10 / 255.0, 0x20 / 255.0, 0x30 / 255.0));
}

TEST(Reference, SimpleLastWinsPainterNearestWins) {
    // Triangles 0 (red, w = 1), 1 (green, w = 0.5, nearer) and 2 (blue, w = 1, the same
    // place and depth as 0 but wound the other way), all covering the same pixels.
    const std::vector<glm::dvec4> v{screen(0, 0),     screen(8, 0),     screen(0, 8),
                                    {0, 0, 0.5, 0.5}, {4, 0, 0.5, 0.5}, {0, 4, 0.5, 0.5},
                                    screen(0, 0),     screen(0, 8),     screen(8, 0)};
    const std::vector<glm::dvec3> col{{1, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 1, 0},
                                      {0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    const std::vector<std::uint32_t> nearFirst{3, 4, 5, 0, 1, 2};
    const Image simple =
        drawClip(v, nearFirst, settingsFor(DrawMode::Solid, ShaderKind::Simple), 8, 8, col);
    EXPECT_EQ(colorAt(simple, 2, 2), glm::dvec3(1, 0, 0));  // last drawn
    EXPECT_TRUE(std::isinf(simple.depth[2 * 8 + 2]));       // Simple never writes depth
    const Image painter = drawClip(v, nearFirst, settingsFor(DrawMode::Solid), 8, 8, col);
    EXPECT_EQ(colorAt(painter, 2, 2), glm::dvec3(0, 1, 0));  // nearest
    EXPECT_NEAR(painter.depth[2 * 8 + 2], 0.5, 1e-12);
    EXPECT_EQ(painter.ambiguous[2 * 8 + 2], 0);  // depths 0.5 and 1 are far apart
    // Equal depths: the first drawn stays, and the tie is flagged as ambiguous.
    const Image tie = drawClip(v, {0, 1, 2, 6, 7, 8}, settingsFor(DrawMode::Solid), 8, 8, col);
    EXPECT_EQ(colorAt(tie, 2, 2), glm::dvec3(1, 0, 0));
    EXPECT_EQ(tie.ambiguous[2 * 8 + 2], 1);
}

TEST(Reference, AmbiguityMarksEdgesThroughPixelCentres) {
    // The diagonal of this triangle passes exactly through pixel centres (i + .5, i + .5).
    const Image img = drawClip({screen(0.5, 0.5), screen(9.5, 0.5), screen(9.5, 9.5)}, {0, 1, 2},
                               settingsFor(DrawMode::Solid), 12, 12);
    for (int i = 0; i <= 9; ++i) {
        EXPECT_EQ(img.ambiguous[static_cast<std::size_t>(i * 12 + i)], 1) << i;
    }
    EXPECT_EQ(img.ambiguous[1 * 12 + 5], 0);    // well inside
    EXPECT_EQ(img.ambiguous[8 * 12 + 2], 0);    // well outside
    EXPECT_EQ(img.ambiguous[11 * 12 + 11], 0);  // beyond the corner, off the grown triangle
}

TEST(Reference, PointsAreSquaresClippedToTheImage) {
    const std::vector<glm::dvec4> v{screen(10.3, 7.8), screen(0.6, 0.4), {5, 5, -1, -1}};
    const Image img =
        drawClip(v, {}, settingsFor(DrawMode::Vertices), 20, 20, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    int red = 0, green = 0;
    for (int y = 0; y < 20; ++y) {
        for (int x = 0; x < 20; ++x) {
            const glm::dvec3& c = colorAt(img, x, y);
            if (c == glm::dvec3(1, 0, 0)) {
                ++red;
                EXPECT_TRUE(x >= 8 && x <= 12 && y >= 5 && y <= 9) << x << "," << y;
            }
            if (c == glm::dvec3(0, 1, 0)) ++green;
            EXPECT_NE(c, glm::dvec3(0, 0, 1));  // behind the camera
        }
    }
    EXPECT_EQ(red, 25);
    EXPECT_EQ(green, 9);  // 5x5 around pixel (0, 0), cut to 3x3

    RenderSettings s = settingsFor(DrawMode::Vertices);
    s.pointSize = 4;  // even: one more pixel on the +x/+y side
    const Image even = drawClip({screen(10.3, 7.8)}, {}, s, 20, 20);
    EXPECT_EQ(coveredCount(even), 16);
    EXPECT_TRUE(covered(even, 9, 6));
    EXPECT_TRUE(covered(even, 12, 9));
    EXPECT_EQ(even.depth[7 * 20 + 10], 1.0);
}

TEST(Reference, ToRgbaClampsRoundsAndPacks) {
    Image img;
    img.width = 3;
    img.height = 1;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    img.color = {{0.5, 1.0 / 255.0, 0.0}, {-1.0, 2.0, nan}, {0.2 / 255.0, 254.6 / 255.0, 1.0}};
    const std::vector<std::uint32_t> rgba = img.toRgba();
    ASSERT_EQ(rgba.size(), 3u);
    EXPECT_EQ(rgba[0], facet::packRgba(128, 1, 0));
    EXPECT_EQ(rgba[1], facet::packRgba(0, 255, 0));
    EXPECT_EQ(rgba[2], facet::packRgba(0, 255, 255));
    EXPECT_EQ(rgba[0] >> 24, 255u);
}

TEST(Reference, BackgroundAndWhiteDefault) {
    RenderSettings s = settingsFor(DrawMode::Solid);
    s.background = 0x5C5C5C;
    const Image img = drawClip({screen(0, 0), screen(4, 0), screen(0, 4)}, {0, 1, 2}, s, 6, 6);
    EXPECT_EQ(colorAt(img, 0, 0), glm::dvec3(1.0));  // no colours: white
    EXPECT_EQ(colorAt(img, 5, 5), glm::dvec3(0x5C / 255.0));
    EXPECT_EQ(img.toRgba()[35], facet::rgbaFromHex(0x5C5C5C));
    EXPECT_TRUE(std::isinf(img.depth[35]));
}

// ---- Shading: lighting (rule 12), textures (rules 8(d), 13), interpolation (rule 11) and the
// normals display (rule 14).

// The course camera looking at the origin from z = -5: world +Y is up on screen, +X to the left.
facet::Scene sceneWith(const facet::Mesh& mesh, int size, double focal) {
    facet::Scene scene;
    scene.camera = {{0.0, 0.0, -5.0}, {0.0, 0.0, 0.0}, {0.0, -1.0, 0.0}, focal, size, size};
    scene.mesh = std::make_shared<const facet::Mesh>(mesh);
    return scene;
}

RenderSettings lit(DrawMode mode, Lighting lighting) {
    RenderSettings s = settingsFor(mode);
    s.lighting = lighting;
    return s;
}

TEST(Reference, PhongEqualsGouraudOnAFlatTriangle) {
    // One triangle facing the camera (normal -z at every vertex), a directional light and no
    // specular term: I is the same everywhere, so both are flat and equal to the hand value.
    facet::Mesh mesh;
    mesh.positions = {{-1.5f, -1.5f, 0.0f}, {-1.5f, 1.5f, 0.0f}, {1.5f, -1.5f, 0.0f}};
    mesh.indices = {0, 1, 2};
    facet::Scene scene = sceneWith(mesh, 64, 80.0);
    scene.lighting.light = {{0.3, 0.2, -1.0, 0.0}, 1.0};
    scene.lighting.material = {0.2, 0.6, 0.0, 1.0};
    const double expected = 0.2 + 0.6 / std::sqrt(1.13);  // Ia·Ka + Id·Kd·(n·l)
    const Image gouraud =
        facet::reference::render(scene, lit(DrawMode::Solid, Lighting::Gouraud)).value();
    const Image phong =
        facet::reference::render(scene, lit(DrawMode::Solid, Lighting::Phong)).value();
    int n = 0;
    for (std::size_t i = 0; i < phong.color.size(); ++i) {
        ASSERT_EQ(std::isfinite(phong.depth[i]), std::isfinite(gouraud.depth[i]));
        if (!std::isfinite(phong.depth[i])) continue;
        ++n;
        expectNear(phong.color[i], glm::dvec3(expected));
        expectNear(gouraud.color[i], glm::dvec3(expected));
    }
    EXPECT_GT(n, 1000);
}

TEST(Reference, PhongShowsTheHighlightGouraudMisses) {
    // A coarse white sphere lit from the eye with a sharp highlight: no vertex sits where the
    // highlight peaks, so Gouraud stays dim there while Phong reaches full white.
    facet::Mesh sphere = facet::makeUvSphere(7, 10);
    sphere.colors.clear();
    facet::Scene scene = sceneWith(sphere, 64, 100.0);
    scene.lighting.light = {{0.0, 0.0, -5.0, 1.0}, 1.0};
    scene.lighting.material = {0.1, 0.4, 0.8, 60.0};
    const Image gouraud =
        facet::reference::render(scene, lit(DrawMode::Solid, Lighting::Gouraud)).value();
    const Image phong =
        facet::reference::render(scene, lit(DrawMode::Solid, Lighting::Phong)).value();
    double maxGouraud = 0.0, maxPhong = 0.0;
    for (std::size_t i = 0; i < phong.color.size(); ++i) {
        if (!std::isfinite(phong.depth[i])) continue;
        ASSERT_FALSE(std::isnan(phong.color[i].r));
        maxGouraud = std::max(maxGouraud, gouraud.color[i].r);
        maxPhong = std::max(maxPhong, phong.color[i].r);
    }
    EXPECT_GT(maxPhong, 0.99);
    EXPECT_LT(maxGouraud, maxPhong - 0.3);

    // Points take their vertex's own position and normal: Phong is Gouraud there.
    const Image gouraudPoints =
        facet::reference::render(scene, lit(DrawMode::Vertices, Lighting::Gouraud)).value();
    const Image phongPoints =
        facet::reference::render(scene, lit(DrawMode::Vertices, Lighting::Phong)).value();
    int drawn = 0;
    for (std::size_t i = 0; i < phongPoints.color.size(); ++i) {
        drawn += std::isfinite(phongPoints.depth[i]) ? 1 : 0;
        EXPECT_EQ(phongPoints.color[i], gouraudPoints.color[i]);
    }
    EXPECT_GT(drawn, 300);
}

TEST(Reference, PhongWithZeroNormalsIsAmbientOnly) {
    const std::vector<glm::dvec3> rgb(3, {1.0, 0.5, 0.25});
    const std::vector<glm::dvec3> origin(3, glm::dvec3(0.0));
    Input input;
    input.colors = rgb;
    input.positions = origin;
    input.lighting.ambient = 0.5;
    input.lighting.light = {{0.0, 0.0, -3.0, 1.0}, 1.0};
    input.lighting.material = {0.4, 1.0, 1.0, 0.0};
    input.eye = {0.0, 0.0, -3.0};
    const glm::dvec3 ambientOnly{0.2, 0.1, 0.05};  // rgb · Ia·Ka

    // A triangle whose normals are all zero (no normals stream at all).
    const std::vector<glm::dvec4> tri{screen(1, 1), screen(15, 1), screen(1, 15)};
    const std::vector<std::uint32_t> triIdx{0, 1, 2};
    input.clip = tri;
    input.indices = triIdx;
    const Image img = draw(input, lit(DrawMode::Solid, Lighting::Phong), 16, 16);
    EXPECT_GT(coveredCount(img), 80);
    for (std::size_t i = 0; i < img.color.size(); ++i) {
        if (std::isfinite(img.depth[i])) expectNear(img.color[i], ambientOnly);
    }

    // A line whose end normals are opposite: they cancel exactly halfway (k = 4 of 8).
    const std::vector<glm::dvec4> line{screen(2.5, 4.5), screen(10.5, 4.5)};
    const std::vector<glm::dvec3> normals{{0.0, 0.0, -1.0}, {0.0, 0.0, 1.0}};
    const std::vector<std::uint32_t> lineIdx{0, 1, 1};
    input.clip = line;
    input.normals = normals;
    input.indices = lineIdx;
    const Image wire = draw(input, lit(DrawMode::Wireframe, Lighting::Phong), 16, 16);
    expectNear(colorAt(wire, 6, 4), ambientOnly);
    EXPECT_EQ(colorAt(wire, 2, 4), glm::dvec3(1.0, 1.0, 0.55));  // lit: I = 0.2 + 1 + 1
}

// An 8×8 texture whose 64 texels all differ.
std::shared_ptr<const facet::Texture> gridTexture() {
    std::vector<std::uint32_t> px;
    for (std::uint32_t j = 0; j < 8; ++j) {
        for (std::uint32_t i = 0; i < 8; ++i) px.push_back(facet::packRgba(i * 32, j * 32, 200));
    }
    auto tex = facet::Texture::fromRgba(8, 8, std::move(px), "grid");
    EXPECT_TRUE(tex.ok());
    return std::make_shared<const facet::Texture>(std::move(tex.value()));
}

// The screen square [0, 8]² at w = 1 with uv = pixel / 8 + offset: pixel (i, j) samples at
// ((i + ½)/8, (j + ½)/8) + offset, the centre of texel (i, j) without offset.
Image drawTexturedSquare(const RenderSettings& s, const facet::Texture* tex,
                         glm::dvec2 offset = {0, 0}, const std::vector<glm::dvec3>& colors = {}) {
    const std::vector<glm::dvec4> clip{screen(0, 0), screen(8, 0), screen(8, 8), screen(0, 8)};
    const std::vector<glm::dvec2> uvs{offset, offset + glm::dvec2(1, 0), offset + glm::dvec2(1, 1),
                                      offset + glm::dvec2(0, 1)};
    const std::vector<std::uint32_t> idx{0, 1, 2, 0, 2, 3};
    Input input;
    input.clip = clip;
    input.uvs = uvs;
    input.colors = colors;
    input.indices = idx;
    input.texture = tex;
    return draw(input, s, 8, 8);
}

RenderSettings textured(facet::TextureFilter filter, bool combine = false) {
    RenderSettings s = settingsFor(DrawMode::Solid, ShaderKind::Texture);
    s.filter = filter;
    s.combine = combine;
    return s;
}

TEST(Reference, TextureShaderReproducesTexels) {
    const auto tex = gridTexture();
    const Image nearest = drawTexturedSquare(textured(facet::TextureFilter::Nearest), tex.get());
    const Image bilinear = drawTexturedSquare(textured(facet::TextureFilter::Bilinear), tex.get());
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 texel = facet::reference::texelColor(tex->level(0), i, j);
            EXPECT_EQ(colorAt(nearest, i, j), texel) << i << "," << j;
            expectNear(colorAt(bilinear, i, j), texel);
            // Texel centres are far from texel borders: only the diagonal (rule 8(a)) is flagged.
            EXPECT_EQ(nearest.ambiguous[static_cast<std::size_t>(j * 8 + i)], i == j ? 1 : 0);
        }
    }
    // Half a texel over, every Nearest lookup sits on a texel border: rule 8(d) flags them all.
    for (const glm::dvec2 offset : {glm::dvec2(-1.0 / 16, 0), glm::dvec2(0, 1.0 / 16)}) {
        const Image border =
            drawTexturedSquare(textured(facet::TextureFilter::Nearest), tex.get(), offset);
        for (const std::uint8_t a : border.ambiguous) EXPECT_EQ(a, 1);
    }
    const Image smooth =
        drawTexturedSquare(textured(facet::TextureFilter::Bilinear), tex.get(), {-1.0 / 16, 0});
    EXPECT_EQ(smooth.ambiguous[1 * 8 + 5], 0);

    // A vertex square samples at the vertex's uv (texel (2, 5)).
    const std::vector<glm::dvec4> point{screen(4.5, 4.5)};
    const std::vector<glm::dvec2> uv{{0.3, 0.7}};
    Input input;
    input.clip = point;
    input.uvs = uv;
    input.texture = tex.get();
    RenderSettings s = textured(facet::TextureFilter::Nearest);
    s.mode = DrawMode::Vertices;
    const Image img = draw(input, s, 8, 8);
    EXPECT_EQ(colorAt(img, 2, 2), facet::reference::texelColor(tex->level(0), 2, 5));
    EXPECT_EQ(colorAt(img, 6, 6), facet::reference::texelColor(tex->level(0), 2, 5));
}

TEST(Reference, TextureCombineNullTextureAndLighting) {
    const auto tex = gridTexture();
    const std::vector<glm::dvec3> rgb(4, {0.5, 1.0, 0.25});
    const Image combined =
        drawTexturedSquare(textured(facet::TextureFilter::Nearest, true), tex.get(), {0, 0}, rgb);
    // Without combine the colours and the lighting do not matter (Phong, no normals here).
    RenderSettings phong = textured(facet::TextureFilter::Nearest);
    phong.lighting = Lighting::Phong;
    const Image plain = drawTexturedSquare(phong, tex.get(), {0, 0}, rgb);
    for (int j = 0; j < 8; ++j) {
        for (int i = 0; i < 8; ++i) {
            const glm::dvec3 texel = facet::reference::texelColor(tex->level(0), i, j);
            expectNear(colorAt(combined, i, j), texel * glm::dvec3(0.5, 1.0, 0.25));
            EXPECT_EQ(colorAt(plain, i, j), texel);
        }
    }
    // No texture: white, and with combine the vertex colour.
    const Image white =
        drawTexturedSquare(textured(facet::TextureFilter::Nearest), nullptr, {0, 0}, rgb);
    const Image tinted =
        drawTexturedSquare(textured(facet::TextureFilter::Trilinear, true), nullptr, {0, 0}, rgb);
    EXPECT_EQ(colorAt(white, 3, 4), glm::dvec3(1.0));
    EXPECT_EQ(colorAt(tinted, 3, 4), glm::dvec3(0.5, 1.0, 0.25));
}

TEST(Reference, SubdividedIsExactEveryNPixelsAndLinearBetween) {
    // A wall X = Z - 4 seen with f = 16 from the origin: its horizon is the column x = 48, the
    // triangle spans x in [32, 46.4]. With N = 8, pixels 32…39 blend the exact weights at
    // columns 32 and 40; for pixels 40…47 the column x1 = 48 is past the horizon (q < 0 there),
    // so they take their exact (perspective) weights.
    constexpr double f = 16.0, c = 32.0;
    const std::vector<glm::dvec4> v{camera(0, -2, 4, f, c, c), camera(0, 2, 4, f, c, c),
                                    camera(36, 0, 40, f, c, c)};
    const std::vector<glm::dvec3> col{{1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    RenderSettings s = settingsFor(DrawMode::Solid, ShaderKind::Painter, Interp::Subdivided);
    s.subdivision = 8;
    const Image sub = drawClip(v, {0, 1, 2}, s, 64, 64, col);
    const Image persp = drawClip(v, {0, 1, 2}, settingsFor(DrawMode::Solid), 64, 64, col);
    double maxDiff = 0.0;
    int blended = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const std::size_t i = static_cast<std::size_t>(y * 64 + x);
            ASSERT_EQ(sub.depth[i], persp.depth[i]);  // depth is perspective-correct in both
            if (!std::isfinite(sub.depth[i])) continue;
            if (x % 8 == 0 || x >= 40) {
                EXPECT_EQ(sub.color[i], persp.color[i]) << x << "," << y;
                continue;
            }
            maxDiff = std::max(maxDiff, std::abs(sub.color[i].g - persp.color[i].g));
            if (!covered(persp, 32, y) || !covered(persp, 40, y)) continue;
            ++blended;
            const double t = (x - 32) / 8.0;
            expectNear(sub.color[i], (1 - t) * colorAt(persp, 32, y) + t * colorAt(persp, 40, y));
        }
    }
    EXPECT_GT(blended, 30);
    EXPECT_GT(maxDiff, 1e-3);

    // Lines treat Subdivided as Perspective.
    s.mode = DrawMode::Wireframe;
    const Image subLines = drawClip(v, {0, 1, 2}, s, 64, 64, col);
    const Image perspLines = drawClip(v, {0, 1, 2}, settingsFor(DrawMode::Wireframe), 64, 64, col);
    EXPECT_EQ(subLines.color, perspLines.color);
    const Image affineLines = drawClip(
        v, {0, 1, 2}, settingsFor(DrawMode::Wireframe, ShaderKind::Painter, Interp::Affine), 64, 64,
        col);
    EXPECT_NE(affineLines.color, perspLines.color);

    // At constant w all three interpolations agree.
    const std::vector<glm::dvec4> flat{{3, 3, 3, 3}, {60, 15, 3, 3}, {21, 57, 3, 3}};
    s.mode = DrawMode::Solid;
    s.subdivision = 5;
    const Image a = drawClip(flat, {0, 1, 2}, s, 24, 24, col);
    const Image b = drawClip(flat, {0, 1, 2}, settingsFor(DrawMode::Solid), 24, 24, col);
    const Image d =
        drawClip(flat, {0, 1, 2}, settingsFor(DrawMode::Solid, ShaderKind::Painter, Interp::Affine),
                 24, 24, col);
    EXPECT_GT(coveredCount(a), 100);
    for (std::size_t i = 0; i < a.color.size(); ++i) {
        expectNear(a.color[i], b.color[i]);
        expectNear(a.color[i], d.color[i]);
    }
}

TEST(Reference, TrilinearPicksHigherLevelsFartherAway) {
    // A 64×64 checkerboard of single texels: level 0 alternates black and white, every level
    // above is one uniform grey.
    std::vector<std::uint32_t> px;
    for (int j = 0; j < 64; ++j) {
        for (int i = 0; i < 64; ++i) px.push_back((i + j) % 2 ? 0xFFFFFFFFu : 0xFF000000u);
    }
    auto loaded = facet::Texture::fromRgba(64, 64, std::move(px), "checker");
    ASSERT_TRUE(loaded.ok());
    const facet::Texture& tex = loaded.value();
    const glm::dvec3 grey = facet::reference::texelColor(tex.level(1), 0, 0);
    ASSERT_EQ(grey, facet::reference::texelColor(tex.level(1), 1, 0));
    ASSERT_EQ(grey, facet::reference::texelColor(tex.level(tex.levelCount() - 1), 0, 0));

    // A floor Y = 1 from Z = 1 (the bottom row) to Z = 64 (row 32), uv repeating 4 times.
    // Texels per pixel grow from about 0.5 at the bottom past 2 above row 40.
    constexpr double f = 32.0, c = 32.0;
    const std::vector<glm::dvec4> clip{camera(-8, 1, 1, f, c, c), camera(8, 1, 1, f, c, c),
                                       camera(8, 1, 64, f, c, c), camera(-8, 1, 64, f, c, c)};
    const std::vector<glm::dvec2> uvs{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    const std::vector<std::uint32_t> idx{0, 1, 2, 0, 2, 3};
    Input input;
    input.clip = clip;
    input.uvs = uvs;
    input.indices = idx;
    input.texture = &tex;
    const Image tri = draw(input, textured(facet::TextureFilter::Trilinear), 64, 64);
    const Image bi = draw(input, textured(facet::TextureFilter::Bilinear), 64, 64);
    int far = 0, near = 0, sharp = 0;
    double farAliasing = 0.0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            if (!covered(tri, x, y)) continue;
            if (y <= 39) {  // level >= 1: the uniform grey, where bilinear aliases
                ++far;
                expectNear(colorAt(tri, x, y), grey);
                farAliasing = std::max(farAliasing, std::abs(colorAt(bi, x, y).r - grey.r));
            } else if (y >= 56) {  // magnified: level 0 only, the sharp checkerboard
                ++near;
                EXPECT_EQ(colorAt(tri, x, y), colorAt(bi, x, y)) << x << "," << y;
                sharp += std::abs(colorAt(tri, x, y).r - 0.5) > 0.05 ? 1 : 0;
            }
        }
    }
    EXPECT_GT(far, 100);
    EXPECT_GT(near, 400);
    EXPECT_GT(sharp, near / 4);
    EXPECT_GT(farAliasing, 0.1);
}

// A floor triangle seen edge-on (normals +Y, so each normal is a vertical segment going up on
// screen) and a blue wall at z = -2 in front of the first vertex. Image 65×65, f = 100: vertex
// (0,0,0) is at (32.5, 32.5), its segment of length 0.2 ends at y = 28.5; vertex (1,0,0) is at
// x = 12.5, y 32.5 → 28.5; vertex (-1,0,1) at x = 49.17, y 32.5 → 29.17.
facet::Mesh floorAndWall(bool wall) {
    facet::Mesh mesh;
    mesh.positions = {{0.0f, 0.0f, 0.0f}, {-1.0f, 0.0f, 1.0f}, {1.0f, 0.0f, 0.0f}};
    mesh.indices = {0, 1, 2};
    mesh.colors = {glm::vec3(1.0f), glm::vec3(1.0f), glm::vec3(1.0f)};
    if (wall) {
        mesh.positions.insert(mesh.positions.end(),
                              {{-0.3f, -0.3f, -2.0f}, {0.3f, -0.3f, -2.0f}, {0.0f, 0.6f, -2.0f}});
        mesh.indices.insert(mesh.indices.end(), {3, 4, 5});
        mesh.colors.insert(mesh.colors.end(), 3, glm::vec3(0.0f, 0.0f, 1.0f));
    }
    return mesh;
}

bool isRed(const Image& img, int x, int y) {
    return colorAt(img, x, y) == glm::dvec3(1.0, 0.0, 0.0);
}

TEST(Reference, NormalsDisplayDrawsRedSegments) {
    RenderSettings s = settingsFor(DrawMode::Solid);
    s.showNormals = true;
    s.normalLength = 0.2;
    const facet::Scene alone = sceneWith(floorAndWall(false), 65, 100.0);
    const Image img = facet::reference::render(alone, s).value();
    int red = 0;
    for (int y = 0; y < 65; ++y) {
        for (int x = 0; x < 65; ++x) red += isRed(img, x, y) ? 1 : 0;
    }
    EXPECT_EQ(red, 14);
    for (int y = 28; y <= 32; ++y) {
        EXPECT_TRUE(isRed(img, 32, y)) << y;
        EXPECT_TRUE(isRed(img, 12, y)) << y;
        EXPECT_EQ(isRed(img, 49, y), y >= 29) << y;
    }
    s.showNormals = false;
    EXPECT_EQ(coveredCount(facet::reference::render(alone, s).value()), 0);  // the floor is edge-on

    // Behind the wall the LESS test hides the segment; Simple draws it over; other segments
    // stay red, also after the Depth shader's mapping and in the other draw modes.
    s.showNormals = true;
    const facet::Scene scene = sceneWith(floorAndWall(true), 65, 100.0);
    const Image painter = facet::reference::render(scene, s).value();
    for (int y = 28; y <= 32; ++y) {
        expectNear(colorAt(painter, 32, y), glm::dvec3(0.0, 0.0, 1.0));
        EXPECT_TRUE(isRed(painter, 12, y)) << y;
    }
    for (const ShaderKind shader : {ShaderKind::Simple, ShaderKind::Depth}) {
        s.shader = shader;
        const Image img2 = facet::reference::render(scene, s).value();
        EXPECT_EQ(isRed(img2, 32, 30), shader == ShaderKind::Simple);
        EXPECT_TRUE(isRed(img2, 12, 30));
        // The Depth shader mapped the wall (blue before) to viridis.
        if (shader == ShaderKind::Depth) {
            EXPECT_GT(glm::length(colorAt(img2, 32, 30) - glm::dvec3(0, 0, 1)), 0.1);
        }
    }
    s.shader = ShaderKind::Painter;
    for (const DrawMode mode : {DrawMode::Wireframe, DrawMode::Vertices}) {
        s.mode = mode;
        const Image img2 = facet::reference::render(scene, s).value();
        EXPECT_TRUE(isRed(img2, 12, 28));
        EXPECT_TRUE(isRed(img2, 12, 29));
    }

    // The default length is normalDisplayLength; vertices without a normal get no segment.
    facet::Mesh mesh = floorAndWall(false);
    mesh.positions.push_back({5.0f, 5.0f, 5.0f});
    mesh.colors.push_back(glm::vec3(1.0f));
    const facet::Scene withLoose = sceneWith(mesh, 65, 100.0);
    s.normalLength = 0.0;
    const std::vector<glm::dvec4> ends = facet::reference::projectNormals(withLoose, s);
    ASSERT_EQ(ends.size(), 6u);
    const double length = static_cast<double>(facet::normalDisplayLength(mesh));
    EXPECT_EQ(ends[0], facet::reference::projectPoint(withLoose.camera, {0.0, 0.0, 0.0}));
    EXPECT_EQ(ends[1], facet::reference::projectPoint(withLoose.camera, {0.0, length, 0.0}));
}

}  // namespace
