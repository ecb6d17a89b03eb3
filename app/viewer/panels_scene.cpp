// Scene and Texture panels: opening files. A file that fails to load opens the error popup and
// leaves what was loaded before on screen.

#include <imgui.h>
#include <imgui_stdlib.h>

#include <filesystem>

#include "facet/texture.hpp"
#include "file_list.hpp"
#include "panels.hpp"
#include "viewer_app.hpp"

namespace facet::view {
namespace {

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

}  // namespace

void scenePanel(App& app) {
    const Scene& scene = app.model.scene;
    ImGui::TextWrapped("%s", scene.path.c_str());
    ImGui::TextDisabled("%zu vertices, %zu triangles%s%s", scene.mesh->vertexCount(),
                        scene.mesh->triangleCount(), scene.mesh->hasColors() ? ", colours" : "",
                        scene.mesh->hasUvs() ? ", uv" : "");

    const bool enter =
        ImGui::InputText("##scene", &app.ui.scenePath, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Open") || enter) openScene(app, app.ui.scenePath);

    const bool list =
        ImGui::InputText("##folder", &app.ui.folder, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("List folder") || list) {
        app.ui.folderError.clear();
        app.ui.folderFiles = listSceneFiles(app.ui.folder, &app.ui.folderError);
    }
    if (!app.ui.folderError.empty())
        ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "%s", app.ui.folderError.c_str());
    if (ImGui::BeginListBox("##files",
                            ImVec2(-1.0f, 5.5f * ImGui::GetTextLineHeightWithSpacing()))) {
        // Opened after the loop: loading changes the recent list and the scene being listed.
        std::string chosen;
        for (const std::string& f : app.ui.folderFiles)
            if (ImGui::Selectable(fileName(f).c_str(), f == scene.path)) chosen = f;
        if (app.ui.folderFiles.empty()) ImGui::TextDisabled("no .scene files here");
        ImGui::EndListBox();
        if (!chosen.empty()) openScene(app, chosen);
    }
    if (app.model.recent.size() > 1 && ImGui::TreeNode("Recent")) {
        std::string chosen;
        for (const std::string& f : app.model.recent)
            if (ImGui::Selectable(f.c_str())) chosen = f;
        ImGui::TreePop();
        if (!chosen.empty()) openScene(app, chosen);
    }
}

void texturePanel(App& app) {
    const Scene& scene = app.model.scene;
    if (scene.texture)
        ImGui::TextWrapped("%s: %dx%d, %d mip levels", fileName(scene.texture->name()).c_str(),
                           scene.texture->width(), scene.texture->height(),
                           scene.texture->levelCount());
    else
        ImGui::TextDisabled("no texture (the texture shader samples white)");
    if (!scene.mesh->hasUvs()) ImGui::TextDisabled("this mesh has no texture coordinates");
    const bool enter =
        ImGui::InputText("##texture", &app.ui.texturePath, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Load") || enter) openTexture(app, app.ui.texturePath);
    if (app.model.settings.shader != ShaderKind::Texture && ImGui::Button("Use the texture shader"))
        app.model.settings.shader = ShaderKind::Texture;
}

}  // namespace facet::view
