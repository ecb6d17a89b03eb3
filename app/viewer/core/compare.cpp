#include "compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "compare_stats.hpp"
#include "settings_map.hpp"

namespace facet::view {

int dividerColumn(double fraction, int width) {
    if (!std::isfinite(fraction)) fraction = 0.5;
    return std::clamp(static_cast<int>(std::lround(fraction * width)), 0, width);
}

void composeSplit(const Framebuffer& a, const Framebuffer& b, int column, Framebuffer& out) {
    out.resize(a.width, a.height);
    if (b.width != a.width || b.height != a.height) {
        out.color = a.color;  // cannot happen with one camera; show something sane anyway
        return;
    }
    const std::size_t w = static_cast<std::size_t>(a.width);
    const std::size_t split = static_cast<std::size_t>(std::clamp(column, 0, a.width));
    const std::uint32_t white = packRgba(255, 255, 255);
    // Whole row segments with memcpy: no per-pixel branch.
    for (int y = 0; y < a.height; ++y) {
        const std::size_t row = static_cast<std::size_t>(y) * w;
        std::memcpy(out.color.data() + row, a.color.data() + row, split * sizeof(std::uint32_t));
        std::memcpy(out.color.data() + row + split, b.color.data() + row + split,
                    (w - split) * sizeof(std::uint32_t));
        if (split < w) out.color[row + split] = white;
    }
}

void CompareView::renderSides(const Scene& scene, const RenderSettings& settings,
                              const CompareSettings& compare) {
    RenderSettings s = settings;
    applyInterp(s, compare.left);
    // A refused frame (checkFrame: the camera, the size) keeps the last image, with no stats.
    Result<RenderStats> left = leftRenderer.render(scene, s, leftFrame);
    leftStats = left ? left.value() : RenderStats{};
    applyInterp(s, compare.right);
    Result<RenderStats> right = rightRenderer.render(scene, s, rightFrame);
    rightStats = right ? right.value() : RenderStats{};
    refused = !left ? left.error().what() : !right ? right.error().what() : std::string();
}

const Framebuffer& CompareView::render(const Scene& scene, const RenderSettings& settings,
                                       const CompareSettings& compare) {
    renderSides(scene, settings, compare);
    return compose(compare);
}

ImageDiff composeSides(const Framebuffer& left, const Framebuffer& right, CompareDisplay display,
                       double divider, int heatScale, Framebuffer& shown) {
    const ImageDiff d = diffImages(left, right, nullptr, 0, DiffPixels::covered);
    if (display == CompareDisplay::Difference)
        diffImages(left, right, &shown, heatTop(heatScale, d.maxError));
    else
        composeSplit(left, right, dividerColumn(divider, left.width), shown);
    return d;
}

const Framebuffer& CompareView::compose(const CompareSettings& compare) {
    diff = composeSides(leftFrame, rightFrame, compare.display, compare.divider, compare.heatScale,
                        shown);
    return shown;
}

}  // namespace facet::view
