#include "facet/framebuffer.hpp"

#include <algorithm>
#include <cassert>
#include <cstdio>

namespace facet {

std::string hexFromRgba(std::uint32_t rgba) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "#%02X%02X%02X", rgba & 0xFFu, (rgba >> 8) & 0xFFu,
                  (rgba >> 16) & 0xFFu);
    return buf;
}

void Framebuffer::resize(int w, int h) {
    assert(w >= 0 && h >= 0);
    width = w;
    height = h;
    const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
    // resize() keeps capacity, so a steady size never reallocates.
    color.resize(n);
    depth.resize(n);
}

void Framebuffer::clear(std::uint32_t rgbaBackground) {
    std::fill(color.begin(), color.end(), rgbaBackground);
    std::fill(depth.begin(), depth.end(), kEmptyDepth);
}

}  // namespace facet
