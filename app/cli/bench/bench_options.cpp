#include "bench_options.hpp"

#include <algorithm>
#include <filesystem>
#include <thread>

namespace facet::app {

FramePlan framePlan(const BenchOptions& o) {
    FramePlan plan;
    // A median of 9 shrugs off a few disturbed frames; --quick only checks that it all runs.
    plan.frames = o.frames > 0 ? o.frames : o.quick ? 2 : 9;
    // The first GL frame of a variant compiles its shaders (~40 ms); the first engine frame
    // sizes its scratch buffers. One more frame settles the caches.
    plan.warmup = o.warmup >= 0 ? o.warmup : o.quick ? 1 : 2;
    plan.budgetSeconds = o.budget;
    return plan;
}

std::string sharedDir(const BenchOptions& o) {
    if (!o.shared.empty()) return o.shared;
#ifdef FACET_SHARED_DIR
    if (std::filesystem::is_directory(FACET_SHARED_DIR)) return FACET_SHARED_DIR;
#endif
    return "../shared";
}

int allCoresThreads(const BenchOptions& o) {
    if (o.threads > 0) return o.threads;
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}  // namespace facet::app
