#include "panels_screenshot.hpp"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <cstdio>

#include "screenshot.hpp"
#include "screenshot_folder.hpp"
#include "viewer_app.hpp"

namespace facet::view {

void screenshotPanel(ScreenshotState& screenshot) {
    ImGui::InputText("folder", &screenshot.folder);
    ImGui::TextDisabled("created when the first screenshot is saved");
    ImGui::Checkbox("the whole window too", &screenshot.windowToo);
    if (ImGui::Button("Save the frame (F12 or P)")) screenshot.requested = true;
    if (!screenshot.last.empty()) ImGui::TextWrapped("%s", screenshot.last.c_str());
}

void takeScreenshot(App& app) {
    if (!app.loop.shown) return;
    if (Status error = ensureFolder(app.screenshot.folder); !error) {
        app.screenshot.last = error.error().what();
        showNotice(app.work, app.screenshot.last);
        return;
    }
    const std::string framePath = nextFreePath(app.screenshot.folder, "facet-frame");
    if (Status error = saveFrameShot(*app.loop.shown, framePath); !error) {
        app.screenshot.last = error.error().what();
        showNotice(app.work, app.screenshot.last);
        return;
    }
    app.screenshot.last = framePath;
    if (app.screenshot.windowToo) {
        const std::string windowPath = nextFreePath(app.screenshot.folder, "facet-window");
        const Status error = saveWindowShot(app.fbWidth, app.fbHeight, windowPath);
        app.screenshot.last +=
            !error ? " (window: " + error.error().what() + ")" : ", " + windowPath;
    }
    showNotice(app.work, "Saved " + app.screenshot.last);
    std::printf("facet-view: saved %s\n", app.screenshot.last.c_str());
    std::fflush(stdout);
}

}  // namespace facet::view
