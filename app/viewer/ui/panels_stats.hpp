#pragma once
// Stats panel: fps, the frame time split with the CPU engine's and the OpenGL twin's times side
// by side, its history, what each drew. The compact overlay in the image's corner is
// workspace_ui.cpp's.

#include "frame_stats.hpp"

namespace facet::view {

struct App;

/// The frame times the Stats panel and the overlay show (the frame loop records them).
struct StatsState {
    FrameHistory history;
    StageTimes lastTimes;  ///< the previous frame's split
};

/// Stats panel: fps, frame time split (the engine's stages from the same frame as its total),
/// history plot, what the engine drew.
void statsPanel(App& app);

}  // namespace facet::view
