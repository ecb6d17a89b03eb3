#include "key_actions.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>

#include "popups.hpp"
#include "viewer_app.hpp"

namespace facet::view {
namespace {

/// The monitor holding most of the window (the primary one when none does).
GLFWmonitor* monitorOf(GLFWwindow* window) {
    int wx = 0, wy = 0, ww = 0, wh = 0;
    glfwGetWindowPos(window, &wx, &wy);
    glfwGetWindowSize(window, &ww, &wh);
    int count = 0;
    GLFWmonitor** monitors = glfwGetMonitors(&count);
    GLFWmonitor* best = glfwGetPrimaryMonitor();
    long long bestArea = 0;
    for (int i = 0; i < count; ++i) {
        const GLFWvidmode* mode = glfwGetVideoMode(monitors[i]);
        if (!mode) continue;
        int mx = 0, my = 0;
        glfwGetMonitorPos(monitors[i], &mx, &my);
        const long long w = std::min(wx + ww, mx + mode->width) - std::max(wx, mx);
        const long long h = std::min(wy + wh, my + mode->height) - std::max(wy, my);
        if (w > 0 && h > 0 && w * h > bestArea) {
            bestArea = w * h;
            best = monitors[i];
        }
    }
    return best;
}

/// Esc: closes one thing, the innermost (escTarget), and never quits.
void closeInnermost(App& app) {
    WorkspaceUi& w = app.work;
    OpenThings open;
    open.popup = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId);
    open.inspector = app.inspector.open && app.inspector.valid;
    open.measureTable = app.accuracy.table && app.accuracy.job.report() != nullptr;
    open.help = w.help;
    open.fullscreen = w.fullscreen;
    switch (escTarget(open)) {
        case EscTarget::Popup: {
            ImGuiContext& g = *ImGui::GetCurrentContext();
            ImGui::ClosePopupToLevel(g.OpenPopupStack.Size - 1, true);
            break;
        }
        case EscTarget::Inspector:
            app.inspector.open = false;
            break;
        case EscTarget::MeasureTable:
            app.accuracy.table = false;
            break;
        case EscTarget::Help:
            w.help = false;
            break;
        case EscTarget::Fullscreen:
            toggleFullscreen(app);
            break;
        case EscTarget::None:
            break;
    }
}

}  // namespace

void applyActions(App& app) {
    WorkspaceUi& w = app.work;
    for (const Action a : app.keys.actions) {
        if (applyDocumentAction(a, app.model, app.compare.settings)) continue;
        switch (a) {
            case Action::Help:
                w.help = !w.help;
                break;
            case Action::Back:
                closeInnermost(app);
                break;
            case Action::Quit:
                askToQuit(app);
                break;
            case Action::TogglePanels:
                w.showPanels = !w.showPanels;
                break;
            case Action::Fullscreen:
                toggleFullscreen(app);
                break;
            case Action::Screenshot:
                app.screenshot.requested = true;
                break;
            case Action::ToggleStats:
                w.statsOverlay = !w.statsOverlay;
                break;
            case Action::ToggleDifference:  // not applied: nothing is compared
                showNotice(w,
                           "D shows the difference of two pictures: turn on Compare (C) or "
                           "side by side (G) first");
                break;
            case Action::ToggleLightMarker:
                app.light.shown = !app.light.shown;
                break;
            default:
                break;
        }
    }
    app.keys.actions.clear();
}

void toggleFullscreen(App& app) {
    WorkspaceUi& w = app.work;
    if (!app.window) return;
    if (!w.fullscreen) {
        glfwGetWindowPos(app.window, &w.windowed[0], &w.windowed[1]);
        glfwGetWindowSize(app.window, &w.windowed[2], &w.windowed[3]);
        GLFWmonitor* monitor = monitorOf(app.window);
        const GLFWvidmode* mode = monitor ? glfwGetVideoMode(monitor) : nullptr;
        if (!mode) return;
        glfwSetWindowMonitor(app.window, monitor, 0, 0, mode->width, mode->height,
                             mode->refreshRate);
        w.fullscreen = true;
    } else {
        glfwSetWindowMonitor(app.window, nullptr, w.windowed[0], w.windowed[1],
                             std::max(1, w.windowed[2]), std::max(1, w.windowed[3]), 0);
        w.fullscreen = false;
    }
    // The swap interval belongs to the context but some drivers reset it on a mode change.
    glfwSwapInterval(app.loop.vsync ? 1 : 0);
}

}  // namespace facet::view
