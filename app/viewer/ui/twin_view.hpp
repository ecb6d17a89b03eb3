#pragma once
// The OpenGL twin inside the viewer. It draws with the window's own context (not EGL), on the
// thread that owns it, into the twin's offscreen FBO, and reads the picture back into a
// Framebuffer like the engine's, which the viewer then shows, composes beside the engine's or
// saves. GlRenderer saves and restores the GL state it changes, so ImGui and the frame drawing
// find theirs untouched. Anything the twin cannot do is a message, never a crash: the error
// popup opens and the viewer goes back to the CPU engine.

#include <optional>
#include <string>

#include "facet/framebuffer.hpp"
#include "gl_renderer.hpp"
#include "lab/renderer.hpp"

namespace facet::view {

struct App;

/// The twin's renderer (made on first use) and its last picture and timing.
struct TwinView {
    std::optional<GlRenderer> renderer;  ///< needs the window's context current, also to die
    Framebuffer frame;                   ///< the last picture, read back
    GlStats stats;                       ///< what the last render did, with its split
    double ms = 0.0;                     ///< the whole render() call: uploads, draw, readback
    lab::Renderer lab;                   ///< your pipeline (the lab's steps), drawn in its place
    lab::Report labReport;               ///< what your pipeline's last frame did
};

/// Renders the model's scene with the model's settings into app.twin.frame: with the OpenGL
/// twin (the window's context must be current), or the lab's pipeline for the lab choices. On
/// failure: the message on stderr, in the error popup and in the run's log, the CPU engine chosen
/// again, and false.
bool renderTwin(App& app);

/// Side by side: the engine's picture (app.loop.display) left, the twin's right (for the lab's
/// choice your pipeline left and the engine right), composed into
/// app.compare.sides.shown with the Compare view's divider or difference; the numbers go to
/// app.compare.sides.diff. Returns the composed picture.
const Framebuffer& composeSideBySide(App& app);

}  // namespace facet::view
