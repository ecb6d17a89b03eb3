#include "gl_depth_colors.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>

#include <glm/vec3.hpp>

#include "facet/colormap.hpp"

namespace facet::gl {
namespace {

/// The engine's 8-bit rounding (spec §5): clamp, ×255, round half up; in float, as the
/// engine converts viridis' double result to float first.
std::uint32_t toByte(float c) {
    const float v = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
    return static_cast<std::uint32_t>(v * 255.0f + 0.5f);
}

}  // namespace

DepthRange colorDepth(Framebuffer& frame, std::span<const float> rangeDepth) {
    float lo = std::numeric_limits<float>::infinity(), hi = -lo;
    for (const float d : rangeDepth) {
        if (d == kEmptyDepth) continue;
        lo = std::min(lo, d);
        hi = std::max(hi, d);
    }
    if (lo > hi) return {};
    const double range = hi > lo ? static_cast<double>(hi) - lo : 1.0;
    for (std::size_t i = 0; i < frame.color.size(); ++i) {
        if ((frame.color[i] >> 24) != 0) continue;  // background or a normal segment
        const glm::vec3 c(viridis((frame.depth[i] - static_cast<double>(lo)) / range));
        frame.color[i] = packRgba(toByte(c.r), toByte(c.g), toByte(c.b));
    }
    return {lo, hi};
}

}  // namespace facet::gl
