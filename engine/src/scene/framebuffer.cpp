#include "facet/framebuffer.hpp"

#include <algorithm>
#include <cstdio>

#include "facet/limits.hpp"

namespace facet {

std::string hexFromRgba(std::uint32_t rgba) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "#%02X%02X%02X", rgba & 0xFFu, (rgba >> 8) & 0xFFu,
                  (rgba >> 16) & 0xFFu);
    return buf;
}

Status Framebuffer::resize(int w, int h) {
    if (w < 0 || h < 0)
        return Error{
            {}, "a frame cannot be " + std::to_string(w) + "x" + std::to_string(h) + " pixels"};
    if (auto problem = frameMemoryProblem(w, h, 1)) return Error{{}, *problem};
    width = w;
    height = h;
    const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    // resize() keeps capacity, so a steady size never reallocates.
    color.resize(n);
    depth.resize(n);
    return {};
}

void Framebuffer::clear(std::uint32_t rgbaBackground) {
    std::fill(color.begin(), color.end(), rgbaBackground);
    std::fill(depth.begin(), depth.end(), kEmptyDepth);
}

}  // namespace facet
