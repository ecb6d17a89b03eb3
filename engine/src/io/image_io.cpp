#include "facet/image_io.hpp"

#include <string>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace facet {

namespace {

// RGB without alpha: the frame is opaque and the files are a quarter smaller.
std::vector<unsigned char> rgbOf(const std::uint32_t* rgba, int width, int height) {
    std::vector<unsigned char> rgb(static_cast<std::size_t>(width) *
                                   static_cast<std::size_t>(height) * 3);
    for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i) {
        const std::uint32_t p = rgba[i];
        rgb[3 * i + 0] = static_cast<unsigned char>(p & 0xFF);
        rgb[3 * i + 1] = static_cast<unsigned char>((p >> 8) & 0xFF);
        rgb[3 * i + 2] = static_cast<unsigned char>((p >> 16) & 0xFF);
    }
    return rgb;
}

void appendBytes(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<std::size_t>(size));
}

}  // namespace

Result<std::string> encodePng(const Framebuffer& frame) {
    if (frame.width <= 0 || frame.height <= 0) return Error{{}, "cannot write an empty image"};
    const std::vector<unsigned char> rgb = rgbOf(frame.color.data(), frame.width, frame.height);
    std::string bytes;
    if (!stbi_write_png_to_func(&appendBytes, &bytes, frame.width, frame.height, 3, rgb.data(),
                                frame.width * 3))
        return Error{{}, "cannot encode the PNG"};
    return bytes;
}

Status writePng(const std::uint32_t* rgba, int width, int height, const std::string& path) {
    if (width <= 0 || height <= 0) return Error{{path, 0}, "cannot write an empty image"};
    const std::vector<unsigned char> rgb = rgbOf(rgba, width, height);
    if (!stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3))
        return Error{{path, 0}, "cannot write PNG (is the folder there and writable?)"};
    return {};
}

Status writePng(const Framebuffer& frame, const std::string& path) {
    return writePng(frame.color.data(), frame.width, frame.height, path);
}

}  // namespace facet
