#include "panels.hpp"

#include <imgui.h>

#include <algorithm>

#include "viewer_app.hpp"

namespace facet::view {

void drawPanels(App& app) {
    if (planFrame(app.model.rendererChoice, app.compare.enabled).twin || app.compare.enabled)
        compareOverlay(app);
    sceneFileEvents(app);
    errorPopup(app);
    if (!app.ui.showPanels) return;

    // One column of collapsible panels on the left, as tall as what is open (llvmpipe pays
    // for every panel pixel: about 1 ms per 100k), scrolling beyond the window's height. The
    // Stats window sits at the top right.
    const float maxHeight = std::max(100.0f, ImGui::GetIO().DisplaySize.y - 20.0f);
    // Wider while the accuracy table shows (it has eight columns); the section says so each
    // frame it is drawn, so the width follows one frame later.
    const float width = app.ui.accuracyWide ? 540.0f : 360.0f;
    app.ui.accuracyWide = false;
    ImGui::SetNextWindowPos(ImVec2(10.0f, 10.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, maxHeight));
    if (ImGui::Begin("facet", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::PushItemWidth(-140.0f);  // room for the labels on the right
        if (ImGui::CollapsingHeader("Scene")) scenePanel(app);
        // Open at start: Render and Camera; Compare alone when the viewer starts comparing two
        // interpolations; Render and Compare (the renderer, then the numbers) side by side.
        const bool split = app.options.renderer == "split";
        auto openIf = [](bool open) {
            return open ? ImGuiTreeNodeFlags_DefaultOpen : ImGuiTreeNodeFlags_None;
        };
        if (ImGui::CollapsingHeader("Render", openIf(!app.options.compare))) renderPanel(app);
        if (ImGui::CollapsingHeader("Camera", openIf(!app.options.compare && !split)))
            cameraPanel(app);
        if (ImGui::CollapsingHeader("Light and material")) lightPanel(app);
        if (ImGui::CollapsingHeader("Texture")) texturePanel(app);
        if (ImGui::CollapsingHeader("Compare", openIf(app.options.compare || split)))
            comparePanel(app);
        if (ImGui::CollapsingHeader("Screenshot")) screenshotPanel(app);
        ImGui::PopItemWidth();
        ImGui::TextDisabled(
            "Esc quit, Tab panels, R reset camera, P screenshot, Ctrl+S save scene,\n"
            "G next renderer (CPU, OpenGL, side by side)");
    }
    ImGui::End();
    statsWindow(app);
}

void errorPopup(App& app) {
    const char* id = "Error##facet";
    if (app.ui.popupPending) {
        ImGui::OpenPopup(id);
        app.ui.popupPending = false;
    }
    const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::TextUnformatted(app.ui.popupTitle.c_str());
        ImGui::Separator();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 45.0f);
        ImGui::TextUnformatted(app.ui.popupMessage.c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::Button("OK", ImVec2(120.0f, 0.0f)) ||
            ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

}  // namespace facet::view
