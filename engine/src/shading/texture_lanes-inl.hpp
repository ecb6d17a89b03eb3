// Bilinear texture lookups for a vector of pixels: samplers.hpp's wrapCoord() and bilinear255()
// lane by lane, with the same operations in the same order, so each lane equals the scalar
// sampler bit for bit. The four texel loads per lane are gathers.
//
// Compiled once per SIMD target (see lanes-inl.hpp).

#include <cstdint>

#include "shading/lanes-inl.hpp"
#include "shading/samplers.hpp"

#if defined(FACET_SHADING_TEXTURE_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACET_SHADING_TEXTURE_LANES_INL_H_
#undef FACET_SHADING_TEXTURE_LANES_INL_H_
#else
#define FACET_SHADING_TEXTURE_LANES_INL_H_
#endif

#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {

/// wrapCoord() lane by lane: NaN, ±inf and |t| ≥ 2^23 give 0.
HWY_INLINE VecF wrapCoordLanes(VecF t) {
    const Df d;
    const MaskF ok = hn::Abs(t) < hn::Set(d, 8388608.0f);  // false for NaN
    const VecF safe = hn::IfThenElseZero(ok, t);           // the conversion below stays defined
    const VecF w = safe - hn::ConvertTo(d, hn::ConvertTo(Di(), safe));
    return hn::IfThenElse(w < hn::Zero(d), w + hn::Set(d, 1.0f), w);
}

/// One 8-bit channel of packed texels, as 0..255 floats.
HWY_INLINE VecF channelLanes(VecI texels, int shift) {
    return hn::ConvertTo(Df(), hn::And(hn::ShiftRightSame(texels, shift), hn::Set(Di(), 0xFF)));
}

/// ⌊x⌋ of lanes in int range: truncation, one less where that rounded up (below 0).
HWY_INLINE VecI floorLanes(VecF x) {
    const Di di;
    const VecI t = hn::ConvertTo(di, x);
    return hn::IfThenElse(hn::RebindMask(di, x < hn::ConvertTo(Df(), t)), t - hn::Set(di, 1), t);
}

/// sampleBilinear(tex, uv, 0) lane by lane, then packColor(): the packed RGBA8 result.
HWY_INLINE VecI bilinearPackedLanes(const MipLevel& level, VecF u, VecF v) {
    const Df d;
    const Di di;
    const int w = level.width, h = level.height;
    const VecF x = wrapCoordLanes(u) * hn::Set(d, static_cast<float>(w)) - hn::Set(d, 0.5f);
    const VecF y = wrapCoordLanes(v) * hn::Set(d, static_cast<float>(h)) - hn::Set(d, 0.5f);
    VecI x0 = floorLanes(x), y0 = floorLanes(y);
    const VecF fx = x - hn::ConvertTo(d, x0);
    const VecF fy = y - hn::ConvertTo(d, y0);
    const VecI one = hn::Set(di, 1), zero = hn::Zero(di), vw = hn::Set(di, w), vh = hn::Set(di, h);
    VecI x1 = x0 + one, y1 = y0 + one;
    x0 = hn::IfThenElse(x0 < zero, x0 + vw, x0);
    y0 = hn::IfThenElse(y0 < zero, y0 + vh, y0);
    x1 = hn::IfThenElse(x1 < vw, x1, x1 - vw);
    y1 = hn::IfThenElse(y1 < vh, y1, y1 - vh);
    // Texel indices fit in int32: a texture has far fewer than 2^31 texels.
    const auto* texels = reinterpret_cast<const std::int32_t*>(level.texels.data());
    const VecI row0 = y0 * vw, row1 = y1 * vw;
    const VecI t00 = hn::GatherIndex(di, texels, row0 + x0);
    const VecI t10 = hn::GatherIndex(di, texels, row0 + x1);
    const VecI t01 = hn::GatherIndex(di, texels, row1 + x0);
    const VecI t11 = hn::GatherIndex(di, texels, row1 + x1);
    VecF rgb[3];
    for (int c = 0; c < 3; ++c) {
        const int shift = 8 * c;
        const VecF c00 = channelLanes(t00, shift), c10 = channelLanes(t10, shift);
        const VecF c01 = channelLanes(t01, shift), c11 = channelLanes(t11, shift);
        const VecF top = c00 + (c10 - c00) * fx;
        const VecF bottom = c01 + (c11 - c01) * fx;
        rgb[c] = (top + (bottom - top) * fy) * hn::Set(d, 1.0f / 255.0f);
    }
    return packColorLanes(rgb[0], rgb[1], rgb[2]);
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_TEXTURE_LANES_INL_H_
