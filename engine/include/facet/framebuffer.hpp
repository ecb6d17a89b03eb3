#pragma once
// The frame: RGBA8 colour and float depth, plain buffers the viewer uploads as they are.

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "facet/error.hpp"

namespace facet {

/// Packs 8-bit channels into the in-memory RGBA byte order (R first).
constexpr std::uint32_t packRgba(std::uint32_t r, std::uint32_t g, std::uint32_t b,
                                 std::uint32_t a = 255) {
    return r | (g << 8) | (b << 16) | (a << 24);
}

/// A colour channel in 8 bits (spec §5): clamped to [0,1] (NaN to 0), ×255, rounded half up; in
/// float, as the renderers compute colours.
constexpr std::uint32_t toByte(float c) {
    const float v = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
    return static_cast<std::uint32_t>(v * 255.0f + 0.5f);
}

/// The same rounding for a channel computed in double (colour maps, legends, heat maps): the
/// product ×255 is rounded in double, so it can differ from the float one by a step at a tie.
inline std::uint32_t toByte(double c) {
    const double v = c > 0.0 ? (c < 1.0 ? c : 1.0) : 0.0;
    return static_cast<std::uint32_t>(std::lround(v * 255.0));
}

/// Converts 0xRRGGBB (as written by users) to an opaque packed RGBA pixel.
constexpr std::uint32_t rgbaFromHex(std::uint32_t rgb) {
    return packRgba((rgb >> 16) & 0xFF, (rgb >> 8) & 0xFF, rgb & 0xFF);
}

/// "#RRGGBB" of a packed pixel (alpha left out), as messages and the inspector show colours.
std::string hexFromRgba(std::uint32_t rgba);

/// Colour and depth planes of equal size; depth holds camera-space Z, +inf where nothing drew.
struct Framebuffer {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> color;  ///< row-major, row 0 at the top, bytes R,G,B,A
    std::vector<float> depth;          ///< row-major camera-space depth

    /// Reallocates only when the size changes (no allocation per frame at a fixed size). An
    /// error, the frame unchanged, for a negative size or buffers beyond kMaxFrameBytes.
    Status resize(int w, int h);
    /// Fills colour with the background and depth with +inf.
    void clear(std::uint32_t rgbaBackground);
    /// Index of pixel (x, y).
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(x);
    }
};

/// Depth value meaning "no fragment".
inline constexpr float kEmptyDepth = std::numeric_limits<float>::infinity();

}  // namespace facet
