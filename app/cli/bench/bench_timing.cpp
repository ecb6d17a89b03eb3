#include "bench_timing.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

namespace facet::app {
namespace {

/// Tells the compiler the buffer is read afterwards, so a fill nobody reads is not dropped.
void keep(const void* p) {
    asm volatile("" : : "r"(p) : "memory");
}

}  // namespace

FrameTimes timeFrames(const FramePlan& plan, const std::function<bool()>& frame) {
    using Clock = std::chrono::steady_clock;
    const auto seconds = [](Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double>(b - a).count();
    };
    // A frame of a second or more has nothing left to warm: one such warm-up frame is enough.
    const auto warmStart = Clock::now();
    for (int i = 0; i < plan.warmup && (i == 0 || seconds(warmStart, Clock::now()) < 1.0); ++i)
        if (!frame()) return {};
    std::vector<double> ms;
    ms.reserve(static_cast<std::size_t>(plan.frames));
    double spent = 0.0;
    for (int i = 0; i < plan.frames; ++i) {
        if (plan.budgetSeconds > 0.0 && i >= kMinTimedFrames && spent > plan.budgetSeconds) break;
        const auto t0 = Clock::now();
        const bool ok = frame();
        const auto t1 = Clock::now();
        if (!ok) break;
        spent += seconds(t0, t1);
        ms.push_back(1e3 * seconds(t0, t1));
    }
    return summarize(std::move(ms));
}

EngineTimes timeEngine(Renderer& renderer, const BenchCase& c, const BenchConfig& config,
                       int threads, const FramePlan& plan, Framebuffer& target) {
    RenderSettings settings = config.settings;
    settings.threads = threads;
    std::vector<double> frontEnd, binning, raster;
    EngineTimes t;
    t.times = timeFrames(plan, [&] {
        const Result<RenderStats> stats = renderer.render(c.scene, settings, target);
        if (!stats) return false;
        frontEnd.push_back(stats->frontEndMs);
        binning.push_back(stats->binningMs);
        raster.push_back(stats->rasterMs);
        return true;
    });
    // The warm-up frames came first: the timed ones are the last `frames`.
    const auto timed = [&](const std::vector<double>& v) {
        const auto n = std::min(v.size(), static_cast<std::size_t>(t.times.frames));
        return medianOf(std::vector<double>(v.end() - static_cast<std::ptrdiff_t>(n), v.end()));
    };
    t.stages = {timed(frontEnd), timed(binning), timed(raster)};
    return t;
}

std::vector<Measurement> measureFloors(const BenchCase& c, int frames) {
    const FramePlan plan{2, frames, 0.0};
    const std::size_t n = pixelCount(c);
    std::vector<std::uint32_t> color(n), copy(n);
    std::vector<float> depth(n);
    const Measurement base{c.name, "-", "", 1, c.scene.camera.width, c.scene.camera.height, 0, {}};
    auto floor = [&](const char* name, const std::function<void()>& write) {
        Measurement m = base;
        m.renderer = name;
        // Two untimed passes fault the pages in and warm the caches as a steady frame would.
        m.times = timeFrames(plan, [&] {
            write();
            return true;
        });
        return m;
    };
    return {
        floor(kFloorFill,
              [&] {
                  std::fill(color.begin(), color.end(), 0xFF5C5C5Cu);
                  keep(color.data());
              }),
        floor(kFloorFillDepth,
              [&] {
                  std::fill(color.begin(), color.end(), 0xFF5C5C5Cu);
                  std::fill(depth.begin(), depth.end(), kEmptyDepth);
                  keep(color.data());
                  keep(depth.data());
              }),
        floor(kFloorCopy,
              [&] {
                  std::memcpy(copy.data(), color.data(), n * sizeof(std::uint32_t));
                  keep(copy.data());
              }),
    };
}

}  // namespace facet::app
