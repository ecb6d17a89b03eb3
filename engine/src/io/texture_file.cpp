// Texture files: the bytes read and checked, decoded by the decoder their signature names (PNG:
// libpng, JPEG: libjpeg-turbo, else stb_image for BMP and TGA) into RGBA8, then handed to
// Texture::fromRgba for the mip chain.

#include "facet/texture.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <new>
#include <span>
#include <string>
#include <utility>
#include <vector>

// stb_image keeps only BMP and TGA: PNG and JPEG go through libpng and libjpeg-turbo
// (image_decode.hpp). Sizes are checked here before decoding, so the message can say the limit.
#define STBI_ONLY_BMP
#define STBI_ONLY_TGA
#define STBI_NO_STDIO
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#include "io/stb_image_quiet.hpp"

#include "facet/limits.hpp"
#include "io/image_decode.hpp"
#include "io/load_progress.hpp"

namespace facet {
namespace detail {
namespace {

Error fileError(const std::string& path, std::string message) {
    return Error{{path, 0}, std::move(message)};
}

std::uint32_t bigEndian32(const unsigned char* p) {
    return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 |
           std::uint32_t{p[3]};
}

bool startsWith(std::span<const unsigned char> bytes, std::span<const unsigned char> magic) {
    return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin());
}

/// Most pixels one byte of a BMP or TGA file can describe (an 8-bit TGA run packet).
constexpr std::uint64_t kMaxStbPixelsPerByte = 64;

/// BMP and TGA through stb_image, its header first so a forged size allocates nothing.
Result<DecodedImage> decodeStb(std::span<const unsigned char> bytes, const std::string& path,
                               const DecodeLimits& limits) {
    const int length = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels = 0;
    if (!stbi_info_from_memory(bytes.data(), length, &w, &h, &channels)) {
        const char* reason = stbi_failure_reason();
        return fileError(path, std::string("not a readable PNG, JPEG, BMP or TGA image "
                                           "(stb_image: ") +
                                   (reason ? reason : "unknown reason") + ")");
    }
    if (w < 1 || h < 1 || w > limits.maxSide || h > limits.maxSide) {
        return imageSizeError(path, static_cast<std::uint64_t>(w), static_cast<std::uint64_t>(h),
                              limits.maxSide);
    }
    // stb_image reads zeros past the end of the data and fills the whole claimed image: a
    // 134-byte TGA claiming 3855x3855 (found by fuzzing) made it loop over 15 million pixels.
    // The densest encoding either format has is an 8-bit TGA run, 128 pixels in 2 bytes.
    if (static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) >
        kMaxStbPixelsPerByte * bytes.size()) {
        return fileError(path, "image claims " + std::to_string(w) + "x" + std::to_string(h) +
                                   " pixels, more than a " + std::to_string(bytes.size()) +
                                   "-byte BMP or TGA file can hold: it is damaged or truncated");
    }
    // Always four channels: grey, grey+alpha and RGB all become RGBA, one uint32 per texel.
    const std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes.data(), length, &w, &h, &channels, 4), stbi_image_free);
    if (!data) {
        const char* reason = stbi_failure_reason();
        return fileError(path, std::string("cannot decode the image, it may be damaged or "
                                           "truncated (stb_image: ") +
                                   (reason ? reason : "unknown reason") + ")");
    }
    DecodedImage image{
        w, h,
        std::vector<std::uint32_t>(static_cast<std::size_t>(w) * static_cast<std::size_t>(h))};
    std::memcpy(image.pixels.data(), data.get(), 4 * image.pixels.size());  // R first in memory
    return image;
}

}  // namespace

Error imageSizeError(const std::string& name, std::uint64_t w, std::uint64_t h, int maxSide) {
    return fileError(name, "image is " + std::to_string(w) + "x" + std::to_string(h) +
                               " pixels; a texture side must be 1 to " + std::to_string(maxSide));
}

Result<DecodedImage> decodeResult(const DecodeEnd& end, DecodedImage&& image,
                                  const std::string& name, std::string_view format,
                                  std::string_view library, int maxSide) {
    if (end.sizeRefused) return imageSizeError(name, end.width, end.height, maxSide);
    const std::string reason = " (" + std::string(library) + ": " + end.message + ")";
    if (!end.finished && !end.headerRead) {
        return Error{
            {name, 0},
            "not a readable " + std::string(format) + " image: its header is damaged" + reason};
    }
    if (!end.finished) {
        return Error{{name, 0}, "cannot decode the image, it may be damaged or truncated" + reason};
    }
    return std::move(image);
}

Result<Texture> decodeTexture(std::span<const unsigned char> bytes, const std::string& name,
                              const DecodeLimits& limits) {
    static constexpr unsigned char kPng[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    static constexpr unsigned char kJpeg[] = {0xFF, 0xD8, 0xFF};
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        return fileError(name, "the texture file is too large (over 2 GB)");
    Result<DecodedImage> image = DecodedImage{};
    if (startsWith(bytes, kPng)) {
        // The size from IHDR first: libpng calls a zero or oversized side a damaged header.
        static constexpr unsigned char kIhdr[] = {'I', 'H', 'D', 'R'};
        if (bytes.size() >= 24 && startsWith(bytes.subspan(12), kIhdr)) {
            const std::uint32_t w = bigEndian32(bytes.data() + 16);
            const std::uint32_t h = bigEndian32(bytes.data() + 20);
            const auto maxSide = static_cast<std::uint32_t>(limits.maxSide);
            if (w < 1 || h < 1 || w > maxSide || h > maxSide)
                return imageSizeError(name, w, h, limits.maxSide);
        }
        image = decodePng(bytes, name, limits);
    } else if (startsWith(bytes, kJpeg)) {
        image = decodeJpeg(bytes, name, limits);
    } else {
        image = decodeStb(bytes, name, limits);
    }
    if (!image) return image.error();
    return Texture::fromRgba(image->width, image->height, std::move(image->pixels), name);
}

}  // namespace detail

Result<Texture> loadTexture(const std::string& path, const LoadControl* control) {
    io::ProgressMeter meter(control);
    // An image decodes in one call, so the checks fall before and after the read.
    meter.phase(0.0f, 0.3f);
    if (meter.cancelled()) return io::ProgressMeter::cancelledError(path);
    using detail::fileError;
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) return fileError(path, "is a folder, not an image file");
    // A device or pipe has no size to check and may never end (opening a pipe even waits).
    if (fs::exists(path, ec) && !fs::is_regular_file(path, ec))
        return fileError(path, "is not a regular file");
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) return fileError(path, "cannot open the texture file (missing or not readable)");
    const std::streamoff size = in.tellg();
    if (size < 0) return fileError(path, "cannot read the texture file");
    if (size == 0) return fileError(path, "the texture file is empty");
    if (static_cast<std::uint64_t>(size) > kMaxFileBytes) {
        return fileError(path, "the texture file is " + std::to_string(size) +
                                   " bytes; the limit is " + std::to_string(kMaxFileBytes));
    }
    try {
        std::vector<unsigned char> bytes(static_cast<std::size_t>(size));
        in.seekg(0);
        if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
            return fileError(path, "cannot read the texture file");
        if (!meter.step(1, 1)) return io::ProgressMeter::cancelledError(path);
        meter.phase(0.3f, 1.0f);
        auto texture = detail::decodeTexture(bytes, path);
        if (meter.cancelled()) return io::ProgressMeter::cancelledError(path);
        if (texture) meter.finish();
        return texture;
    } catch (const std::bad_alloc&) {
        return fileError(path, "not enough memory to load this texture");
    }
}

}  // namespace facet
