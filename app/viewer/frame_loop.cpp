// One frame of the viewer. Pipelined (the default), the engine renders the state the panels
// just produced on its own thread while this thread uploads, draws and swaps the previous
// engine frame; serial (--serial, or the Stats checkbox), it waits for the engine first. Both
// show a change in the very next frame drawn after the one in which it was made.

#include <epoxy/gl.h>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdio>

#include "panels.hpp"
#include "screenshot.hpp"
#include "viewer_app.hpp"

namespace facet::view {
int App::frame(Clock::time_point start, bool last) {
    int status = 0;
    const auto tEvents = Clock::now();
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    // The frame's size and place first: input maps mouse pixels through them.
    const Camera& camera = model.prepareFrame(fbWidth, fbHeight);
    view = letterbox(camera.width, camera.height, fbWidth, fbHeight);
    handleInput(*this);
    drawPanels(*this);
    if (ui.vsync != vsyncApplied) {
        vsyncApplied = ui.vsync;
        glfwSwapInterval(vsyncApplied ? 1 : 0);
    }
    const Camera& final = model.prepareFrame(fbWidth, fbHeight);  // after the panels' edits
    view = letterbox(final.width, final.height, fbWidth, fbHeight);
    const auto tPanels = Clock::now();

    worker->submit(model.scene, model.sceneVersion, model.settings, compare);
    // Serial, or nothing to show yet: wait for this frame's render before drawing.
    const bool early = !ui.pipelined || display.width == 0;
    double waited = 0.0;
    auto collect = [&] {
        const auto w0 = Clock::now();
        const RenderResult& r = worker->wait(display);
        waited += ms(w0, Clock::now());
        model.stats = r.stats;
        compare.leftStats = r.stats;
        compare.rightStats = r.rightStats;
        compare.diff = r.diff;
        lastTimes.render = r.renderMs;
        lastTimes.compare = r.compareMs;
    };
    if (early) collect();
    shown = &display;
    const auto tCollected = Clock::now();

    gl->upload(display);
    const auto tUpload = Clock::now();
    gl->draw(view, fbWidth, fbHeight);
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
        if (Status e = saveWindowShot(fbWidth, fbHeight, options.windowShot)) {
            std::fprintf(stderr, "facet-view: %s\n", e->what().c_str());
            status = 1;
        }
    }
    const auto tShot = Clock::now();
    glfwSwapBuffers(window);
    ++frameCount;
    const auto tSwap = Clock::now();
    if (!early) collect();  // the frame rendered meanwhile becomes the next one shown
    const auto tEnd = Clock::now();

    lastTimes.upload = ms(tCollected, tUpload);
    lastTimes.draw = ms(tUpload, tDraw);
    lastTimes.ui = ms(tEvents, tPanels) + ms(tDraw, tUi);
    lastTimes.present = ms(start, tEvents) + ms(tShot, tSwap);
    lastTimes.wait = waited;
    lastTimes.total = ms(start, tEnd) - ms(tUi, tShot);  // screenshots are not frame time
    history.push(lastTimes);
    return status;
}

}  // namespace facet::view
