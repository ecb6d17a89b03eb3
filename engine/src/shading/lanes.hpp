#pragma once
// Eight pixels at a time: the vector types of the span loop (span_raster.hpp) and the few
// operations GCC's generic vectors lack. With AVX2 a vector is one register; on the x86-64
// baseline GCC splits it into two SSE registers.

#include <cstdint>
#include <cstring>

#include <xmmintrin.h>

// GCC notes that these types are passed differently with and without AVX. That matters: the span
// loop is compiled for both (target_clones), so a vector must never cross a call that is not
// inlined, or the AVX2 clone and a baseline callee disagree on where it is (seen as a crash in
// an unoptimised build). Every function taking or returning one is always_inline, and no lambda
// takes one. Not popped: GCC reports it at the end of the including file.
#pragma GCC diagnostic ignored "-Wpsabi"

// The span loop's AVX2 and baseline clones. Clang 14 refuses target_clones on a template, so
// under Clang the loop is built once for the baseline (slower, same images) until the portable
// SIMD rewrite replaces this.
#if defined(__clang__)
#define FACET_SPAN_CLONES
#else
#define FACET_SPAN_CLONES gnu::target_clones("avx2", "default")
#endif

namespace facet::detail {

inline constexpr int kLanes = 8;
using Float8 = float __attribute__((vector_size(4 * kLanes)));
using Int8 = std::int32_t __attribute__((vector_size(4 * kLanes)));

/// Square roots of eight lanes: sqrtps (correctly rounded, like std::sqrt) on each half, as
/// std::sqrt itself is not vectorized while it may set errno.
[[gnu::always_inline]] inline Float8 sqrt8(Float8 v) {
    __m128 half[2];
    std::memcpy(half, &v, sizeof v);
    half[0] = _mm_sqrt_ps(half[0]);
    half[1] = _mm_sqrt_ps(half[1]);
    Float8 out;
    std::memcpy(&out, half, sizeof out);
    return out;
}

/// Bit i set where lane i of a comparison is true: movmskps on each half.
[[gnu::always_inline]] inline unsigned laneMask(Int8 condition) {
    __m128 half[2];
    std::memcpy(half, &condition, sizeof condition);
    return static_cast<unsigned>(_mm_movemask_ps(half[0]) | (_mm_movemask_ps(half[1]) << 4));
}

/// toByte() lane by lane: clamp to [0, 1] (NaN to 0), scale, round half up.
[[gnu::always_inline]] inline Int8 toByte8(Float8 c) {
    const Float8 zero = {}, one = zero + 1.0f;
    const Float8 v = c > 0.0f ? (c < 1.0f ? c : one) : zero;
    return __builtin_convertvector(v * 255.0f + 0.5f, Int8);
}

/// packColor() lane by lane: opaque RGBA8, R in the low byte.
[[gnu::always_inline]] inline Int8 packColor8(Float8 r, Float8 g, Float8 b) {
    return toByte8(r) | (toByte8(g) << 8) | (toByte8(b) << 16) |
           static_cast<std::int32_t>(0xFF000000u);
}

}  // namespace facet::detail
