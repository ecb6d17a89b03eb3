#pragma once
// The running viewer: the window, the document, the GL frame and the panels' state, and the
// frame loop that ties them together (events → panels → engine render → upload → draw → UI →
// swap). Panels and input handlers get the App and edit it between frames.

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "accuracy_job.hpp"
#include "compare.hpp"
#include "file_list.hpp"
#include "frame_stats.hpp"
#include "gl_frame.hpp"
#include "inspector.hpp"
#include "layout.hpp"
#include "load_job.hpp"
#include "options.hpp"
#include "render_worker.hpp"
#include "renderer_choice.hpp"
#include "twin_view.hpp"
#include "viewer_model.hpp"
#include "workspace_ui.hpp"

struct GLFWwindow;

namespace facet::view {

/// What the panels keep between frames: text fields, the folder listing, the error popup.
struct UiState {
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
    std::string iniPath;               ///< ImGui's layout file (kept alive for ImGui)
    std::string texturePath;           ///< the Texture panel's path field
    std::string screenshotFolder;  ///< set at start: the pictures folder (screenshot_folder.hpp)
    bool screenshotWindowToo = false;  ///< the screenshot key also saves the whole window
    std::string lastScreenshot;        ///< what the last screenshot wrote (or its error)
    std::string popupTitle;            ///< error popup; opened on the next frame when set
    std::string popupMessage;
    bool popupPending = false;
    bool vsync = true;
    bool pipelined = true;   ///< the engine renders frame N+1 while N is drawn
    bool showPanels = true;  ///< Tab hides the panels
    int accuracySamples = kDefaultAccuracySamples;  ///< ground truth samples per axis
    bool accuracyOpen = false;  ///< the "Against the ground truth" section is open
};

/// A mouse drag that belongs to the viewer (it started over the image, not a panel).
struct DragState {
    int button = -1;       ///< ImGui mouse button, −1: none
    bool divider = false;  ///< the drag moves the Compare divider
    float lastX = 0.0f;    ///< where the pointer was last frame (at the press on its first)
    float lastY = 0.0f;
};

/// What the keys (key_map.hpp, dispatched by handleInput) asked the frame loop for.
struct KeyEvents {
    bool quit = false;
    bool screenshot = false;
    bool saveScene = false;  ///< Ctrl+S: save the scene shown
};

/// The whole viewer.
struct App {
    ViewerOptions options;
    GLFWwindow* window = nullptr;
    ViewerModel model;
    CompareSettings compare;  ///< the Compare panel's choices
    CompareView sides;        ///< two-sided frames' numbers and the CPU | OpenGL picture
    std::unique_ptr<GlFrame> gl;
    std::unique_ptr<RenderWorker> worker;  ///< the engine's thread
    Framebuffer display;                   ///< the engine's latest frame (from the worker)
    TwinView twin;                         ///< the OpenGL twin, in this window's context
    RendererLog rendererLog;               ///< what each renderer did, for --state
    RendererChoice lastChoice = RendererChoice::Cpu;  ///< the previous frame's, to count switches
    bool engineFresh = false;  ///< `display` is the engine's frame of the previous frame's state
    FrameHistory history;
    StageTimes lastTimes;  ///< the previous frame's split, shown by the Stats panel
    UiState ui;
    DragState drag;
    KeyEvents keys;
    WorkspaceUi work;  ///< side bar, overlays, pending key actions, light drag
    Rect view;         ///< where the frame is shown in the window
    int fbWidth = 0;   ///< framebuffer size, pixels
    int fbHeight = 0;
    const Framebuffer* shown = nullptr;  ///< the frame on screen: engine, twin or composed
    long long frameCount = 0;
    bool screenshotRequested = false;  ///< from the key or the button; taken this frame
    bool vsyncApplied = true;          ///< the swap interval last set
    AccuracyJob accuracy;              ///< Compare: the methods against the ground truth
    InspectorState inspector;          ///< the pixel inspector (Shift + click)
    LoadJob loading;                   ///< a scene or mesh being opened on a worker thread
    /// The large file named on the command line is on the loading thread (the default scene
    /// shows meanwhile); the command line's settings are applied again once it arrives.
    bool startupLoad = false;
    std::uint64_t accuracySeen = 0;  ///< reports announced on stdout so far
    /// The view and Compare settings the engine last rendered, so a frame can be skipped while
    /// the accuracy job measures (see frame_loop.cpp).
    AccuracyView lastEngineView;
    CompareSettings lastEngineCompare;

    /// Runs until the window closes, --frames is reached or SIGTERM/SIGINT; returns the exit code.
    int run();

    /// One frame, events already polled at `start`: panels, engine and/or twin, upload, draw,
    /// UI, swap. `last` also writes --window-shot. Returns 0, or 1 when an output could not be
    /// written.
    int frame(std::chrono::steady_clock::time_point start, bool last);
};

/// Starts opening a scene or mesh on the loading thread; the old scene stays until it is ready
/// (sceneFileEvents adopts it), and a failure opens the error popup.
void openScene(App& app, const std::string& path);

/// Makes a finished load the shown scene: the model adopts it, the panels' fields and the
/// window title follow.
void adoptScene(App& app, LoadedScene loaded);

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

/// Loads a texture into the scene, or opens the error popup.
void openTexture(App& app, const std::string& path);

/// Queues the error popup.
void showError(App& app, const std::string& title, const std::string& message);

/// Saves the shown engine frame (and the window when the panel asks for it) to the next free
/// numbered files in the screenshot folder; the frame loop calls it before the swap.
void takeScreenshot(App& app);

/// Mouse and keys for the camera and the Compare divider; call after ImGui::NewFrame().
void handleInput(App& app);

/// Announces a newly finished accuracy report on stdout (scripts and tests wait for it).
void announceAccuracy(App& app);

}  // namespace facet::view
