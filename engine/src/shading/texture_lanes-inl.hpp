// Bilinear texture lookups for a vector of pixels: samplers.hpp's wrapCoord() and bilinear255()
// lane by lane, with the same operations in the same order, so each lane equals the scalar
// sampler bit for bit. The four texel loads per lane are gathers.
//
// Compiled once per SIMD target (see lanes-inl.hpp).

#include <cstdint>
#include <type_traits>

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

/// wrapCoord() lane by lane: NaN, ±inf and |t| ≥ 2^23 give 0. t − ⌊t⌋ is wrapCoord()'s float:
/// wrapCoord() subtracts trunc(t), which is exact, and adds 1 below 0, so both round the one real
/// value t − ⌊t⌋ once (only a zero's sign may differ, −0 there being +0 here; both become −½ in
/// bilinearPackedLanes()). Floats of magnitude ≥ 2^23 are integers: 0. NaN and ±inf give NaN,
/// which the compare (false for NaN) sets to 0.
HWY_INLINE VecF wrapCoordLanes(VecF t) {
    const VecF w = t - hn::Floor(t);
    return hn::IfThenElseZero(w <= hn::Set(Df(), 1.0f), w);
}

/// One 8-bit channel of packed texels, as 0..255 floats: the low byte by a mask, the others by
/// a byte shuffle (one operation instead of a shift and a mask).
template <int kChannel>
HWY_INLINE VecF channelLanes(VecI texels) {
    const Di di;
    if constexpr (kChannel == 0) {
        return hn::ConvertTo(Df(), hn::And(texels, hn::Set(di, 0xFF)));
    } else {
        // Byte kChannel of each lane to its low byte, the other three zeroed (index ≥ 0x80). The
        // byte indices count within a 128-bit block: lane j's bytes start at 4j.
        constexpr auto kByte = [](std::uint32_t lane) {
            return static_cast<std::int32_t>(0x80808000u | (4u * lane + kChannel));
        };
        alignas(16) static constexpr std::int32_t kPick[4] = {kByte(0), kByte(1), kByte(2),
                                                              kByte(3)};
        return hn::ConvertTo(Df(), hn::TableLookupBytesOr0(texels, hn::LoadDup128(di, kPick)));
    }
}

/// The texels at indices i and i + 1 of `texels` in every lane, as (first, second): one 64-bit
/// gather per two lanes, half the elements of two 32-bit gathers. x86 intrinsics, since Highway
/// has no gather with 32-bit indices into 64-bit lanes: the lanes' indices are permuted so that
/// the two gathers' even and odd halves come out in lane order with one shuffle each.
/// Only on AVX2 and AVX-512; kPairGathers says whether this target has it.
#if HWY_TARGET == HWY_AVX2 || HWY_TARGET == HWY_AVX3
inline constexpr bool kPairGathers = true;
HWY_INLINE void gatherPairs(const std::uint32_t* texels, VecI i, VecI& first, VecI& second) {
    const auto* base = reinterpret_cast<const long long*>(texels);  // 4-byte steps: unaligned
#if HWY_TARGET == HWY_AVX2
    // Pixels 0 1 4 5 in the low half, 2 3 6 7 in the high one.
    const __m256i q = _mm256_permute4x64_epi64(i.raw, 0xD8);
    const __m256 a =
        _mm256_castsi256_ps(_mm256_i32gather_epi64(base, _mm256_castsi256_si128(q), 4));
    const __m256 b =
        _mm256_castsi256_ps(_mm256_i32gather_epi64(base, _mm256_extracti128_si256(q, 1), 4));
    // Per 128-bit block: a's pixels 4j, 4j + 1, then b's 4j + 2, 4j + 3.
    first = VecI{_mm256_castps_si256(_mm256_shuffle_ps(a, b, 0x88))};
    second = VecI{_mm256_castps_si256(_mm256_shuffle_ps(a, b, 0xDD))};
#else
    // Pixels 0 1 4 5 8 9 12 13 in the low half, 2 3 6 7 10 11 14 15 in the high one.
    const __m512i q = _mm512_permutexvar_epi64(_mm512_setr_epi64(0, 2, 4, 6, 1, 3, 5, 7), i.raw);
    const __m512 a =
        _mm512_castsi512_ps(_mm512_i32gather_epi64(_mm512_castsi512_si256(q), base, 4));
    const __m512 b =
        _mm512_castsi512_ps(_mm512_i32gather_epi64(_mm512_extracti64x4_epi64(q, 1), base, 4));
    first = VecI{_mm512_castps_si512(_mm512_shuffle_ps(a, b, 0x88))};
    second = VecI{_mm512_castps_si512(_mm512_shuffle_ps(a, b, 0xDD))};
#endif
}
#else
inline constexpr bool kPairGathers = false;
/// Never called on this target (kPairGathers), but compiled: two 32-bit gathers.
HWY_INLINE void gatherPairs(const std::uint32_t* texels, VecI i, VecI& first, VecI& second) {
    const auto* t = reinterpret_cast<const std::int32_t*>(texels);
    first = hn::GatherIndex(Di(), t, i);
    second = hn::GatherIndex(Di(), t, i + hn::Set(Di(), 1));
}
#endif

/// sampleBilinear(tex, uv, 0) lane by lane, then packColor(): the packed RGBA8 result. The same
/// float operations as bilinear255() where they decide a value, cheaper ones where the result is
/// provably the same (each step says why).
HWY_INLINE VecI bilinearPackedLanes(const MipLevel& level, VecF u, VecF v) {
    const Df d;
    const Di di;
    const Du du;
    const int w = level.width, h = level.height;
    const VecF x = wrapCoordLanes(u) * hn::Set(d, static_cast<float>(w)) - hn::Set(d, 0.5f);
    const VecF y = wrapCoordLanes(v) * hn::Set(d, static_cast<float>(h)) - hn::Set(d, 0.5f);
    // ⌊x⌋ is exact, so it is the float of bilinearTaps()'s integer floor, and the fractions are
    // the same subtractions.
    const VecF xf = hn::Floor(x), yf = hn::Floor(y);
    const VecF fx = x - xf, fy = y - yf;
    // x ∈ [−½, w − ½] and y ∈ [−½, h − ½], so x0 ∈ [−1, w − 1] and y0 ∈ [−1, h − 1]: only −1
    // wraps down (to size − 1: as unsigned it is above every other index, so a min puts it there)
    // and only x0 + 1 = w wraps up (to 0).
    const VecI x0 = truncateInRangeLanes(xf), y0 = truncateInRangeLanes(yf);
    const VecI one = hn::Set(di, 1), vw = hn::Set(di, w), vh = hn::Set(di, h);
    const VecI y0w = hn::BitCast(di, hn::Min(hn::BitCast(du, y0), hn::Set(du, h - 1)));
    const VecI y1 = y0 + one;
    const VecI y1w = hn::IfThenZeroElse(y1 == vh, y1);
    // Texel indices fit in int32: a texture has far fewer than 2^31 texels.
    const std::uint32_t* texels = level.texels.data();
    const VecI row0 = y0w * vw, row1 = y1w * vw;
    VecI t00, t10, t01, t11;
    // Where no lane's x0 wraps (x0 ∈ [0, w − 2]), each row's two texels are neighbours in memory.
    if (kPairGathers && hn::AllTrue(du, hn::BitCast(du, x0) < hn::Set(du, w - 1))) {
        gatherPairs(texels, row0 + x0, t00, t10);
        gatherPairs(texels, row1 + x0, t01, t11);
    } else {
        const VecI x0w = hn::BitCast(di, hn::Min(hn::BitCast(du, x0), hn::Set(du, w - 1)));
        const VecI x1 = x0 + one;
        const VecI x1w = hn::IfThenZeroElse(x1 == vw, x1);
        const auto* t = reinterpret_cast<const std::int32_t*>(texels);
        t00 = hn::GatherIndex(di, t, row0 + x0w);
        t10 = hn::GatherIndex(di, t, row0 + x1w);
        t01 = hn::GatherIndex(di, t, row1 + x0w);
        t11 = hn::GatherIndex(di, t, row1 + x1w);
    }
    VecF rgb[3];
    const auto lerp = [&](auto channel) {
        constexpr int c = decltype(channel)::value;
        const VecF c00 = channelLanes<c>(t00), c10 = channelLanes<c>(t10);
        const VecF c01 = channelLanes<c>(t01), c11 = channelLanes<c>(t11);
        const VecF top = c00 + (c10 - c00) * fx;
        const VecF bottom = c01 + (c11 - c01) * fx;
        rgb[c] = top + (bottom - top) * fy;
    };
    lerp(std::integral_constant<int, 0>());
    lerp(std::integral_constant<int, 1>());
    lerp(std::integral_constant<int, 2>());
    // packColor(c / 255) without toByte()'s clamp: the lerps stay within their texels (a + (b −
    // a)·f with f ∈ [0, 1) lies between a and b), so c ∈ [0, 255] and c · fl(1/255) ∈ [0, 1]
    // (rounding is monotone and 255 · fl(1/255) rounds to exactly 1): the clamp changes nothing.
    const VecF k = hn::Set(d, 1.0f / 255.0f);
    return packBytesLanes(unitToByteLanes(rgb[0] * k), unitToByteLanes(rgb[1] * k),
                          unitToByteLanes(rgb[2] * k));
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // FACET_SHADING_TEXTURE_LANES_INL_H_
