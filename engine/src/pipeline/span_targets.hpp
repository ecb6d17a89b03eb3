#pragma once
// The vector span, block and multisampled loops, compiled once per SIMD target (SSE4, AVX2,
// AVX-512 and Highway's portable fallback on x86; span_targets.cpp, block_targets.cpp,
// msaa_targets.cpp), and the run-time choice among them: once per draw, never per pixel.

#include <cstdint>

#include "frontend/front_end.hpp"
#include "pipeline/variants.hpp"
#include "shading/msaa_loop.hpp"
#include "shading/span_loop.hpp"

namespace facet::detail {

/// The span loop of `key`'s variant for the best SIMD target this CPU has (Highway's run-time
/// choice, which tests may restrict with hwy::SetSupportedTargetsForTest); null when the
/// variant has none (subdivided interpolation, trilinear filtering).
PixelLoopFn spanLoop(const VariantKey& key);

/// The block loop (small triangles, span_loop-inl.hpp) of `key`'s variant for the same target
/// as spanLoop(); null exactly when spanLoop() is.
PixelLoopFn blockLoop(const VariantKey& key);

/// The multisampled span loop (msaa_loop-inl.hpp) of `key`'s
/// variant for the same target as spanLoop(); null when the variant has none.
MsaaLoopFn msaaSpanLoop(const VariantKey& key);

/// The name of the SIMD target spanLoop() picks now, e.g. "AVX2".
const char* spanTarget();

/// The Highway targets (HWY_* bits) the span loops were compiled for.
std::int64_t spanTargetsCompiled();

/// Turns the vector loops off (spanLoop(), blockLoop() and msaaSpanLoop() return null: every
/// triangle takes the scalar loop; and laneSetup() too: every triangle takes the scalar front
/// end) or back on, for the whole process: the scalar code is the reference the vector targets
/// must equal bit for bit. Not for use while a draw runs.
void enableSpanLoops(bool enabled);

/// Whether the vector loops are on (enableSpanLoops()).
bool spanLoopsEnabled();

/// What `pick(variant)` returns for `key`'s variant, called only for variants with vector loops
/// (kHasSpanLoop); null for the others. Each *_targets.cpp picks its loop with it.
template <class Fn, class Pick>
Fn vectorLoopOf(const VariantKey& key, Pick pick) {
    Fn loop = nullptr;
    dispatch(key, [&](auto variant) {
        if constexpr (kHasSpanLoop<decltype(variant)>) loop = pick(variant);
    });
    return loop;
}

/// spanLoop() for a compile-time Variant.
template <class V>
PixelLoopFn spanLoopFor() {
    return spanLoop({V::kShader, V::kInterp, V::kLayout, V::kFilter, V::kCombine});
}

/// blockLoop() for a compile-time Variant.
template <class V>
PixelLoopFn blockLoopFor() {
    return blockLoop({V::kShader, V::kInterp, V::kLayout, V::kFilter, V::kCombine});
}

}  // namespace facet::detail
