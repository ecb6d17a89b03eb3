#include "camera_input.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "inspector.hpp"
#include "key_actions.hpp"
#include "viewer_app.hpp"

namespace facet::view {
namespace {

/// Window pixels around the divider line that grab it.
constexpr double kDividerGrab = 6.0;

/// True when a window point is within reach of the divider (Compare, or CPU | OpenGL).
bool overDivider(const App& app, ImVec2 mouse) {
    const FramePlan plan = planFrame(app.model.rendererChoice, app.compare.settings.enabled);
    if (!plan.twoSides() || app.compare.settings.display != CompareDisplay::Split) return false;
    if (app.view.w <= 0) return false;
    const double x = app.view.x + app.compare.settings.divider * app.view.w;
    const double y = mouse.y;
    return std::abs(mouse.x - x) <= kDividerGrab && y >= app.view.y && y < app.view.y + app.view.h;
}

}  // namespace

void handleInput(App& app) {
    // Input is read from ImGui after NewFrame(), when WantCaptureMouse describes this very
    // frame: a press over a panel belongs to the panel and never starts a camera drag, even if
    // the pointer jumped there since last frame.
    ImGuiIO& io = ImGui::GetIO();
    applyActions(app);

    // Shift + click inspects a pixel (inspector.hpp) and starts no drag.
    const bool inspected =
        app.drag.button < 0 && app.light.drag == LightDrag::None && inspectorClick(app);
    // The light's marker (or Ctrl + drag) takes a left press before the camera does.
    if (!inspected && app.drag.button < 0 && app.light.drag == LightDrag::None &&
        !io.WantCaptureMouse && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
        startLightDrag(app);
    dragLightStep(app);
    if (!inspected && app.drag.button < 0 && app.light.drag == LightDrag::None &&
        !io.WantCaptureMouse) {
        for (int b = 0; b < 3; ++b) {
            if (!ImGui::IsMouseClicked(b)) continue;
            app.drag.button = b;
            app.drag.divider = b == ImGuiMouseButton_Left && overDivider(app, io.MousePos);
            // Measured from the press: the pointer's travel before it is no drag.
            app.drag.lastX = io.MouseClickedPos[b].x;
            app.drag.lastY = io.MouseClickedPos[b].y;
            break;
        }
    }
    if (app.drag.button >= 0) {
        // From the press (or last frame's place) to here; the travel before the press is not
        // the drag's (at a few frames a second it turned the view by 90 degrees at a click).
        const bool valid = ImGui::IsMousePosValid();  // not while outside the window
        const double dx = valid ? io.MousePos.x - app.drag.lastX : 0.0;
        const double dy = valid ? io.MousePos.y - app.drag.lastY : 0.0;
        if (valid) {
            app.drag.lastX = io.MousePos.x;
            app.drag.lastY = io.MousePos.y;
        }
        const bool moved = (dx != 0.0 || dy != 0.0) && std::isfinite(dx) && std::isfinite(dy);
        if (moved && app.drag.divider) {
            if (app.view.w > 0)
                app.compare.settings.divider =
                    std::clamp(app.compare.settings.divider + dx / app.view.w, 0.0, 1.0);
        } else if (moved && app.drag.button == ImGuiMouseButton_Left) {
            app.model.rotate(dx, dy);
        } else if (moved) {
            // Pan speed in frame pixels, so the scene follows the pointer at any letterbox scale.
            const double scale = frameScale(app.view, app.model.scene.camera.width);
            app.model.pan(dx * scale, dy * scale);
        }
        if (!ImGui::IsMouseDown(app.drag.button)) app.drag = {};
    }
    if (!io.WantCaptureMouse && io.MouseWheel != 0.0f && std::isfinite(io.MouseWheel))
        app.model.zoom(io.MouseWheel);

    // The pointer over the divider shows it can be moved.
    if (!io.WantCaptureMouse && (app.drag.divider || overDivider(app, io.MousePos)))
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
}

}  // namespace facet::view
