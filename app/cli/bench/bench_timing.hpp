#pragma once
// Timing loops: warm-up frames first, then each timed frame clocked on its own, so the median
// ignores the odd frame another process disturbed.

#include <functional>

#include "bench_options.hpp"
#include "bench_suite.hpp"
#include "facet/framebuffer.hpp"
#include "facet/render.hpp"
#include "report/bench_results.hpp"

namespace facet::app {

/// Calls `frame` for the plan's warm-up frames untimed, then times each of its frames (fewer
/// when the budget runs out, see FramePlan). `frame` returns false to stop at once (an error it
/// reports itself); the frames timed so far are summarised.
FrameTimes timeFrames(const FramePlan& plan, const std::function<bool()>& frame);

/// The engine's frame times and the medians of its stage times over the timed frames.
struct EngineTimes {
    FrameTimes times;
    StageTimes stages;
};

/// The engine drawing a case in a config with `threads` worker threads into `target`: each
/// timed frame is the whole of Renderer::render (clear, vertices, raster, resolve, post).
EngineTimes timeEngine(Renderer& renderer, const BenchCase& c, const BenchConfig& config,
                       int threads, const FramePlan& plan, Framebuffer& target);

/// The memory floor at a case's size, on one thread: filling the colour plane (what a clear
/// costs), filling colour and depth, and copying the colour plane (what a frame readback or
/// upload costs). No renderer can write a frame faster than the first.
std::vector<Measurement> measureFloors(const BenchCase& c, int frames);

}  // namespace facet::app
