#pragma once
// The keys' actions in the window: the key map (key_map.hpp) says which action a key asks for;
// the document's actions are applied there, the window's (help, quit, side bar, fullscreen,
// screenshot, overlays) here. The same actions sit behind buttons in the side bar.

#include <vector>

#include "key_map.hpp"

namespace facet::view {

struct App;

/// What the keys asked for since the last frame.
struct KeyEvents {
    std::vector<Action> actions;  ///< keys pressed since the last frame, in order
    bool quit = false;            ///< the frame loop ends after this frame
    bool saveScene = false;       ///< Ctrl+S: save the scene shown
};

/// The key actions queued since the last frame; call after ImGui::NewFrame().
void applyActions(App& app);

/// Fullscreen on the monitor under the window, or back to the window it was.
void toggleFullscreen(App& app);

}  // namespace facet::view
