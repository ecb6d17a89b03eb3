#pragma once
// The engine on a second thread. While the main thread uploads, draws and swaps frame N (on
// llvmpipe that is several milliseconds of CPU work), the worker renders frame N+1, so a frame
// costs about the larger of the two instead of their sum. The worker keeps its own copy of the
// scene (the mesh and texture are shared and immutable, so that copies pointers and a few
// numbers), so the panels edit the document freely while it renders.
//
// Plain C++ threads, no GL: the unit tests drive it directly.

#include <condition_variable>
#include <mutex>
#include <thread>

#include "compare.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "facet/scene.hpp"
#include "facet/settings.hpp"
#include "frame_stats.hpp"

namespace facet::view {

/// What one finished job produced, for the Stats and Compare panels.
struct RenderResult {
    RenderStats stats;       ///< the single render, or the left side in Compare
    RenderStats rightStats;  ///< Compare: the right side
    ImageDiff diff;          ///< Compare: left against right
    bool compared = false;   ///< the job was a Compare job
    double renderMs = 0.0;   ///< engine time (both sides in Compare)
    double compareMs = 0.0;  ///< difference and composition time
    std::string refused;     ///< why the engine drew nothing (checkFrame's message), or empty
};

/// Copies a job's times into a frame's: the engine's total, its stages (both sides summed in
/// Compare) and the comparison's.
void recordEngineTimes(const RenderResult& result, StageTimes& times);

/// Renders submitted frames on its own thread, one job at a time.
class RenderWorker {
  public:
    RenderWorker();
    /// Finishes the job in flight and joins the thread.
    ~RenderWorker();
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    /// Starts rendering a copy of `scene` with `settings`; with compare.enabled, both sides as
    /// `compare` says. The previous job must have been collected with wait().
    void submit(const Scene& scene, const RenderSettings& settings, const CompareSettings& compare);

    /// Blocks until the submitted job is done, then swaps its picture into `shown` (no copy)
    /// and returns what it did. Without a job in flight it returns the last result unchanged.
    const RenderResult& wait(Framebuffer& shown);

  private:
    void loop();

    std::mutex mutex_;
    std::condition_variable cv_;
    bool pending_ = false;  // a job was submitted and is not finished
    bool fresh_ = false;    // a finished job's picture was not handed out yet
    bool quit_ = false;

    // Owned by the worker while a job runs, by the caller otherwise.
    Scene scene_;
    RenderSettings settings_;
    CompareSettings compare_;
    CompareView sides_;  // the Compare job's renderers and frames
    Renderer renderer_;
    Framebuffer frame_;
    RenderResult result_;

    std::thread thread_;  // last: starts after everything above exists
};

}  // namespace facet::view
