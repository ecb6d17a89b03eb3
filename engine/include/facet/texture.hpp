#pragma once
// Textures (spec §7): an RGBA8 image with its mip chain. Texels stay 8-bit (4 bytes each,
// a quarter of float storage, so more of the image stays in cache); the samplers that read them
// live with the pixel loops (fast) and the reference renderer (double).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "facet/error.hpp"
#include "facet/limits.hpp"
#include "facet/load_control.hpp"

namespace facet {

/// One level of a mip chain: packed RGBA8 texels (R in the low byte, like Framebuffer::color),
/// row-major, row 0 at the top of the image.
struct MipLevel {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> texels;  ///< width * height entries

    /// The packed texel at (x, y); no bounds check.
    std::uint32_t at(int x, int y) const {
        return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                      static_cast<std::size_t>(x)];
    }
};

/// An image and its mip chain. A class because the samplers index texels without bounds checks:
/// only fromRgba() builds a chain, so every level is non-empty and holds width * height texels.
class Texture {
  public:
    /// A 1×1 white texture: neutral under "combine", and safe to sample when none was loaded.
    Texture();

    /// Builds a texture and its mip chain from packed RGBA8 pixels (row 0 at the top). Each
    /// level halves the previous one's sides (rounding down, never below 1) and every texel is
    /// the area-weighted mean of the source region it covers: the 2×2 box for even sides, a
    /// 3-tap box over 2.5, 1.5... texels for odd ones, so no source texel is skipped or doubled.
    /// Channels are averaged as stored (no sRGB decoding, like the rest of the colour maths)
    /// and rounded to nearest. `name` labels errors and the UI.
    static Result<Texture> fromRgba(int width, int height, std::vector<std::uint32_t> pixels,
                                    std::string name);

    /// Width of level 0.
    int width() const { return levels_.front().width; }
    /// Height of level 0.
    int height() const { return levels_.front().height; }
    /// Number of mip levels, 1 + floor(log2(max(width, height))).
    int levelCount() const { return static_cast<int>(levels_.size()); }
    /// Level i, 0 being the image itself; i must be in [0, levelCount()).
    const MipLevel& level(int i) const { return levels_[static_cast<std::size_t>(i)]; }
    /// The file (or label) the texture came from.
    const std::string& name() const { return name_; }

  private:
    std::vector<MipLevel> levels_;
    std::string name_;
};

/// Reads a PNG (libpng), JPEG (libjpeg-turbo), BMP or TGA (stb_image) file as RGBA8 and builds
/// its mip chain. Missing, empty, corrupt, unsupported or over-limit files (limits.hpp) and sides
/// outside 1…kMaxImageSide give an Error naming the file. The optional `control` gets the
/// progress (after reading, after decoding) and may cancel between those steps.
Result<Texture> loadTexture(const std::string& path, const LoadControl* control = nullptr);

}  // namespace facet
