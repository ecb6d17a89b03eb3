#include "gl_depth_colors.hpp"

#include <algorithm>
#include <limits>

#include "facet/colormap.hpp"

namespace facet::gl {

DepthRange colorDepth(Framebuffer& frame, std::span<const float> rangeDepth) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float d : rangeDepth) {
        if (d == kEmptyDepth) continue;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    if (lo > hi) return {};
    for (std::size_t i = 0; i < frame.color.size(); ++i) {
        if ((frame.color[i] >> 24) != 0) continue;            // background or a normal segment
        frame.color[i] = depthColor(frame.depth[i], lo, hi);  // the engine's depth colours
    }
    return {lo, hi};
}

}  // namespace facet::gl
