// Texture files: the bytes read and checked, decoded by stb_image into RGBA8, then handed to
// Texture::fromRgba for the mip chain.

#include "facet/texture.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "facet/camera.hpp"

// Only the formats the conventions promise: less decoder surface for hostile files, and anything
// else is reported as unsupported rather than half-working. Sizes are checked in loadTexture()
// (stb's own cap is far larger) so the message can say what the limit is.
#define STBI_ONLY_PNG
#define STBI_ONLY_JPEG
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_NO_STDIO
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wold-style-cast"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wnull-dereference"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace facet {
namespace {

Error fileError(const std::string& path, std::string message) {
    return Error{{path, 0}, std::move(message)};
}

Error sizeError(const std::string& path, std::uint64_t w, std::uint64_t h) {
    return fileError(path, "image is " + std::to_string(w) + "x" + std::to_string(h) +
                               " pixels; a texture side must be 1 to " +
                               std::to_string(kMaxImageSide));
}

std::uint32_t bigEndian32(const unsigned char* p) {
    return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 |
           std::uint32_t{p[3]};
}

/// Why stb_image could not read the header. stb tries every decoder in turn, so its own reason
/// is the last decoder's ("unknown image type") even for a PNG it refused as too large: the
/// signature tells which format the file claims to be, and a PNG's size is easy to read.
Error headerError(const std::string& path, const std::vector<unsigned char>& bytes,
                  const char* stbReason) {
    static constexpr unsigned char kPng[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    const auto startsWith = [&](const unsigned char* magic, std::size_t n) {
        return bytes.size() >= n && std::equal(magic, magic + n, bytes.begin());
    };
    if (startsWith(kPng, sizeof kPng)) {
        if (bytes.size() >= 24 && std::equal(bytes.begin() + 12, bytes.begin() + 16, "IHDR")) {
            const std::uint32_t w = bigEndian32(bytes.data() + 16);
            const std::uint32_t h = bigEndian32(bytes.data() + 20);
            if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
                return sizeError(path, w, h);
        }
        return fileError(path, "not a readable PNG image: its header is damaged");
    }
    static constexpr unsigned char kJpeg[] = {0xFF, 0xD8, 0xFF};
    if (startsWith(kJpeg, sizeof kJpeg))
        return fileError(path, "not a readable JPEG image: its header is damaged");
    return fileError(path, std::string("not a readable PNG, JPEG, BMP or TGA image (stb_image: ") +
                               (stbReason ? stbReason : "unknown reason") + ")");
}

}  // namespace

Result<Texture> loadTexture(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) return fileError(path, "is a folder, not an image file");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return fileError(path, "cannot open the texture file (missing or not readable)");
    const std::streamoff size = in.tellg();
    if (size < 0) return fileError(path, "cannot read the texture file");
    if (size == 0) return fileError(path, "the texture file is empty");
    if (size > std::numeric_limits<int>::max())
        return fileError(path, "the texture file is too large (over 2 GB)");
    const int length = static_cast<int>(size);

    try {
        std::vector<unsigned char> bytes(static_cast<std::size_t>(length));
        in.seekg(0);
        if (!in.read(reinterpret_cast<char*>(bytes.data()), length))
            return fileError(path, "cannot read the texture file");

        // The header first: a forged size is refused before anything is decoded or allocated.
        int w = 0, h = 0, channels = 0;
        if (!stbi_info_from_memory(bytes.data(), length, &w, &h, &channels))
            return headerError(path, bytes, stbi_failure_reason());
        if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
            return sizeError(path, static_cast<std::uint64_t>(w), static_cast<std::uint64_t>(h));

        // Always four channels: grey, grey+alpha and RGB all become RGBA, one uint32 per texel.
        const std::unique_ptr<stbi_uc, void (*)(void*)> data(
            stbi_load_from_memory(bytes.data(), length, &w, &h, &channels, 4), stbi_image_free);
        if (!data) {
            const char* reason = stbi_failure_reason();
            return fileError(path, std::string("cannot decode the image, it may be damaged or "
                                               "truncated (stb_image: ") +
                                       (reason ? reason : "unknown reason") + ")");
        }
        std::vector<std::uint32_t> pixels(static_cast<std::size_t>(w) *
                                          static_cast<std::size_t>(h));
        for (std::size_t i = 0; i < pixels.size(); ++i) {
            const stbi_uc* p = data.get() + 4 * i;
            pixels[i] = static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
                        static_cast<std::uint32_t>(p[2]) << 16 |
                        static_cast<std::uint32_t>(p[3]) << 24;
        }
        return Texture::fromRgba(w, h, std::move(pixels), path);
    } catch (const std::bad_alloc&) {
        return fileError(path, "not enough memory to load this texture");
    }
}

}  // namespace facet
