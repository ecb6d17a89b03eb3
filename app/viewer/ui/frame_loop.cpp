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

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdio>

#include "accuracy_job.hpp"
#include "popups.hpp"
#include "screenshot.hpp"
#include "viewer_app.hpp"

namespace facet::view {

int App::frame(Clock::time_point start, bool last) {
    int status = 0;
    lastTimes = {};
    const auto tEvents = Clock::now();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    // The frame's size and place first: input maps mouse pixels through them.
    placeFrame(*this);
    handleInput(*this);
    drawPanels(*this);
    if (ui.vsync != vsyncApplied) {
        vsyncApplied = ui.vsync;
        glfwSwapInterval(vsyncApplied ? 1 : 0);
    }
    placeFrame(*this);  // after the panels' edits (and the side bar's new width)
    if (model.rendererChoice != lastChoice) {
        ++rendererLog.switches;
        lastChoice = model.rendererChoice;
    }
    FramePlan plan = planFrame(model.rendererChoice, compare.enabled);
    const AccuracyView engineView = accuracyView(model.scene, model.sceneVersion, model.settings);
    // The frame in hand is this one: leave the cores to the job (or to the file being read).
    const bool skipEngine = (accuracy.running() || loading.running()) && plan.engine &&
                            !plan.twin && engineFresh && engineView == lastEngineView &&
                            compare == lastEngineCompare;
    if (skipEngine) plan.engine = false;
    const auto tPanels = Clock::now();

    bool inFlight = false;
    double waited = 0.0;
    auto submit = [&] {
        worker->submit(model.scene, model.settings, compare);
        inFlight = true;
        lastEngineView = engineView;
        lastEngineCompare = compare;
    };
    auto collect = [&] {
        if (!inFlight) return;
        inFlight = false;
        const auto w0 = Clock::now();
        const RenderResult& r = worker->wait(display);
        waited += ms(w0, Clock::now());
        model.stats = r.stats;
        model.refused = r.refused;
        sides.leftStats = r.stats;
        sides.rightStats = r.rightStats;
        if (r.compared) sides.diff = r.diff;
        recordEngineTimes(r, lastTimes);
        ++rendererLog.engineFrames;
    };
    if (plan.engine) submit();
    // Wait for this frame's engine picture before drawing when serial, when the one in hand is
    // stale (none yet, or the engine sat out the last frame), or side by side.
    const bool early = plan.engine && (!ui.pipelined || !engineFresh || plan.sideBySide);
    bool twinDrew = false;
    auto drawTwin = [&] {
        twinDrew = renderTwin(*this);
        if (!twinDrew) return;
        lastTimes.twin = twin.ms;
        lastTimes.twinUpload = twin.stats.uploadMs;
        lastTimes.twinDraw = twin.stats.drawMs;
        lastTimes.twinReadback = twin.stats.readbackMs;
    };
    if (plan.twin && ui.pipelined) drawTwin();
    if (early) collect();
    if (plan.twin && !ui.pipelined) drawTwin();
    if (plan.twin && !twinDrew && !plan.engine) {
        submit();  // the twin failed (and said why): the engine's picture of this state instead
        collect();
    }
    engineFresh = plan.engine || (plan.twin && !twinDrew) || skipEngine;
    const auto tCompose = Clock::now();
    if (twinDrew && plan.sideBySide) {
        shown = &composeSideBySide(*this);
        lastTimes.compare = ms(tCompose, Clock::now());
    } else {
        shown = twinDrew ? &twin.frame : &display;
    }
    const auto tCollected = Clock::now();

    gl->upload(*shown, view);
    const auto tUpload = Clock::now();
    gl->draw(view, work.backdrop, fbWidth, fbHeight);
    // llvmpipe draws on the CPU when the commands are flushed: finishing each stage charges
    // its real cost to it instead of to the swap (the swap would wait for it anyway).
    glFinish();
    const auto tDraw = Clock::now();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    glFinish();
    const auto tUi = Clock::now();
    if (screenshotRequested || keys.screenshot) takeScreenshot(*this);
    screenshotRequested = keys.screenshot = false;
    if (last && !options.windowShot.empty()) {
        if (Status e = saveWindowShot(fbWidth, fbHeight, options.windowShot); !e) {
            std::fprintf(stderr, "facet-view: %s\n", e.error().what().c_str());
            status = 1;
        }
    }
    const auto tShot = Clock::now();
    glfwSwapBuffers(window);
    ++frameCount;
    const auto tSwap = Clock::now();
    collect();  // pipelined: the frame rendered meanwhile becomes the next one shown
    const auto tEnd = Clock::now();

    lastTimes.upload = ms(tCollected, tUpload);
    lastTimes.draw = ms(tUpload, tDraw);
    lastTimes.ui = ms(tEvents, tPanels) + ms(tDraw, tUi);
    lastTimes.uiDraw = ms(tDraw, tUi);
    lastTimes.present = ms(start, tEvents) + ms(tShot, tSwap);
    lastTimes.wait = waited;
    lastTimes.total = ms(start, tEnd) - ms(tUi, tShot);  // screenshots are not frame time
    history.push(lastTimes);
    announceAccuracy(*this);
    return status;
}

}  // namespace facet::view
