#include "popups.hpp"

#include <imgui.h>

#include "viewer_app.hpp"

namespace facet::view {

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

void quitPopup(App& app) {
    WorkspaceUi& w = app.work;
    const char* id = "Quit facet-view?##quit";
    if (w.quitPending) {
        ImGui::OpenPopup(id);
        w.quitPending = false;
    }
    const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        noteWindow(app, "quit_question");
        ImGui::TextUnformatted(
            "The scene has unsaved changes (camera, light, material or settings).");
        ImGui::TextDisabled("Ctrl+Q again quits, Esc stays.");
        if (ImGui::Button("Save and quit")) {
            // A failed save keeps the viewer open: its error says why.
            if (writeShownScene(app)) app.keys.quit = true;
            ImGui::CloseCurrentPopup();
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("to %s", app.ui.saveScenePath.c_str());
        ImGui::SameLine();
        if (ImGui::Button("Quit without saving")) app.keys.quit = true;
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    } else {
        w.quitAsked = false;  // cancelled (or Esc): the next Ctrl+Q asks again
    }
}

}  // namespace facet::view
