#include "other_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdexcept>

namespace testgl {

namespace {

GLADapiproc load_gl(const char* name) {
    return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

}  // namespace

OtherContext::OtherContext(Sharing sharing, int major, int minor) {
    EGLDisplay display = eglGetCurrentDisplay();
    EGLContext first = eglGetCurrentContext();
    if (display == EGL_NO_DISPLAY || first == EGL_NO_CONTEXT)
        throw std::runtime_error("OtherContext: no EGL context is current");
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, major, EGL_CONTEXT_MINOR_VERSION, minor,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE, EGL_NONE};
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR,
                                          sharing == Sharing::with_current ? first : EGL_NO_CONTEXT, attribs);
    if (context == EGL_NO_CONTEXT) throw std::runtime_error("OtherContext: eglCreateContext failed");
    display_ = display;
    first_ = first;
    context_ = context;
}

OtherContext::~OtherContext() {
    if (eglGetCurrentContext() == static_cast<EGLContext>(context_))
        eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(static_cast<EGLDisplay>(display_), static_cast<EGLContext>(context_));
}

void OtherContext::make_current() {
    if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                        static_cast<EGLContext>(context_)))
        throw std::runtime_error("OtherContext: eglMakeCurrent failed");
    if (errors_) return;
    if (gladLoadGLContext(&gl_, load_gl) == 0) throw std::runtime_error("OtherContext: glad could not load GL");
    errors_ = std::make_unique<DebugErrors>(gl_);
}

void OtherContext::make_first_current() {
    if (!eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                        static_cast<EGLContext>(first_)))
        throw std::runtime_error("OtherContext: eglMakeCurrent (first context) failed");
}

void OtherContext::release_current() {
    eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
}

const std::vector<std::string>& OtherContext::gl_errors() const {
    static const std::vector<std::string> none;
    return errors_ ? errors_->messages() : none;
}

}  // namespace testgl
