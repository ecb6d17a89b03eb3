#include "compare_stats.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "facet/colormap.hpp"

namespace facet::view {

ImageDiff diffCovered(const Framebuffer& a, const Framebuffer& b) {
    ImageDiff d;
    if (a.width != b.width || a.height != b.height || a.color.size() != b.color.size()) {
        d.sameSize = false;
        return d;
    }
    const std::size_t n = a.color.size();
    const bool depths = a.depth.size() == n && b.depth.size() == n;
    std::uint64_t sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const int e = pixelError(a.color[i], b.color[i]);
        const bool covered =
            !depths || e > 0 || a.depth[i] != kEmptyDepth || b.depth[i] != kEmptyDepth;
        d.pixels += covered;
        sum += static_cast<std::uint64_t>(e);
        d.pixelsDiffering += e > 0;
        d.maxError = std::max(d.maxError, e);
    }
    d.meanError = d.pixels ? static_cast<double>(sum) / static_cast<double>(d.pixels) : 0.0;
    return d;
}

int heatTop(int heatScale, int maxError) {
    return heatScale > 0 ? heatScale : std::max(kMinAutoHeat, maxError);
}

glm::dvec3 heatColour(double error, int top) {
    if (!(error > 0.0)) return glm::dvec3(0.0);
    return viridis(error / static_cast<double>(std::max(1, top)));
}

}  // namespace facet::view
