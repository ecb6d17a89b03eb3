#pragma once
// Camera panel: sliders bound straight to the orbit; the next frame renders with them, nothing
// is reloaded.

namespace facet::view {

struct ViewerModel;

/// Camera: yaw, pitch, distance, focal length, target, up axis, reset, what resizing does, and
/// the window's `vsync`.
void cameraPanel(ViewerModel& model, bool& vsync);

}  // namespace facet::view
