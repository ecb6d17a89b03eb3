// The debug views' numbers and their heat maps (see debug_maps.hpp, facet/debug_view.hpp).

#include "debug/debug_maps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "binning/tiles.hpp"
#include "facet/colormap.hpp"
#include "facet/legend.hpp"
#include "shading/fragment.hpp"

namespace facet::detail {
namespace {

constexpr float kNone = std::numeric_limits<float>::quiet_NaN();

std::size_t frameIndex(int width, int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x);
}

void start(DebugView view, int width, int height, DebugMap& map) {
    map.view = view;
    map.width = width;
    map.height = height;
    map.values.assign(static_cast<std::size_t>(std::max(0, width)) *
                          static_cast<std::size_t>(std::max(0, height)),
                      kNone);
    map.maxValue = 0.0f;
    map.mipLevels = 0;
    map.tileSize = 0;
}

void finish(DebugMap& map) {
    for (const float v : map.values)
        if (v > map.maxValue) map.maxValue = v;
}

}  // namespace

RenderSettings debugViewBase(const RenderSettings& settings) {
    RenderSettings base = settings;
    base.view = DebugView::None;
    base.mode = DrawMode::Solid;
    base.supersample = 1;
    base.msaa = 1;  // the views count one sample per pixel
    base.showNormals = false;
    base.depthLegend = false;
    if (settings.view == DebugView::TextureLod) {
        base.shader = ShaderKind::Texture;
        base.filter = TextureFilter::Trilinear;
    }
    return base;
}

void fillFromProbe(DebugView view, const DrawProbe& probe, int mipLevels, DebugMap& map) {
    start(view, probe.depth.width, probe.depth.height, map);
    map.mipLevels = view == DebugView::TextureLod ? mipLevels : 0;
    for (std::size_t i = 0; i < map.values.size(); ++i) {
        if (probe.fragments[i] == 0) continue;
        const std::uint32_t w = probe.winner[i];
        switch (view) {
            case DebugView::Overdraw:
                map.values[i] = static_cast<float>(probe.fragments[i]);
                break;
            case DebugView::DepthTest:
                map.values[i] = static_cast<float>(probe.failures[i]);
                break;
            case DebugView::TriangleSize:
                if (w != DrawProbe::kNoTriangle)
                    map.values[i] = static_cast<float>(probe.trianglePixels[w]);
                break;
            case DebugView::TextureLod:
                if (w != DrawProbe::kNoTriangle && !probe.lod.empty()) map.values[i] = probe.lod[i];
                break;
            default:
                break;
        }
    }
    finish(map);
}

void fillBinLoad(const std::vector<std::uint32_t>& perTile, int width, int height, DebugMap& map) {
    start(DebugView::BinLoad, width, height, map);
    map.tileSize = kTileSize;
    const int tilesX = (width + kTileSize - 1) / kTileSize;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint32_t n =
                perTile[static_cast<std::size_t>(y / kTileSize * tilesX + x / kTileSize)];
            if (n > 0) map.values[frameIndex(width, x, y)] = static_cast<float>(n);
        }
    finish(map);
}

void fillInterpError(const Framebuffer& perspective, const Framebuffer& affine, DebugMap& map) {
    start(DebugView::InterpError, perspective.width, perspective.height, map);
    for (std::size_t i = 0; i < map.values.size(); ++i) {
        if (perspective.depth[i] == kEmptyDepth && affine.depth[i] == kEmptyDepth) continue;
        const std::uint32_t a = perspective.color[i], b = affine.color[i];
        int worst = 0;
        for (int shift = 0; shift < 24; shift += 8)
            worst = std::max(worst, std::abs(static_cast<int>((a >> shift) & 0xFF) -
                                             static_cast<int>((b >> shift) & 0xFF)));
        map.values[i] = static_cast<float>(worst);
    }
    finish(map);
}

}  // namespace facet::detail

namespace facet {
namespace {

std::uint32_t packViridis(double t) {
    return detail::packColor(glm::vec3(viridis(t)));
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

/// Most counts a legend shows as one band each; more are shown as a continuous bar.
constexpr int kMaxBands = 32;

/// The legend of integer counts lo…hi: one viridis band per count (labelled at its centre)
/// when they are few, else a continuous bar; every count labelled when at most 10, else the
/// ends and the middle.
LegendBar countBar(std::string title, int lo, int hi) {
    const int n = hi - lo + 1;
    const bool banded = n <= kMaxBands;
    LegendBar bar{std::move(title), banded ? n : 0, {}};
    auto tick = [&](int k) {
        const double t = banded ? (k - lo + 0.5) / n : static_cast<double>(k - lo) / (hi - lo);
        bar.ticks.push_back({t, number(k)});
    };
    if (n <= 10) {
        for (int k = lo; k <= hi; ++k) tick(k);
    } else {
        for (const int k : {lo, (lo + hi) / 2, hi}) tick(k);
    }
    return bar;
}

double countT(float v, int lo, int hi) {
    return hi > lo ? (static_cast<double>(v) - lo) / (hi - lo) : 0.0;
}

}  // namespace

void paintDebugView(const DebugMap& map, Framebuffer& frame) {
    frame.resize(map.width, map.height);
    if (map.view == DebugView::None || map.values.empty()) return;
    const int scale = legendScale(map.height);
    auto paint = [&](auto colorOf) {
        for (std::size_t i = 0; i < map.values.size(); ++i)
            frame.color[i] = std::isnan(map.values[i]) ? kDebugEmpty : colorOf(map.values[i]);
    };
    const int top = static_cast<int>(std::lround(map.maxValue));
    switch (map.view) {
        case DebugView::Overdraw: {
            const int hi = std::max(2, top);
            paint([&](float v) { return packViridis(countT(v, 1, hi)); });
            drawLegend(frame, countBar("FRAGMENTS PER PIXEL", 1, hi), scale);
            break;
        }
        case DebugView::BinLoad: {
            const int hi = std::max(2, top);
            paint([&](float v) { return packViridis(countT(v, 1, hi)); });
            // The tile borders, darkened, show which pixels share a count.
            for (int y = 0; y < frame.height; ++y)
                for (int x = 0; x < frame.width; ++x)
                    if (map.tileSize > 0 && (x % map.tileSize == 0 || y % map.tileSize == 0)) {
                        std::uint32_t& c = frame.color[frame.index(x, y)];
                        c = (c >> 1 & 0x007F7F7Fu) | 0xFF000000u;
                    }
            drawLegend(frame,
                       countBar("TRIANGLES PER " + number(map.tileSize) + "X" +
                                    number(map.tileSize) + " TILE",
                                1, hi),
                       scale);
            break;
        }
        case DebugView::TriangleSize: {
            // Pixels per triangle span 1 to the whole frame: a log scale.
            const double hi = std::max(10.0, static_cast<double>(map.maxValue));
            const double span = std::log10(hi);
            paint([&](float v) { return packViridis(std::log10(std::max(1.0f, v)) / span); });
            LegendBar bar{"PIXELS PER TRIANGLE (LOG)", 0, {}};
            for (double p = 1.0; p <= hi * 1.0001; p *= 10.0)
                bar.ticks.push_back({std::log10(p) / span, number(p)});
            if (bar.ticks.back().t < 0.8) bar.ticks.push_back({1.0, number(std::round(hi))});
            drawLegend(frame, bar, scale);
            break;
        }
        case DebugView::DepthTest:
            paint([](float v) { return v > 0.0f ? kDepthTestFailed : kDepthTestPassed; });
            drawLegend(frame, "DEPTH TEST",
                       {{kDepthTestNever, "NO FRAGMENT"},
                        {kDepthTestPassed, "EVERY FRAGMENT PASSED"},
                        {kDepthTestFailed, "SOME FRAGMENT FAILED"}},
                       scale);
            break;
        case DebugView::TextureLod: {
            const int last = std::max(1, map.mipLevels - 1);
            paint([&](float v) { return packViridis(static_cast<double>(v) / last); });
            LegendBar bar{"MIP LEVEL (TRILINEAR)", 0, {}};
            const int step = last <= 10 ? 1 : 2;
            for (int k = 0; k <= last; k += step)
                bar.ticks.push_back({static_cast<double>(k) / last, number(k)});
            drawLegend(frame, bar, scale);
            break;
        }
        case DebugView::InterpError: {
            const int hi = std::max(1, top);
            paint([&](float v) { return packViridis(countT(v, 0, hi)); });
            drawLegend(frame, countBar("AFFINE VS PERSPECTIVE: 8-BIT STEPS", 0, hi), scale);
            break;
        }
        case DebugView::None:
            break;
    }
}

}  // namespace facet
