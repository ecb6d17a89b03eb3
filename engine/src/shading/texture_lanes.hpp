#pragma once
// Bilinear texture lookups for eight pixels: texture.hpp's wrapCoord() and bilinear255() lane by
// lane, with the same operations in the same order, so each lane equals the scalar sampler bit
// for bit. Only the four texel loads per lane stay scalar (a gather).

#include <cstddef>
#include <cstdint>

#include "shading/lanes.hpp"
#include "shading/samplers.hpp"

namespace facet::detail {

/// wrapCoord() for eight lanes: NaN, ±inf and |t| ≥ 2^23 give 0.
[[gnu::always_inline]] inline Float8 wrapCoord8(Float8 t) {
    const Float8 zero = {};
    const Float8 magnitude = t < 0.0f ? -t : t;
    const Int8 ok = magnitude < 8388608.0f;  // false for NaN
    const Float8 safe = ok ? t : zero;       // the conversion below stays defined
    const Float8 w = safe - __builtin_convertvector(__builtin_convertvector(safe, Int8), Float8);
    return w < 0.0f ? w + 1.0f : w;
}

/// The packed texels at (x[i], y[i]) of `level`.
[[gnu::always_inline]] inline Int8 gather8(const std::uint32_t* texels, Int8 x, Int8 y, int width) {
    Int8 out;
    for (int i = 0; i < kLanes; ++i)
        out[i] = static_cast<std::int32_t>(
            texels[static_cast<std::size_t>(y[i]) * static_cast<std::size_t>(width) +
                   static_cast<std::size_t>(x[i])]);
    return out;
}

/// One 8-bit channel of packed texels, as 0..255 floats.
[[gnu::always_inline]] inline Float8 channel8(Int8 texels, int shift) {
    return __builtin_convertvector((texels >> shift) & 0xFF, Float8);
}

/// sampleBilinear(tex, uv, 0) for eight lanes, then packColor(): the packed RGBA8 result.
[[gnu::always_inline]] inline Int8 bilinearPacked8(const MipLevel& level, Float8 u, Float8 v) {
    const int w = level.width, h = level.height;
    const Float8 x = wrapCoord8(u) * static_cast<float>(w) - 0.5f;
    const Float8 y = wrapCoord8(v) * static_cast<float>(h) - 0.5f;
    Int8 x0 = __builtin_convertvector(x, Int8);  // truncation; one less below 0 makes it floor
    Int8 y0 = __builtin_convertvector(y, Int8);
    x0 += x < __builtin_convertvector(x0, Float8);  // a true comparison is −1
    y0 += y < __builtin_convertvector(y0, Float8);
    const Float8 fx = x - __builtin_convertvector(x0, Float8);
    const Float8 fy = y - __builtin_convertvector(y0, Float8);
    Int8 x1 = x0 + 1, y1 = y0 + 1;
    x0 += (x0 < 0) & w;
    y0 += (y0 < 0) & h;
    x1 -= (x1 >= w) & w;
    y1 -= (y1 >= h) & h;
    const std::uint32_t* texels = level.texels.data();
    const Int8 t00 = gather8(texels, x0, y0, w), t10 = gather8(texels, x1, y0, w);
    const Int8 t01 = gather8(texels, x0, y1, w), t11 = gather8(texels, x1, y1, w);
    Float8 rgb[3];
    for (int c = 0; c < 3; ++c) {
        const int shift = 8 * c;
        const Float8 c00 = channel8(t00, shift), c10 = channel8(t10, shift);
        const Float8 c01 = channel8(t01, shift), c11 = channel8(t11, shift);
        const Float8 top = c00 + (c10 - c00) * fx;
        const Float8 bottom = c01 + (c11 - c01) * fx;
        rgb[c] = (top + (bottom - top) * fy) * (1.0f / 255.0f);
    }
    return packColor8(rgb[0], rgb[1], rgb[2]);
}

}  // namespace facet::detail
