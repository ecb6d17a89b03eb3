#include "render_worker.hpp"

#include <chrono>
#include <utility>

#include "frame_stats.hpp"

namespace facet::view {
RenderWorker::RenderWorker() : thread_([this] { loop(); }) {}

RenderWorker::~RenderWorker() {
    {
        std::unique_lock lock(mutex_);
        cv_.wait(lock, [this] { return !pending_; });
        quit_ = true;
    }
    cv_.notify_all();
    thread_.join();
}

void RenderWorker::submit(const Scene& scene, const RenderSettings& settings,
                          const CompareSettings& compare) {
    std::unique_lock lock(mutex_);
    cv_.wait(lock, [this] { return !pending_; });  // the caller should have waited already
    scene_ = scene;
    settings_ = settings;
    compare_ = compare;
    pending_ = true;
    lock.unlock();
    cv_.notify_all();
}

void recordEngineTimes(const RenderResult& r, StageTimes& t) {
    t.render = r.renderMs;
    t.compare = r.compareMs;
    const RenderStats none;
    const RenderStats& right = r.compared ? r.rightStats : none;
    t.engineClear = r.stats.clearMs + right.clearMs;
    t.engineVertex = r.stats.vertexMs + right.vertexMs;
    t.engineRaster = r.stats.rasterMs + right.rasterMs;
    t.enginePost = r.stats.postMs + right.postMs;
}

const RenderResult& RenderWorker::wait(Framebuffer& shown) {
    std::unique_lock lock(mutex_);
    cv_.wait(lock, [this] { return !pending_; });
    // The finished picture goes to the caller and the caller's old buffer comes back to be
    // drawn into: both keep their capacity, so a steady size allocates nothing.
    if (fresh_) {
        if (result_.compared)
            std::swap(shown, sides_.shown);
        else
            std::swap(shown, frame_);
        fresh_ = false;
    }
    return result_;
}

void RenderWorker::loop() {
    std::unique_lock lock(mutex_);
    for (;;) {
        cv_.wait(lock, [this] { return pending_ || quit_; });
        if (quit_) return;
        // The job's inputs are not touched by the caller until pending_ is false again.
        lock.unlock();
        RenderResult r;
        const auto t0 = Clock::now();
        if (compare_.enabled) {
            sides_.renderSides(scene_, settings_, compare_);
            const auto t1 = Clock::now();
            sides_.compose(compare_);
            r.renderMs = ms(t0, t1);
            r.compareMs = ms(t1, Clock::now());
            r.stats = sides_.leftStats;
            r.rightStats = sides_.rightStats;
            r.diff = sides_.diff;
            r.compared = true;
            r.refused = sides_.refused;
        } else {
            // A refused frame (checkFrame) keeps the last image, with no stats.
            Result<RenderStats> rendered = renderer_.render(scene_, settings_, frame_);
            r.stats = rendered ? rendered.value() : RenderStats{};
            if (!rendered) r.refused = rendered.error().what();
            r.renderMs = ms(t0, Clock::now());
        }
        lock.lock();
        result_ = r;
        pending_ = false;
        fresh_ = true;
        cv_.notify_all();
    }
}

}  // namespace facet::view
