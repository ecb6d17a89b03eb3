#pragma once
// One frame of the viewer: panels, the engine on its own thread and/or the OpenGL twin, upload,
// draw, UI, swap; and what the loop keeps between frames.

#include <memory>

#include "accuracy_job.hpp"
#include "compare.hpp"
#include "facet/framebuffer.hpp"
#include "frame_stats.hpp"
#include "gl_frame.hpp"
#include "render_worker.hpp"
#include "renderer_choice.hpp"

namespace facet::view {

struct App;

/// The frame loop's state: who renders, the pictures in hand, the loop's settings.
struct FrameLoop {
    std::unique_ptr<GlFrame> gl;
    std::unique_ptr<RenderWorker> worker;  ///< the engine's thread
    Framebuffer display;                   ///< the engine's latest frame (from the worker)
    const Framebuffer* shown = nullptr;    ///< the frame on screen: engine, twin or composed
    RendererLog rendererLog;               ///< what each renderer did, for --state
    RendererChoice lastChoice = RendererChoice::Cpu;  ///< the previous frame's, to count switches
    bool engineFresh = false;  ///< `display` is the engine's frame of the previous frame's state
    long long frameCount = 0;
    bool vsync = true;         ///< wait for the display between frames (Camera panel)
    bool vsyncApplied = true;  ///< the swap interval last set
    bool pipelined = true;     ///< the engine renders frame N+1 while N is drawn (Stats panel)
    /// The view and Compare settings the engine last rendered, so a frame can be skipped while
    /// the accuracy job measures.
    AccuracyView lastEngineView;
    CompareSettings lastEngineCompare;
};

/// One frame, events already polled at `start`: panels, engine and/or twin, upload, draw, UI,
/// swap. `last` also writes --window-shot. Returns 0, or 1 when an output could not be written.
int runFrame(App& app, Clock::time_point start, bool last);

}  // namespace facet::view
