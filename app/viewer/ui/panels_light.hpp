#pragma once
// Light and material panel: fields bound straight to the scene's lighting; the next frame
// renders with them, nothing is reloaded.

namespace facet::view {

struct ViewerModel;

/// Light (position, point or directional, Ia, Id) and material (Ka, Kd, Ks, s).
void lightPanel(ViewerModel& model);

}  // namespace facet::view
