#pragma once
// Image decoders behind loadTexture: PNG through libpng, JPEG through libjpeg-turbo (both fuzzed
// upstream and maintained with security fixes by Debian), BMP and TGA through stb_image. Each
// turns bytes into RGBA8 (R in the low byte, as Texture wants) or an Error naming the file.
// Private to the engine; the texture fuzz target calls decodeTexture directly.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "facet/error.hpp"
#include "facet/limits.hpp"
#include "facet/texture.hpp"

namespace facet::detail {

/// An image decoded to packed RGBA8, row 0 at the top.
struct DecodedImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> pixels;
};

/// How strict and how large a decode may be.
struct DecodeLimits {
    int maxSide = kMaxImageSide;  ///< larger sides are refused before any pixel is allocated
    /// PNG chunk checksums: on for files (a flipped bit is a damaged file); the fuzz target turns
    /// them off so its mutations reach the image data instead of failing the checksum.
    bool checkPngCrc = true;
};

/// "image is WxH pixels; a texture side must be 1 to N".
Error imageSizeError(const std::string& name, std::uint64_t w, std::uint64_t h, int maxSide);

/// How a libpng or libjpeg decode ended, as its callbacks and checks recorded it.
struct DecodeEnd {
    bool finished = false;                ///< the whole image was decoded
    bool headerRead = false;              ///< a failure before it means the header is damaged
    bool sizeRefused = false;             ///< the header's size is outside DecodeLimits::maxSide
    std::uint64_t width = 0, height = 0;  ///< the header's size, once read
    std::string message;                  ///< the library's reason, or ours
};

/// The decoded `image`, or the error `end` describes, in the same words for PNG and JPEG:
/// `format` is "PNG" or "JPEG", `library` the decoder named in the message.
Result<DecodedImage> decodeResult(const DecodeEnd& end, DecodedImage&& image,
                                  const std::string& name, std::string_view format,
                                  std::string_view library, int maxSide);

/// Decodes a PNG (the caller has seen its signature).
Result<DecodedImage> decodePng(std::span<const unsigned char> bytes, const std::string& name,
                               const DecodeLimits& limits);

/// Decodes a JPEG (the caller has seen its signature).
Result<DecodedImage> decodeJpeg(std::span<const unsigned char> bytes, const std::string& name,
                                const DecodeLimits& limits);

/// Decodes an image of any supported format, chosen by its first bytes, and builds its mips.
Result<Texture> decodeTexture(std::span<const unsigned char> bytes, const std::string& name,
                              const DecodeLimits& limits = {});

}  // namespace facet::detail
