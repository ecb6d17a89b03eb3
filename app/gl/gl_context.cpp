#include "gl_context.hpp"

#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <cstring>
#include <utility>

namespace facet {
namespace {

Error contextError(const std::string& message) {
    return Error{{"OpenGL twin", 0}, message};
}

/// The message with EGL's last error code, which names what the driver refused.
Error eglError(const std::string& message) {
    char code[40];
    std::snprintf(code, sizeof code, " (EGL error 0x%04X)", static_cast<unsigned>(eglGetError()));
    return contextError(message + code);
}

/// Whether a shared library loads. epoxy aborts the whole process when it cannot open libEGL
/// or a GL library, so both are looked for before its first call. The handle stays open:
/// epoxy opens the same library right after.
bool libraryLoads(const char* name) {
    return dlopen(name, RTLD_LAZY | RTLD_LOCAL) != nullptr;
}

/// Whether a space-separated extension list holds `name` as a whole word.
bool hasExtension(const char* list, const char* name) {
    if (list == nullptr) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p != nullptr; p = std::strstr(p + 1, name)) {
        const bool starts = p == list || p[-1] == ' ';
        const bool ends = p[n] == '\0' || p[n] == ' ';
        if (starts && ends) return true;
    }
    return false;
}

bool displayHas(EGLDisplay display, const char* name) {
    return hasExtension(eglQueryString(display, EGL_EXTENSIONS), name);
}

EGLDisplay initialize(EGLDisplay display) {
    EGLint major = 0, minor = 0;
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, &major, &minor)) return EGL_NO_DISPLAY;
    return display;
}

/// The newest core context the driver grants: 4.5 (clip control: full depth precision), else
/// 4.3, else 3.3 (the twin's GLSL level).
EGLContext createCoreContext(EGLDisplay display, EGLConfig config) {
    constexpr EGLint kVersions[][2] = {{4, 5}, {4, 3}, {3, 3}};
    for (const auto& v : kVersions) {
        const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                     v[0],
                                     EGL_CONTEXT_MINOR_VERSION,
                                     v[1],
                                     EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                     EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                     EGL_NONE};
        const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, attributes);
        if (context != EGL_NO_CONTEXT) return context;
    }
    return EGL_NO_CONTEXT;
}

std::string glString(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? text : "?";
}

}  // namespace

Result<GlContext> GlContext::createHeadless() {
    if (!libraryLoads("libEGL.so.1"))
        return contextError("libEGL.so.1 not found: install libegl1 and libegl-mesa0");
    if (!libraryLoads("libOpenGL.so.0") && !libraryLoads("libGL.so.1"))
        return contextError("no OpenGL library (libOpenGL.so.0 or libGL.so.1): install libgl1");

    GlContext result;
    std::string how = "EGL surfaceless";
    EGLDisplay display = EGL_NO_DISPLAY;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (hasExtension(client, "EGL_EXT_platform_base") &&
        hasExtension(client, "EGL_MESA_platform_surfaceless"))
        display = initialize(
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
    if (display == EGL_NO_DISPLAY) {
        how = "EGL default display";
        display = initialize(eglGetDisplay(EGL_DEFAULT_DISPLAY));
    }
    if (display == EGL_NO_DISPLAY)
        return eglError(
            "no EGL display could be initialised (are libegl-mesa0 and libgl1-mesa-dri "
            "installed?)");
    result.display_ = display;  // from here on the destructor cleans up

    if (!(epoxy_egl_version(display) >= 15 || displayHas(display, "EGL_KHR_create_context")))
        return contextError("EGL 1.5 or EGL_KHR_create_context is needed for a core context");
    if (!eglBindAPI(EGL_OPENGL_API)) return eglError("this EGL offers no desktop OpenGL");

    // Without a window there is nothing to draw to but the twin's own framebuffer object; a
    // pbuffer stands in only where the driver insists on a surface.
    const bool needSurface = !displayHas(display, "EGL_KHR_surfaceless_context");
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (needSurface || !displayHas(display, "EGL_KHR_no_config_context")) {
        const EGLint wanted[] = {EGL_SURFACE_TYPE, needSurface ? EGL_PBUFFER_BIT : EGL_DONT_CARE,
                                 EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(display, wanted, &config, 1, &count) || count < 1)
            return eglError("no EGL configuration renders desktop OpenGL");
    }
    if (needSurface) {
        how += ", pbuffer";
        const EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        result.surface_ = eglCreatePbufferSurface(display, config, size);
        if (result.surface_ == EGL_NO_SURFACE) return eglError("cannot create a pbuffer");
    }
    result.context_ = createCoreContext(display, config);
    if (result.context_ == EGL_NO_CONTEXT)
        return eglError("the driver grants no OpenGL 3.3 core context");
    if (Status st = result.makeCurrent(); !st) return st.error();
    result.description_ = glString(GL_RENDERER) + " | " + glString(GL_VERSION) + " | " + how;
    return result;
}

GlContext::GlContext(GlContext&& other) noexcept
    : display_(std::exchange(other.display_, nullptr)),
      context_(std::exchange(other.context_, nullptr)),
      surface_(std::exchange(other.surface_, nullptr)),
      description_(std::move(other.description_)) {}

GlContext& GlContext::operator=(GlContext&& other) noexcept {
    if (this != &other) {
        release();
        display_ = std::exchange(other.display_, nullptr);
        context_ = std::exchange(other.context_, nullptr);
        surface_ = std::exchange(other.surface_, nullptr);
        description_ = std::move(other.description_);
    }
    return *this;
}

GlContext::~GlContext() {
    release();
}

Status GlContext::makeCurrent() const {
    if (!eglMakeCurrent(display_, surface_, surface_, context_))
        return eglError("cannot make the OpenGL context current");
    return {};
}

void GlContext::release() {
    if (display_ == nullptr) return;
    if (context_ != nullptr) {
        if (eglGetCurrentContext() == context_)
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
    }
    if (surface_ != nullptr) eglDestroySurface(display_, surface_);
    // The display stays initialised: EGL displays are per-process singletons, eglTerminate
    // would end every context on it (other code's too), and Mesa leaks a little per terminate,
    // which LeakSanitizer reports under make test-sanitize. A later context reuses it.
    display_ = context_ = surface_ = nullptr;
}

}  // namespace facet
