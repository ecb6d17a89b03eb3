#pragma once
// Frame timing: each frame's time split into stages, a rolling history for the plot, and the
// medians printed by --fps-report.

#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

namespace facet::view {

/// The clock every stage is timed with.
using Clock = std::chrono::steady_clock;

/// Milliseconds from a to b.
inline double ms(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

/// Milliseconds one frame spent in each stage.
struct StageTimes {
    double render = 0.0;  ///< engine: Renderer::render (both sides in Compare); 0: not run
    double twin = 0.0;    ///< OpenGL twin: GlRenderer::render, glFinish and readback; 0: not run
    double twinUpload = 0.0;    ///< ...of which preparing and uploading vertices and texture
    double twinDraw = 0.0;      ///< ...drawing, on the CPU clock up to glFinish
    double twinReadback = 0.0;  ///< ...reading the picture back, and the post passes
    double compare = 0.0;       ///< Compare: difference and composition
    double upload = 0.0;        ///< the frame into its texture (reordered for the blit)
    double draw = 0.0;          ///< OpenGL showing the frame: blit or triangle (llvmpipe: CPU)
    double ui = 0.0;            ///< ImGui: building the panels and drawing them
    double uiDraw = 0.0;        ///< ...of which drawing them (llvmpipe: CPU, up to glFinish)
    double present = 0.0;       ///< buffer swap and window events
    double wait = 0.0;          ///< the main thread waiting for the engine (its thread)
    double total = 0.0;         ///< start of one frame to the start of the next
    // The engine's stages within `render`, from the same job (both sides in Compare), so they
    // never add up to more than it.
    double engineClear = 0.0;
    double engineVertex = 0.0;
    double engineRaster = 0.0;  ///< rasterize and shade
    double enginePost = 0.0;    ///< normals, legend, supersampling's resolve
};

/// Every frame's times (for medians) and the last `window` totals in order (for the plot).
struct FrameHistory {
    std::size_t window = 240;        ///< frames shown by the plot
    std::size_t capacity = 100000;   ///< frames kept; beyond it the older half is dropped
    std::vector<StageTimes> frames;  ///< the frames kept, oldest first
    std::size_t dropped = 0;         ///< frames dropped from the front of `frames`
    std::vector<float> plot;         ///< last `window` totals, oldest first

    /// Appends a frame; plot keeps its length once full (shifting is cheap at this size).
    void push(const StageTimes& t);

    /// Per-stage medians over the frames after the first `skip` ever pushed; zero when none.
    /// render and the twin's fields count only the frames in which that renderer ran.
    StageTimes median(std::size_t skip = 0) const;

    /// Per-stage medians over the last `count` frames.
    StageTimes recentMedian(std::size_t count) const;

    /// Among the last `count` frames in which `field` is above 0, the one whose `field` is the
    /// median (the lower middle for an even count), whole: its stages were measured with it, so
    /// they add up to no more than it, as medians taken stage by stage need not. All zero when
    /// no frame qualifies.
    StageTimes medianFrameBy(std::size_t count, double StageTimes::*field) const;
};

/// One line: "median 123.4 fps (8.10 ms: render 6.00, twin 0.00, compare 0.00, upload 0.20,
/// draw 0.50, ui 0.80 (drawing 0.50), present 0.60, wait 1.00) over N frames". With the engine on
/// its own thread, render and compare overlap the other stages and the stages add up to more than
/// the frame.
std::string fpsReport(const FrameHistory& history, std::size_t skip);

}  // namespace facet::view
