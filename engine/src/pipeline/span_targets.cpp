// One instantiation of every variant's span loop per SIMD target: hwy/foreach_target.h compiles
// this file once for each target Highway enables, and HWY_DYNAMIC_DISPATCH picks the best one
// the CPU has. The choice returns a plain function pointer, called once per triangle. The block
// and multisampled loops are compiled the same way in block_targets.cpp and msaa_targets.cpp;
// this file holds what the three share (the switch that turns them off, the target's name).

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pipeline/span_targets.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h

#include <hwy/highway.h>

#include "pipeline/span_targets.hpp"
#include "shading/span_loop-inl.hpp"

HWY_BEFORE_NAMESPACE();
namespace facet::detail::HWY_NAMESPACE {

PixelLoopFn spanLoopOf(const VariantKey& key) {
    return vectorLoopOf<PixelLoopFn>(
        key, [](auto variant) { return &rasterizeSpans<decltype(variant)>; });
}

const char* targetName() {
    return hwy::TargetName(HWY_TARGET);
}

}  // namespace facet::detail::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <atomic>

namespace facet::detail {
namespace {
std::atomic<bool> gSpanLoops{true};
}  // namespace

HWY_EXPORT(spanLoopOf);
HWY_EXPORT(targetName);

bool spanLoopsEnabled() {
    return gSpanLoops.load(std::memory_order_relaxed);
}

PixelLoopFn spanLoop(const VariantKey& key) {
    if (!spanLoopsEnabled()) return nullptr;
    return HWY_DYNAMIC_DISPATCH(spanLoopOf)(key);
}

std::int64_t spanTargetsCompiled() {
    return HWY_TARGETS;
}

void enableSpanLoops(bool enabled) {
    gSpanLoops.store(enabled, std::memory_order_relaxed);
    enableLaneSetup(enabled);
}

const char* spanTarget() {
    return HWY_DYNAMIC_DISPATCH(targetName)();
}

}  // namespace facet::detail
#endif  // HWY_ONCE
