#pragma once
// Scene and Texture panels: opening files (a small browser, recent files, drag and drop),
// saving the scene shown, and the loading progress. A file that fails to load opens the error
// popup and leaves what was loaded before on screen.

#include <string>
#include <vector>

#include "file_list.hpp"
#include "load_job.hpp"

namespace facet::view {

struct App;

/// The Scene and Texture panels between frames: their fields, the folder listing, the save
/// path and the file being opened.
struct ScenePanelState {
    std::string scenePath;  ///< the Scene panel's path field
    std::string folder;     ///< the folder the Scene panel's browser lists
    std::vector<FolderEntry> folderFiles;
    std::string folderError;
    std::string saveScenePath;         ///< where "Save scene" (Ctrl+S) writes
    std::string lastSave;              ///< what the last save wrote (or its error)
    bool saveChosen = false;           ///< the save path was seen (dialog or field): Ctrl+S writes
    bool saveDialogPending = false;    ///< the save dialog opens in the next frame
    bool saveWindowSize = false;       ///< save the window's image size, not the scene's
    std::vector<std::string> dropped;  ///< paths dropped on the window since the last frame
    std::string texturePath;           ///< the Texture panel's path field
    LoadJob loading;                   ///< a scene or mesh being opened on a worker thread
    /// The large file named on the command line is on the loading thread (the default scene
    /// shows meanwhile); the command line's settings are applied again once it arrives.
    bool startupLoad = false;
};

/// Starts opening a scene or mesh on the loading thread; the old scene stays until it is ready
/// (sceneFileEvents adopts it), and a failure opens the error popup.
void openScene(App& app, const std::string& path);

/// Makes a finished load the shown scene: the model adopts it, the panels' fields and the
/// window title follow.
void adoptScene(App& app, LoadedScene loaded);

/// Loads a texture into the scene, or opens the error popup.
void openTexture(App& app, const std::string& path);

/// Once per frame, panels shown or not: adopts a finished load (or shows its error), opens
/// dropped files, handles Ctrl+S, and draws the loading progress with its Cancel button.
void sceneFileEvents(App& app);

/// Sends files dropped on the window to sceneFileEvents.
void installFileDrop(App& app);

/// Ctrl+S: the first time asks where (saveDialog, the scene's folder proposed), then writes to
/// that path.
void saveShownScene(App& app);

/// Writes the scene shown to the save path (made absolute) and says where over the image; false
/// (and the error popup) when it could not.
bool writeShownScene(App& app);

/// The first save's question: the path, the image size, Save or Cancel.
void saveDialog(App& app);

/// Scene: path field, a folder's .scene files, recent files; mesh facts.
void scenePanel(App& app);

/// Texture: the current image and a path field to load another.
void texturePanel(App& app);

}  // namespace facet::view
