#include "compare_stats.hpp"

#include <algorithm>

#include "facet/colormap.hpp"

namespace facet::view {

int heatTop(int heatScale, int maxError) {
    return heatScale > 0 ? heatScale : std::max(kMinAutoHeat, maxError);
}

glm::dvec3 heatColour(double error, int top) {
    if (!(error > 0.0)) return glm::dvec3(0.0);
    return viridis(error / static_cast<double>(std::max(1, top)));
}

}  // namespace facet::view
