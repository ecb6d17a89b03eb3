#pragma once
// Running a test body once per SIMD target this CPU has, each forced in turn, so that a lane
// function is checked on every target the engine may pick at run time.

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <hwy/targets.h>

namespace facet::test {

/// Each target this CPU has, forced in turn, runs `body(name)`; the targets are reset after.
template <class Body>
void onEveryTarget(Body body) {
    const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());
    for (const std::int64_t target : targets) {
        hwy::SetSupportedTargetsForTest(target);
        body(hwy::TargetName(target));
    }
    hwy::SetSupportedTargetsForTest(0);
}

}  // namespace facet::test
