// Scene and Texture panels: opening files (a small browser, recent files, drag and drop),
// saving the scene shown, and the loading progress. A file that fails to load opens the error
// popup and leaves what was loaded before on screen.

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <cstdio>
#include <filesystem>

#include "facet/texture.hpp"
#include "file_list.hpp"
#include "popups.hpp"
#include "scene_defaults.hpp"
#include "viewer_app.hpp"
#include "workspace_ui.hpp"

namespace facet::view {
namespace {

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
    App* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    if (!app) return;
    for (int i = 0; i < count; ++i) app->ui.dropped.emplace_back(paths[i]);
}

void listFolderInto(App& app, const std::string& folder) {
    app.ui.folderError.clear();
    app.ui.folder = std::filesystem::path(folder).lexically_normal().string();
    app.ui.folderFiles = listFolder(app.ui.folder, &app.ui.folderError);
}

void openDropped(App& app) {
    if (app.ui.dropped.empty()) return;
    const DropPlan plan = planDrop(app.ui.dropped);
    app.ui.dropped.clear();
    if (!plan.folder.empty()) listFolderInto(app, plan.folder);
    if (!plan.texture.empty()) {
        app.ui.texturePath = plan.texture;
        openTexture(app, plan.texture);  // with the settings that show it, as any route
    }
    if (!plan.open.empty()) openScene(app, plan.open);
    if (!plan.refused.empty()) {
        std::string message;
        for (const std::string& r : plan.refused) message += r + "\n";
        showError(app, "Cannot open the dropped file", message);
    }
}

// The loading window: name, the fraction read and the time, Cancel.
void loadingWindow(App& app) {
    const ImVec2 size = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(size.x * 0.5f, size.y * 0.5f), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(420.0f, 0.0f));
    if (ImGui::Begin("Opening##load", nullptr,
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize |
                         ImGuiWindowFlags_NoSavedSettings)) {
        const double seconds = app.loading.seconds();
        ImGui::TextWrapped("%s", fileName(app.loading.path()).c_str());
        const float done = app.loading.progress();
        char label[48];
        std::snprintf(label, sizeof label, "%.0f %%  (%.1f s)", 100.0 * done, seconds);
        ImGui::ProgressBar(done, ImVec2(-1.0f, 0.0f), label);
        ImGui::TextDisabled("the current scene stays until this one is ready");
        if (ImGui::Button("Cancel")) app.loading.cancel();
        // Where Cancel is, for the window tests (--state) to click it.
        const ImVec2 at = ImGui::GetItemRectMin();
        const ImVec2 button = ImGui::GetItemRectSize();
        app.work.drawn["loading_cancel"] = {static_cast<int>(at.x), static_cast<int>(at.y),
                                            static_cast<int>(button.x), static_cast<int>(button.y)};
        noteWindow(app, "loading");
    }
    ImGui::End();
}

}  // namespace

void installFileDrop(App& app) {
    if (app.window) glfwSetDropCallback(app.window, onDrop);
}

void saveShownScene(App& app) {
    if (!app.ui.saveChosen) {
        app.ui.saveDialogPending = true;  // the first save asks where (saveDialog)
        return;
    }
    writeShownScene(app);
}

bool writeShownScene(App& app) {
    if (app.ui.saveScenePath.empty()) return false;
    std::error_code ec;
    const std::string full =
        std::filesystem::absolute(app.ui.saveScenePath, ec).lexically_normal().string();
    if (Status error = app.model.saveScene(full, app.ui.saveWindowSize); !error) {
        app.ui.lastSave = error.error().what();
        showError(app, "Cannot save the scene", error.error().what());
        return false;
    }
    app.ui.saveScenePath = full;
    app.ui.saveChosen = true;
    app.ui.lastSave = "saved " + full;
    showNotice(app, "Saved to " + full);
    std::printf("facet-view: saved scene %s\n", full.c_str());
    std::fflush(stdout);
    return true;
}

void saveDialog(App& app) {
    const char* id = "Save scene##save";
    bool focus = false;
    if (app.ui.saveDialogPending) {
        ImGui::OpenPopup(id);
        app.ui.saveDialogPending = false;
        focus = true;
    }
    const ImVec2 centre(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f);
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    noteWindow(app, "save_dialog");
    const Camera user = app.model.userCamera();
    const Camera& frame = app.model.scene.camera;
    ImGui::TextUnformatted("The camera, light and material shown, as a .scene file:");
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 32.0f);
    if (focus) ImGui::SetKeyboardFocusHere();
    const bool enter =
        ImGui::InputText("##savepath", &app.ui.saveScenePath, ImGuiInputTextFlags_EnterReturnsTrue);
    char label[96];
    std::snprintf(label, sizeof label, "at the window's size (%dx%d), not the scene's (%dx%d)",
                  frame.width, frame.height, user.width, user.height);
    ImGui::Checkbox(label, &app.ui.saveWindowSize);
    if (ImGui::Button("Save") || enter) {
        if (writeShownScene(app)) ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) ImGui::CloseCurrentPopup();
    ImGui::SameLine();
    ImGui::TextDisabled("Enter saves, Esc cancels");
    ImGui::EndPopup();
}

void sceneFileEvents(App& app) {
    if (std::optional<Result<LoadedScene>> done = app.loading.take()) {
        if (*done) {
            adoptScene(app, std::move(*done).value());
        } else {
            if (app.startupLoad)  // the command line's file: said where scripts look too
                std::fprintf(stderr, "facet-view: %s\n", done->error().what().c_str());
            app.startupLoad = false;
            showError(app, "Cannot open the file",
                      done->error().what() + "\n\nThe previous scene stays.");
        }
    }
    openDropped(app);
    if (app.keys.saveScene) saveShownScene(app);
    app.keys.saveScene = false;
    if (app.loading.running()) loadingWindow(app);
}

void scenePanel(App& app) {
    const Scene& scene = app.model.scene;
    ImGui::TextWrapped("%s%s", scene.path.c_str(), app.model.bareMesh ? " (bare mesh)" : "");
    ImGui::TextDisabled("%zu vertices, %zu triangles%s%s%s", scene.mesh->vertexCount(),
                        scene.mesh->triangleCount(), scene.mesh->hasColors() ? ", colours" : "",
                        scene.mesh->hasUvs() ? ", uv" : "",
                        scene.mesh->hasNormals() ? ", normals from the file" : "");

    const bool enter =
        ImGui::InputText("##scene", &app.ui.scenePath, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Open") || enter) openScene(app, app.ui.scenePath);

    const bool save =
        ImGui::InputText("##save", &app.ui.saveScenePath, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Save scene") || save) writeShownScene(app);  // the path is in view
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Ctrl+S: write the camera, image size, light and material shown as a .scene file");
    if (!app.ui.lastSave.empty()) ImGui::TextDisabled("%s", app.ui.lastSave.c_str());

    // The browser: folders (and ".." up), scenes, meshes, images; a click opens or lists.
    const bool list =
        ImGui::InputText("##folder", &app.ui.folder, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("List folder") || list) listFolderInto(app, app.ui.folder);
    if (!app.ui.folderError.empty())
        ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "%s", app.ui.folderError.c_str());
    if (ImGui::BeginListBox("##files",
                            ImVec2(-1.0f, 7.5f * ImGui::GetTextLineHeightWithSpacing()))) {
        // Acted on after the loop: opening or listing changes the list being drawn.
        const FolderEntry* chosen = nullptr;
        for (const FolderEntry& f : app.ui.folderFiles) {
            const bool dim = f.kind == EntryKind::image;
            if (dim) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.7f, 0.8f, 1.0f, 1.0f));
            if (ImGui::Selectable(f.name.c_str(), f.path == scene.path)) chosen = &f;
            if (dim) ImGui::PopStyleColor();
        }
        if (app.ui.folderFiles.size() <= 1) ImGui::TextDisabled("no scenes, meshes or images");
        ImGui::EndListBox();
        if (chosen) {
            const FolderEntry entry = *chosen;
            if (entry.kind == EntryKind::folder || entry.kind == EntryKind::parent)
                listFolderInto(app, entry.path);
            else
                app.ui.dropped.push_back(entry.path);  // opened as a drop would be
        }
    }
    ImGui::TextDisabled("or drop a scene, mesh, image or folder on the window");
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
