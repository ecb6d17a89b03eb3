#pragma once
// Render panel: who draws (the CPU engine, the OpenGL twin, or both side by side), then every
// RenderSettings field the engine exposes, named by the engine's own lists.

namespace facet::view {

struct CompareSettings;
struct PopupState;
struct TwinView;
struct ViewerModel;

/// Render: renderer, mode, shader, interpolation, filter, lighting, combine, normals, culling,
/// samples, debug view, background. Choosing a renderer may change `compare`; a frame too
/// large for memory is refused in the error popup; the lab's report comes from `twin`.
void renderPanel(ViewerModel& model, CompareSettings& compare, const TwinView& twin,
                 PopupState& popups);

}  // namespace facet::view
