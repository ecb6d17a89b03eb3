#include "viewer_app.hpp"

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "facet/scene_io.hpp"
#include "file_list.hpp"
#include "resources.hpp"
#include "scene_defaults.hpp"
#include "screenshot.hpp"
#include "screenshot_folder.hpp"
#include "state_file.hpp"
#include "ui_style.hpp"
#include "workspace_state.hpp"

namespace facet::view {
namespace {

// A file named on the command line above this size opens on the loading thread (App::run); a
// few megabytes of mesh load in well under a second.
constexpr std::uintmax_t kStartupLoadBytes = std::uintmax_t{8} << 20;

volatile std::sig_atomic_t gStopSignal = 0;  // SIGTERM/SIGINT: finish the frame, write outputs

void onSignal(int) {
    gStopSignal = 1;
}

std::string gGlfwError;  // the last GLFW error, for the one-line message

void onGlfwError(int, const char* description) {
    gGlfwError = description ? description : "unknown GLFW error";
}

void onKey(GLFWwindow* window, int key, int, int action, int mods) {
    if (action != GLFW_PRESS) return;
    App* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    // Ctrl+S saves even from a text field (the save path's own, typically); Ctrl+Q quits
    // from anywhere, the quit question too.
    if (app && key == GLFW_KEY_S && (mods & GLFW_MOD_CONTROL)) {
        app->keys.saveScene = true;
        return;
    }
    if (app && key == GLFW_KEY_Q && (mods & GLFW_MOD_CONTROL)) {
        app->keys.actions.push_back(Action::Quit);
        return;
    }
    // Esc closes the innermost thing, a modal pop-up too (which owns the keyboard), unless a
    // text field is being edited: there it leaves the field.
    if (app && key == GLFW_KEY_ESCAPE && !ImGui::GetIO().WantTextInput) {
        app->keys.actions.push_back(Action::Back);
        return;
    }
    // A text field being edited owns the keyboard (P is a letter, Esc leaves the field).
    if (!app || ImGui::GetIO().WantCaptureKeyboard) return;
    // Keys without a character here; the others come through onChar, as typed.
    std::optional<NamedKey> named;
    switch (key) {
        case GLFW_KEY_ESCAPE:
            named = NamedKey::Escape;
            break;
        case GLFW_KEY_TAB:
            named = NamedKey::Tab;
            break;
        case GLFW_KEY_HOME:
            named = NamedKey::Home;
            break;
        case GLFW_KEY_F1:
            named = NamedKey::F1;
            break;
        case GLFW_KEY_F11:
            named = NamedKey::F11;
            break;
        case GLFW_KEY_F12:
            named = NamedKey::F12;
            break;
        default:
            return;
    }
    if (const std::optional<Action> a = actionForKey(*named)) app->keys.actions.push_back(*a);
}

void onChar(GLFWwindow* window, unsigned codepoint) {
    App* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    if (!app || ImGui::GetIO().WantCaptureKeyboard) return;
    if (const std::optional<Action> a = actionForChar(codepoint)) app->keys.actions.push_back(*a);
}

/// The window's close button asks as Ctrl+Q does (askToQuit, in the next frame).
void onClose(GLFWwindow* window) {
    App* app = static_cast<App*>(glfwGetWindowUserPointer(window));
    if (!app) return;
    glfwSetWindowShouldClose(window, GLFW_FALSE);
    app->keys.actions.push_back(Action::Quit);
}

void onContentScale(GLFWwindow* window, float, float) {
    if (App* app = static_cast<App*>(glfwGetWindowUserPointer(window)))
        app->work.scaleChanged = true;
}

/// The window size: --size, else room for the scene's image beside the side bar, within the
/// monitor's work area less the window's decorations (the image shrinks, aspect kept, to fit).
void initialWindowSize(const ViewerOptions& o, const Camera& camera, GLFWwindow* window,
                       int sidebarWidth, int& w, int& h) {
    if (o.width > 0 && o.height > 0) {
        w = o.width;
        h = o.height;
        return;
    }
    int workW = 0, workH = 0;
    if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
        int x = 0, y = 0;
        glfwGetMonitorWorkarea(monitor, &x, &y, &workW, &workH);
    }
    int left = 0, top = 0, right = 0, bottom = 0;  // decorations; 0 without a window manager
    glfwGetWindowFrameSize(window, &left, &top, &right, &bottom);
    if (workW > 0) workW -= left + right;
    if (workH > 0) workH -= top + bottom;
    const OpeningSize size = openingSize(camera.width, camera.height, sidebarWidth, workW, workH);
    w = size.width;
    h = size.height;
}

}  // namespace

std::string windowTitle(const Scene& scene) {
    return "facet-view - " + std::filesystem::path(scene.path).filename().string();
}

int App::run() {
    std::signal(SIGTERM, onSignal);
    std::signal(SIGINT, onSignal);
    int status = 0;
    const std::string path = options.scene.empty() ? defaultScenePath() : options.scene;
    Status error;
    if (path.empty()) error = Error{{"assets/default.scene", 0}, "not found; name a .scene file"};
    // A large file opens on the loading thread as one chosen in the window does, so the window
    // and its progress bar are up at once; the default scene shows until it is ready. Smaller
    // files load here, so bad input still ends the run with exit code 2 and one line, and so
    // does everything in a run of a fixed number of frames (--frames: a script wants that file).
    std::error_code sizeError;
    files.startupLoad = error && options.frames <= 0 && path != defaultScenePath() &&
                        options.texture.empty() &&
                        std::filesystem::is_regular_file(path, sizeError) &&
                        std::filesystem::file_size(path, sizeError) > kStartupLoadBytes &&
                        !defaultScenePath().empty();
    if (const std::optional<UpAxis> up = parseUpAxis(options.up))
        model.up = *up;
    else if (error)
        error = Error{{}, "--up " + options.up + ": expected x, y or z"};
    if (error) error = model.load(files.startupLoad ? defaultScenePath() : path);
    // After the load: the default scene shown meanwhile is not one the user opened.
    model.recentFile = configFolder().empty() ? "" : configFolder() + "/recent.txt";
    model.recent = readRecent(model.recentFile, kMaxRecent);
    // A file named on the command line is one the user opened (the default scene is not).
    if (error && !files.startupLoad && path != defaultScenePath()) model.rememberFile(path);
    if (files.startupLoad) files.loading.start(path, model.openOptions());
    // The same route as a texture chosen in the window (ViewerModel::loadTexture).
    if (error && !options.texture.empty()) error = model.loadTexture(options.texture);
    if (error) error = facet::app::applyRenderOptions(options, model.settings);
    model.markSaved();  // the command line's choices are where the user starts
    if (!error) {       // bad input is reported the same with or without a display
        std::fprintf(stderr, "facet-view: %s\n", error.error().what().c_str());
        return 2;
    }
    files.scenePath = path;
    files.folder = std::filesystem::path(path).parent_path().string();
    files.folderFiles = listFolder(files.folder, &files.folderError);
    files.saveScenePath = defaultSavePath(path);
    files.texturePath = model.scene.texturePath;
    screenshot.folder = screenshotFolder(picturesEnvFromProcess());
    loop.vsync = !options.noVsync;
    model.sizePolicy = options.keepSceneSize ? SizePolicy::SceneSize : SizePolicy::FollowWindow;
    compare.settings.enabled = options.compare;
    model.rendererChoice = parseRenderer(options.renderer).value_or(RendererChoice::Cpu);
    loop.lastChoice = model.rendererChoice;
    loop.pipelined = !options.serial;
    if (options.difference) compare.settings.display = CompareDisplay::Difference;
    work.showPanels = !options.hidePanels;

    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        std::fprintf(stderr,
                     "facet-view: cannot open a window (%s); run it under a virtual display "
                     "with `xvfb-run -a facet-view ...`, or render to a PNG with `facet render "
                     "SCENE -o OUT.png`\n",
                     gGlfwError.c_str());
        return 2;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    // No depth or stencil buffer: nothing here needs one, so none is cleared or carried.
    glfwWindowHint(GLFW_DEPTH_BITS, 0);
    glfwWindowHint(GLFW_STENCIL_BITS, 0);
    // Hidden until sized: its content scale and decorations decide the size it opens at.
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    window = glfwCreateWindow(640, 480, windowTitle(model.scene).c_str(), nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "facet-view: cannot create an OpenGL 3.3 core window (%s)\n",
                     gGlfwError.c_str());
        glfwTerminate();
        return 2;
    }
    work.scale = windowUiScale(window, options.uiScale);
    work.sidebarWidth = static_cast<int>(kSidebarWidth * work.scale + 0.5f);
    // A window sized for the scene beside the full side bar keeps that layout until resized.
    if (options.width <= 0 || options.height <= 0) work.keepWidthAt = -1;
    int width = 0, height = 0;
    initialWindowSize(options, model.sceneCamera, window, work.showPanels ? work.sidebarWidth : 0,
                      width, height);
    glfwSetWindowSize(window, width, height);
    glfwShowWindow(window);
    glfwMakeContextCurrent(window);
    glfwSwapInterval(loop.vsync ? 1 : 0);
    glfwSetWindowUserPointer(window, this);
    // Before ImGui's, which chain to them.
    glfwSetKeyCallback(window, onKey);
    glfwSetCharCallback(window, onChar);
    glfwSetWindowCloseCallback(window, onClose);
    glfwSetWindowContentScaleCallback(window, onContentScale);
    installFileDrop(*this);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    // The panels' layout is kept with the recent files, never in the working folder.
    iniPath = configFolder().empty() ? "" : configFolder() + "/imgui.ini";
    if (!iniPath.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(configFolder(), ec);
    }
    ImGui::GetIO().IniFilename = iniPath.empty() ? nullptr : iniPath.c_str();
    applyUiStyle(work.scale, false);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");

    loop.gl = std::make_unique<GlFrame>();
    if (Status e = loop.gl->init(); !e) {  // names the shader file, with the GLSL log
        std::fprintf(stderr, "facet-view: %s\n", e.error().what().c_str());
        status = 1;
    }

    loop.worker = std::make_unique<RenderWorker>();
    loop.vsyncApplied = loop.vsync;
    while (status == 0) {
        const auto start = std::chrono::steady_clock::now();
        // While the accuracy job measures or a file loads, ten frames a second are enough for
        // the progress bar and leave the cores to the job (frame_loop.cpp skips unchanged engine
        // frames too); input still wakes the loop at once.
        if (accuracy.job.running() || files.loading.running())
            glfwWaitEventsTimeout(0.1);
        else
            glfwPollEvents();
        const bool last = glfwWindowShouldClose(window) || keys.quit || gStopSignal ||
                          (options.frames > 0 && loop.frameCount + 1 >= options.frames);
        if (work.scaleChanged && options.uiScale <= 0.0) {  // moved to another monitor
            const float scale = windowUiScale(window, options.uiScale);
            work.sidebarWidth =
                static_cast<int>(static_cast<float>(work.sidebarWidth) * scale / work.scale + 0.5f);
            work.sidebarSizeSet = true;
            work.scale = scale;
            applyUiStyle(scale, true);
        }
        work.scaleChanged = false;
        glfwGetFramebufferSize(window, &fbWidth, &fbHeight);
        if (fbWidth <= 0 || fbHeight <= 0) {  // minimised: nothing to draw
            if (last) break;
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        status = runFrame(*this, start, last);
        if (last) break;
    }
    // No job is in flight after a frame: `shown` is the newest picture (with the engine on its
    // own thread, the engine frame collected after the last swap).
    loop.worker->wait(loop.display);
    if (!loop.shown) loop.shown = &loop.display;
    accuracy.job.cancel();  // a ground truth in flight stops within milliseconds
    accuracy.job.wait();

    if (status == 0 && !options.screenshot.empty() && loop.shown) {
        if (Status e = saveFrameShot(*loop.shown, options.screenshot); !e) {
            std::fprintf(stderr, "facet-view: %s\n", e.error().what().c_str());
            status = 1;
        }
    }
    if (!options.statePath.empty()) {
        const std::string text = stateText(model, loop.frameCount) +
                                 rendererLogText(loop.rendererLog) +
                                 accuracyStateText(accuracy.job.report().get()) +
                                 workspaceStateText(*this) + inspectorStateText(*this);
        if (Status e = writeTextFile(options.statePath, text); !e) {
            std::fprintf(stderr, "facet-view: %s\n", e.error().what().c_str());
            status = 1;
        }
    }
    files.loading.cancel();  // after --state, which tells whether a load was in flight
    if (options.fpsReport) {
        // The first frames pay for first-touch allocations and ImGui's layout pass.
        const std::size_t skip = std::min<std::size_t>(10, stats.history.frames.size() / 5);
        std::printf("%s\n", fpsReport(stats.history, skip).c_str());
    }

    loop.worker.reset();
    twin.renderer.reset();  // GL objects go while the context is current
    loop.gl.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    window = nullptr;
    glfwTerminate();
    return status;
}

}  // namespace facet::view
