#pragma once
// Mouse input for the view: orbit with the left button, pan with the right or middle, zoom with
// the wheel, the divider (Compare, or CPU | OpenGL) by dragging it; the light's marker and the
// pixel inspector take their clicks first, and the keys' actions are applied before all.

namespace facet::view {

struct App;

/// A mouse drag that belongs to the viewer (it started over the image, not a panel).
struct DragState {
    int button = -1;       ///< ImGui mouse button, −1: none
    bool divider = false;  ///< the drag moves the Compare divider
    float lastX = 0.0f;    ///< where the pointer was last frame (at the press on its first)
    float lastY = 0.0f;
};

/// Mouse and keys for the camera and the Compare divider; call after ImGui::NewFrame().
void handleInput(App& app);

}  // namespace facet::view
