#pragma once
// A headless OpenGL context through EGL, for running the OpenGL twin without a window (the CLI,
// tests, benchmarks). GlRenderer does not depend on it: it draws with whatever context is
// current, so a window's context (the viewer's GLFW one) serves just as well.

#include <string>

#include "facet/error.hpp"

namespace facet {

/// An EGL display and an OpenGL core-profile context (4.5 when the driver has it, else 3.3),
/// current on the thread that created it. Move-only; releases the context when destroyed.
class GlContext {
  public:
    /// Creates a context without a window: EGL's surfaceless platform (EGL_MESA_platform_
    /// surfaceless) first, then the default display with a 1×1 pbuffer. When EGL, a GL library
    /// or a driver is missing, the Error says which and what to install; it never aborts.
    static Result<GlContext> createHeadless();

    GlContext(GlContext&& other) noexcept;
    GlContext& operator=(GlContext&& other) noexcept;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;
    /// Releases the context (the EGL display stays initialised for the next one).
    ~GlContext();

    /// Makes this context current on the calling thread.
    Status makeCurrent() const;

    /// "renderer | version | how it was created", e.g.
    /// "llvmpipe (LLVM 15.0.6, 256 bits) | 4.5 (Core Profile) Mesa 22.3.6 | EGL surfaceless".
    const std::string& description() const { return description_; }

  private:
    GlContext() = default;
    void release();

    // EGL handles as void*, which they are, so this header does not pull in EGL.
    void* display_ = nullptr;
    void* context_ = nullptr;
    void* surface_ = nullptr;  // the pbuffer of the fallback, else none
    std::string description_;
};

}  // namespace facet
