#pragma once
// Fonts and widget sizes that follow the monitor's content scale, and opaque windows and
// pop-ups.

struct GLFWwindow;

namespace facet::view {

/// Fonts and widget sizes for `scale`; `rebuild` when the GL backend already made its font
/// texture. Pop-ups and windows are opaque.
void applyUiStyle(float scale, bool rebuild);

/// The UI scale of the window: `uiScaleOption` (--ui-scale) when above 0, else its monitor's
/// content scale (glfwGetWindowContentScale) over the framebuffer's scale, within 0.5…4.
float windowUiScale(GLFWwindow* window, double uiScaleOption);

}  // namespace facet::view
