// The texture decoders (libpng, libjpeg-turbo, stb_image for BMP and TGA) and the mip chain, on
// arbitrary bytes. Sides are capped at 4096 here instead of 16384 so that a forged header costs
// 64 MiB rather than 1 GiB per run (the same check with a smaller number), and PNG checksums are
// ignored so that mutations reach the image data.

#include <cstddef>
#include <cstdint>
#include <span>

#include "fuzz_check.hpp"
#include "io/image_decode.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using facet::fuzz::require;
    const facet::detail::DecodeLimits limits{.maxSide = 4096, .checkPngCrc = false};
    const facet::Result<facet::Texture> texture =
        facet::detail::decodeTexture(std::span(data, size), "fuzz.img", limits);
    if (texture) {
        require(texture->width() >= 1 && texture->width() <= limits.maxSide);
        require(texture->height() >= 1 && texture->height() <= limits.maxSide);
        for (int i = 0; i < texture->levelCount(); ++i) {
            const facet::MipLevel& level = texture->level(i);
            require(level.texels.size() ==
                    static_cast<std::size_t>(level.width) * static_cast<std::size_t>(level.height));
        }
    } else {
        require(texture.error().loc.file == "fuzz.img");
    }
    return 0;
}
