#include "panels_scene.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <cstdio>
#include <filesystem>

#include "facet/texture.hpp"
#include "file_list.hpp"
#include "options.hpp"
#include "popups.hpp"
#include "scene_defaults.hpp"
#include "viewer_app.hpp"

namespace facet::view {
namespace {

std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

void onDrop(GLFWwindow* window, int count, const char** paths) {
    App* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    if (!app) return;
    for (int i = 0; i < count; ++i) app->files.dropped.emplace_back(paths[i]);
}

void listFolderInto(App& app, const std::string& folder) {
    app.files.folderError.clear();
    app.files.folder = std::filesystem::path(folder).lexically_normal().string();
    app.files.folderFiles = listFolder(app.files.folder, &app.files.folderError);
}

void openDropped(App& app) {
    if (app.files.dropped.empty()) return;
    const DropPlan plan = planDrop(app.files.dropped);
    app.files.dropped.clear();
    if (!plan.folder.empty()) listFolderInto(app, plan.folder);
    if (!plan.texture.empty()) {
        app.files.texturePath = plan.texture;
        openTexture(app, plan.texture);  // with the settings that show it, as any route
    }
    if (!plan.open.empty()) openScene(app, plan.open);
    if (!plan.refused.empty()) {
        std::string message;
        for (const std::string& r : plan.refused) message += r + "\n";
        showError(app.popups, "Cannot open the dropped file", message);
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
        const double seconds = app.files.loading.seconds();
        ImGui::TextWrapped("%s", fileName(app.files.loading.path()).c_str());
        const float done = app.files.loading.progress();
        char label[48];
        std::snprintf(label, sizeof label, "%.0f %%  (%.1f s)", 100.0 * done, seconds);
        ImGui::ProgressBar(done, ImVec2(-1.0f, 0.0f), label);
        ImGui::TextDisabled("the current scene stays until this one is ready");
        if (ImGui::Button("Cancel")) app.files.loading.cancel();
        // Where Cancel is, for the window tests (--state) to click it.
        const ImVec2 at = ImGui::GetItemRectMin();
        const ImVec2 button = ImGui::GetItemRectSize();
        app.work.drawn["loading_cancel"] = {static_cast<int>(at.x), static_cast<int>(at.y),
                                            static_cast<int>(button.x), static_cast<int>(button.y)};
        noteWindow(app.work, "loading");
    }
    ImGui::End();
}

}  // namespace

void openScene(App& app, const std::string& path) {
    app.files.startupLoad = false;  // replaced: the command line's file is no longer coming
    app.files.scenePath = path;
    app.files.loading.start(path, app.model.openOptions());
}

void adoptScene(App& app, LoadedScene loaded) {
    const std::string path = loaded.path;
    app.model.adopt(std::move(loaded));
    if (app.files.startupLoad) {
        // The command line's file: its options win over the scene's defaults, as they do when
        // it loads before the window opens (they were checked then).
        app.files.startupLoad = false;
        (void)facet::app::applyRenderOptions(app.options, app.model.settings);
        app.model.markSaved();  // what the command line asked for is no unsaved change
    }
    app.files.scenePath = path;
    app.files.texturePath = app.model.scene.texturePath;
    app.files.saveScenePath = defaultSavePath(path);
    app.files.saveChosen = false;  // a new scene: its first save asks where again
    if (app.window) glfwSetWindowTitle(app.window, windowTitle(app.model.scene).c_str());
}

void openTexture(App& app, const std::string& path) {
    if (Status error = app.model.loadTexture(path); !error)
        showError(app.popups, "Cannot load the texture", error.error().what());
}

void installFileDrop(App& app) {
    if (app.window) glfwSetDropCallback(app.window, onDrop);
}

void saveShownScene(App& app) {
    if (!app.files.saveChosen) {
        app.files.saveDialogPending = true;  // the first save asks where (saveDialog)
        return;
    }
    writeShownScene(app);
}

bool writeShownScene(App& app) {
    if (app.files.saveScenePath.empty()) return false;
    std::error_code ec;
    const std::string full =
        std::filesystem::absolute(app.files.saveScenePath, ec).lexically_normal().string();
    if (Status error = app.model.saveScene(full, app.files.saveWindowSize); !error) {
        app.files.lastSave = error.error().what();
        showError(app.popups, "Cannot save the scene", error.error().what());
        return false;
    }
    app.files.saveScenePath = full;
    app.files.saveChosen = true;
    app.files.lastSave = "saved " + full;
    showNotice(app.work, "Saved to " + full);
    std::printf("facet-view: saved scene %s\n", full.c_str());
    std::fflush(stdout);
    return true;
}

void saveDialog(App& app) {
    const bool focus = app.files.saveDialogPending;  // opened in this frame: the path field
    if (!beginCentredModal("Save scene##save", app.files.saveDialogPending)) return;
    noteWindow(app.work, "save_dialog");
    const Camera user = app.model.userCamera();
    const Camera& frame = app.model.scene.camera;
    ImGui::TextUnformatted("The camera, light and material shown, as a .scene file:");
    ImGui::SetNextItemWidth(ImGui::GetFontSize() * 32.0f);
    if (focus) ImGui::SetKeyboardFocusHere();
    const bool enter = ImGui::InputText("##savepath", &app.files.saveScenePath,
                                        ImGuiInputTextFlags_EnterReturnsTrue);
    char label[96];
    std::snprintf(label, sizeof label, "at the window's size (%dx%d), not the scene's (%dx%d)",
                  frame.width, frame.height, user.width, user.height);
    ImGui::Checkbox(label, &app.files.saveWindowSize);
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
    if (std::optional<Result<LoadedScene>> done = app.files.loading.take()) {
        if (*done) {
            adoptScene(app, std::move(*done).value());
        } else {
            if (app.files.startupLoad)  // the command line's file: said where scripts look too
                std::fprintf(stderr, "facet-view: %s\n", done->error().what().c_str());
            app.files.startupLoad = false;
            showError(app.popups, "Cannot open the file",
                      done->error().what() + "\n\nThe previous scene stays.");
        }
    }
    openDropped(app);
    if (app.keys.saveScene) saveShownScene(app);
    app.keys.saveScene = false;
    if (app.files.loading.running()) loadingWindow(app);
}

void scenePanel(App& app) {
    const Scene& scene = app.model.scene;
    ImGui::TextWrapped("%s%s", scene.path.c_str(), app.model.bareMesh ? " (bare mesh)" : "");
    ImGui::TextDisabled("%zu vertices, %zu triangles%s%s%s", scene.mesh->vertexCount(),
                        scene.mesh->triangleCount(), scene.mesh->hasColors() ? ", colours" : "",
                        scene.mesh->hasUvs() ? ", uv" : "",
                        scene.mesh->hasNormals() ? ", normals from the file" : "");

    const bool enter =
        ImGui::InputText("##scene", &app.files.scenePath, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Open") || enter) openScene(app, app.files.scenePath);

    const bool save =
        ImGui::InputText("##save", &app.files.saveScenePath, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Save scene") || save) writeShownScene(app);  // the path is in view
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "Ctrl+S: write the camera, image size, light and material shown as a .scene file");
    if (!app.files.lastSave.empty()) ImGui::TextDisabled("%s", app.files.lastSave.c_str());

    // The browser: folders (and ".." up), scenes, meshes, images; a click opens or lists.
    const bool list =
        ImGui::InputText("##folder", &app.files.folder, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("List folder") || list) listFolderInto(app, app.files.folder);
    if (!app.files.folderError.empty())
        ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "%s", app.files.folderError.c_str());
    if (ImGui::BeginListBox("##files",
                            ImVec2(-1.0f, 7.5f * ImGui::GetTextLineHeightWithSpacing()))) {
        // Acted on after the loop: opening or listing changes the list being drawn.
        const FolderEntry* chosen = nullptr;
        for (const FolderEntry& f : app.files.folderFiles) {
            const bool dim = f.kind == EntryKind::image;
            if (dim) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.7f, 0.8f, 1.0f, 1.0f));
            if (ImGui::Selectable(f.name.c_str(), f.path == scene.path)) chosen = &f;
            if (dim) ImGui::PopStyleColor();
        }
        if (app.files.folderFiles.size() <= 1) ImGui::TextDisabled("no scenes, meshes or images");
        ImGui::EndListBox();
        if (chosen) {
            const FolderEntry entry = *chosen;
            if (entry.kind == EntryKind::folder || entry.kind == EntryKind::parent)
                listFolderInto(app, entry.path);
            else
                app.files.dropped.push_back(entry.path);  // opened as a drop would be
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
        ImGui::InputText("##texture", &app.files.texturePath, ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if (ImGui::Button("Load") || enter) openTexture(app, app.files.texturePath);
    if (app.model.settings.shader != ShaderKind::Texture && ImGui::Button("Use the texture shader"))
        app.model.settings.shader = ShaderKind::Texture;
}

}  // namespace facet::view
