// Every variant's block loop (small triangles, span_loop-inl.hpp), compiled once per SIMD target:
// hwy/foreach_target.h compiles this file once for each target Highway enables, and
// HWY_DYNAMIC_DISPATCH picks the best one the CPU has. The choice returns a plain function pointer,
// called once per triangle. Its own translation unit beside span_targets.cpp, so that a build
// compiles the vector loops side by side (Clang's sanitizer build spent over 20 minutes on one file
// holding all three).

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/block_targets.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

#include <hwy/highway.h>

#include "pipeline/span_targets.hpp"
#include "shading/span_loop-inl.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {

PixelLoopFn blockLoopOf(const VariantKey& key) {
    return vectorLoopOf<PixelLoopFn>(
        key, [](auto variant) { return &rasterizeBlocks<decltype(variant)>; });
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facet::detail {

HWY_EXPORT(blockLoopOf);

PixelLoopFn blockLoop(const VariantKey& key) {
    if (!spanLoopsEnabled()) return nullptr;
    return HWY_DYNAMIC_DISPATCH(blockLoopOf)(key);
}

}  // namespace facet::detail
#endif  // HWY_ONCE
