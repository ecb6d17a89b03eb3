#include "popups.hpp"

#include <imgui.h>

#include "viewer_app.hpp"

namespace facet::view {

void showError(PopupState& popups, const std::string& title, const std::string& message) {
    popups.title = title;
    popups.message = message;
    popups.pending = true;
}

bool beginCentredModal(const char* id, bool& pending) {
    if (pending) {
        ImGui::OpenPopup(id);
        pending = false;
    }
    const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    return ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize);
}

void errorPopup(PopupState& popups) {
    if (beginCentredModal("Error##facet", popups.pending)) {
        ImGui::TextUnformatted(popups.title.c_str());
        ImGui::Separator();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 45.0f);
        ImGui::TextUnformatted(popups.message.c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::Button("OK", ImVec2(120.0f, 0.0f)) ||
            ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
}

void askToQuit(App& app) {
    PopupState& p = app.popups;
    // Asked already (the question is open): the second Ctrl+Q or close click quits.
    if (p.quitAsked || !app.model.unsaved()) {
        app.keys.quit = true;
        return;
    }
    p.quitAsked = true;
    p.quitPending = true;
}

void quitPopup(App& app) {
    PopupState& p = app.popups;
    if (beginCentredModal("Quit facet-view?##quit", p.quitPending)) {
        noteWindow(app.work, "quit_question");
        ImGui::TextUnformatted(
            "The scene has unsaved changes (camera, light, material or settings).");
        ImGui::TextDisabled("Ctrl+Q again quits, Esc stays.");
        if (ImGui::Button("Save and quit")) {
            // A failed save keeps the viewer open: its error says why.
            if (writeShownScene(app)) app.keys.quit = true;
            ImGui::CloseCurrentPopup();
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("to %s", app.files.saveScenePath.c_str());
        ImGui::SameLine();
        if (ImGui::Button("Quit without saving")) app.keys.quit = true;
        ImGui::SameLine();
        if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    } else {
        p.quitAsked = false;  // cancelled (or Esc): the next Ctrl+Q asks again
    }
}

}  // namespace facet::view
