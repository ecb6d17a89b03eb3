#include "screenshot.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "facet/image_io.hpp"

namespace facet::view {

Status saveFrameShot(const Framebuffer& frame, const std::string& path) {
    return writePng(frame, path);
}

Status saveWindowShot(int width, int height, const std::string& path) {
    if (width <= 0 || height <= 0) return Error{{path, 0}, "the window has no pixels to save"};
    const std::size_t w = static_cast<std::size_t>(width);
    const std::size_t h = static_cast<std::size_t>(height);
    std::vector<std::uint32_t> pixels(w * h);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    // GL rows start at the bottom; PNG rows (and the engine's) at the top.
    for (std::size_t y = 0; y < h / 2; ++y)
        std::swap_ranges(pixels.begin() + static_cast<std::ptrdiff_t>(y * w),
                         pixels.begin() + static_cast<std::ptrdiff_t>((y + 1) * w),
                         pixels.begin() + static_cast<std::ptrdiff_t>((h - 1 - y) * w));
    return writePng(pixels.data(), width, height, path);
}

}  // namespace facet::view
