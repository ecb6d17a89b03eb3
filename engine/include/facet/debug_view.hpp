#pragma once
// Debug views (settings.hpp, DebugView): the numbers behind each view, one per pixel, and the
// heat map with a legend that Renderer::render() draws from them. docs/debug-views.md says
// what each view counts.

#include <cstdint>
#include <vector>

#include "facet/framebuffer.hpp"
#include "facet/settings.hpp"

namespace facet {

/// What a debug view measured, before it is coloured.
struct DebugMap {
    DebugView view = DebugView::None;
    int width = 0, height = 0;
    /// One number per pixel, row-major; NaN where the view has nothing (no fragment reached
    /// the pixel, or no triangle touched the tile). Overdraw: fragments that reached the depth
    /// test. TriangleSize: fragments of the triangle that wrote the pixel. BinLoad: triangles
    /// binned in the pixel's tile. DepthTest: fragments that failed the depth test (0: all
    /// passed). TextureLod: the mip level of the fragment that wrote the pixel. InterpError:
    /// the largest channel difference, in 8-bit steps, between the affine and the perspective
    /// image.
    std::vector<float> values;
    float maxValue = 0.0f;  ///< the largest value (0 when there is none)
    int mipLevels = 0;      ///< TextureLod: levels of the texture sampled (1 for none)
    int tileSize = 0;       ///< BinLoad: side of a tile in pixels

    /// The value at pixel (x, y).
    float at(int x, int y) const {
        return values[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
    /// Every field equal (NaN values compare unequal).
    bool operator==(const DebugMap&) const = default;
};

/// The depth-test view's colours: no fragment, every fragment passed, some fragment failed.
inline constexpr std::uint32_t kDepthTestNever = packRgba(0, 0, 0);
inline constexpr std::uint32_t kDepthTestPassed = packRgba(40, 170, 60);
inline constexpr std::uint32_t kDepthTestFailed = packRgba(220, 40, 40);
/// Pixels a heat map has no value for (nothing drawn there).
inline constexpr std::uint32_t kDebugEmpty = packRgba(0, 0, 0);

/// Colours `frame` (resized to the map) by `map` and draws the view's legend in its
/// bottom-left corner: viridis for the counts and levels (the triangle size on a log scale),
/// the three colours above for the depth test, black where the map has no value.
void paintDebugView(const DebugMap& map, Framebuffer& frame);

}  // namespace facet
