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

}  // namespace facet::detail
