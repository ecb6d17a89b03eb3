// One frame of the viewer. Pipelined (the default), the engine renders the state the panels
// just produced on its own thread while this thread uploads, draws and swaps the previous
// engine frame; serial (--serial, or the Stats checkbox), it waits for the engine first. Both
// show a change in the very next frame drawn after the one in which it was made.
//
// The OpenGL twin draws on this thread, which owns the window's context. Side by side, both
// halves show the same state: the engine's picture of this frame is waited for, and the twin
// renders meanwhile (pipelined) or after it (serial, so neither time holds the other's work).
//
// While the Compare panel's accuracy job runs, the engine renders only when the view, the
// settings or the Compare state changed (the picture in hand is still right otherwise), and
// App::run() polls events ten times a second: the job's timings share the cores with as little
// of the viewer's own work as possible.

#include "frame_loop.hpp"

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdio>

#include "camera_input.hpp"
#include "panels_accuracy.hpp"
#include "panels_screenshot.hpp"
#include "screenshot.hpp"
#include "viewer_app.hpp"
#include "workspace_ui.hpp"

namespace facet::view {

int runFrame(App& app, Clock::time_point start, bool last) {
    int status = 0;
    app.stats.lastTimes = {};
    const auto tEvents = Clock::now();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    // The frame's size and place first: input maps mouse pixels through them.
    placeFrame(app);
    handleInput(app);
    drawPanels(app);
    if (app.loop.vsync != app.loop.vsyncApplied) {
        app.loop.vsyncApplied = app.loop.vsync;
        glfwSwapInterval(app.loop.vsyncApplied ? 1 : 0);
    }
    placeFrame(app);  // after the panels' edits (and the side bar's new width)
    if (app.model.rendererChoice != app.loop.lastChoice) {
        ++app.loop.rendererLog.switches;
        app.loop.lastChoice = app.model.rendererChoice;
    }
    FramePlan plan = planFrame(app.model.rendererChoice, app.compare.settings.enabled);
    const AccuracyView engineView =
        accuracyView(app.model.scene, app.model.sceneVersion, app.model.settings);
    // The frame in hand is this one: leave the cores to the job (or to the file being read).
    const bool skipEngine = (app.accuracy.job.running() || app.files.loading.running()) &&
                            plan.engine && !plan.twin && app.loop.engineFresh &&
                            engineView == app.loop.lastEngineView &&
                            app.compare.settings == app.loop.lastEngineCompare;
    if (skipEngine) plan.engine = false;
    const auto tPanels = Clock::now();

    bool inFlight = false;
    double waited = 0.0;
    auto submit = [&] {
        app.loop.worker->submit(app.model.scene, app.model.settings, app.compare.settings);
        inFlight = true;
        app.loop.lastEngineView = engineView;
        app.loop.lastEngineCompare = app.compare.settings;
    };
    auto collect = [&] {
        if (!inFlight) return;
        inFlight = false;
        const auto w0 = Clock::now();
        const RenderResult& r = app.loop.worker->wait(app.loop.display);
        waited += ms(w0, Clock::now());
        app.model.stats = r.stats;
        app.model.refused = r.refused;
        app.compare.sides.leftStats = r.stats;
        app.compare.sides.rightStats = r.rightStats;
        if (r.compared) app.compare.sides.diff = r.diff;
        recordEngineTimes(r, app.stats.lastTimes);
        ++app.loop.rendererLog.engineFrames;
    };
    if (plan.engine) submit();
    // Wait for this frame's engine picture before drawing when serial, when the one in hand is
    // stale (none yet, or the engine sat out the last frame), or side by side.
    const bool early =
        plan.engine && (!app.loop.pipelined || !app.loop.engineFresh || plan.sideBySide);
    bool twinDrew = false;
    auto drawTwin = [&] {
        twinDrew = renderTwin(app);
        if (!twinDrew) return;
        app.stats.lastTimes.twin = app.twin.ms;
        app.stats.lastTimes.twinUpload = app.twin.stats.uploadMs;
        app.stats.lastTimes.twinDraw = app.twin.stats.drawMs;
        app.stats.lastTimes.twinReadback = app.twin.stats.readbackMs;
    };
    if (plan.twin && app.loop.pipelined) drawTwin();
    if (early) collect();
    if (plan.twin && !app.loop.pipelined) drawTwin();
    if (plan.twin && !twinDrew && !plan.engine) {
        submit();  // the twin failed (and said why): the engine's picture of this state instead
        collect();
    }
    app.loop.engineFresh = plan.engine || (plan.twin && !twinDrew) || skipEngine;
    const auto tCompose = Clock::now();
    if (twinDrew && plan.sideBySide) {
        app.loop.shown = &composeSideBySide(app);
        app.stats.lastTimes.compare = ms(tCompose, Clock::now());
    } else {
        app.loop.shown = twinDrew ? &app.twin.frame : &app.loop.display;
    }
    const auto tCollected = Clock::now();

    app.loop.gl->upload(*app.loop.shown, app.view);
    const auto tUpload = Clock::now();
    app.loop.gl->draw(app.view, app.work.backdrop, app.fbWidth, app.fbHeight);
    // llvmpipe draws on the CPU when the commands are flushed: finishing each stage charges
    // its real cost to it instead of to the swap (the swap would wait for it anyway).
    glFinish();
    const auto tDraw = Clock::now();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glFinish();
    const auto tUi = Clock::now();
    if (app.screenshot.requested) takeScreenshot(app);
    app.screenshot.requested = false;
    if (last && !app.options.windowShot.empty()) {
        if (Status e = saveWindowShot(app.fbWidth, app.fbHeight, app.options.windowShot); !e) {
            std::fprintf(stderr, "facet-view: %s\n", e.error().what().c_str());
            status = 1;
        }
    }
    const auto tShot = Clock::now();
    glfwSwapBuffers(app.window);
    ++app.loop.frameCount;
    const auto tSwap = Clock::now();
    collect();  // pipelined: the frame rendered meanwhile becomes the next one shown
    const auto tEnd = Clock::now();

    app.stats.lastTimes.upload = ms(tCollected, tUpload);
    app.stats.lastTimes.draw = ms(tUpload, tDraw);
    app.stats.lastTimes.ui = ms(tEvents, tPanels) + ms(tDraw, tUi);
    app.stats.lastTimes.uiDraw = ms(tDraw, tUi);
    app.stats.lastTimes.present = ms(start, tEvents) + ms(tShot, tSwap);
    app.stats.lastTimes.wait = waited;
    app.stats.lastTimes.total = ms(start, tEnd) - ms(tUi, tShot);  // screenshots are not frame time
    app.stats.history.push(app.stats.lastTimes);
    announceAccuracy(app.accuracy);
    return status;
}

}  // namespace facet::view
