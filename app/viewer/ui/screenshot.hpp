#pragma once
// Screenshots: the engine frame as it is (no GL involved), or the whole window read back from
// the GL back buffer before the swap (reading the front buffer after it gave black).

#include <string>

#include "facet/error.hpp"
#include "facet/framebuffer.hpp"

namespace facet::view {

/// Writes the frame as PNG.
Status saveFrameShot(const Framebuffer& frame, const std::string& path);

/// Reads the back buffer (GL_RGBA bytes, rows flipped to top-first) and writes it as PNG; call
/// after drawing and before glfwSwapBuffers.
Status saveWindowShot(int width, int height, const std::string& path);

}  // namespace facet::view
