#include "egl_context.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstring>

namespace eglctx {

namespace {

GLADapiproc load_gl(const char* name) {
    return reinterpret_cast<GLADapiproc>(eglGetProcAddress(name));
}

bool has_extension(const char* list, const char* name) {
    if (!list) return false;
    const size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    }
    return false;
}

// Surfaceless needs no window system and no device node; the device platform
// is the fallback on drivers without it.
EGLDisplay open_display(std::string& why) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto get_platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    EGLint major = 0, minor = 0;
    if (get_platform_display && has_extension(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return d;
    }
    if (get_platform_display && has_extension(client, "EGL_EXT_platform_device")) {
        auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(
            eglGetProcAddress("eglQueryDevicesEXT"));
        EGLDeviceEXT devices[8];
        EGLint count = 0;
        if (query_devices && query_devices(8, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                EGLDisplay d = get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return d;
            }
        }
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, &major, &minor)) return d;
    why = "no EGL display could be initialised (is libgl1-mesa-dri installed?)";
    return EGL_NO_DISPLAY;
}

}  // namespace

std::unique_ptr<Context> Context::create(const Options& options, std::string& error) {
    std::string why;
    EGLDisplay display = open_display(why);
    if (display == EGL_NO_DISPLAY) {
        error = why;
        return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        error = "EGL cannot bind the desktop OpenGL API";
        return nullptr;
    }
    const EGLint attribs[] = {
        EGL_CONTEXT_MAJOR_VERSION, options.major,
        EGL_CONTEXT_MINOR_VERSION, options.minor,
        EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
        EGL_CONTEXT_OPENGL_DEBUG, options.debug ? EGL_TRUE : EGL_FALSE,
        EGL_NONE};
    // EGL_KHR_no_config_context + surfaceless_context: no surface at all;
    // everything renders into framebuffer objects.
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (context == EGL_NO_CONTEXT) {
        error = "EGL could not create an OpenGL " + std::to_string(options.major) + "." +
                std::to_string(options.minor) + " core context (EGL error 0x" +
                [](EGLint e) { char b[16]; std::snprintf(b, sizeof b, "%04x", e); return std::string(b); }(eglGetError()) + ")";
        return nullptr;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        error = "EGL could not make the context current without a surface";
        return nullptr;
    }
    std::unique_ptr<Context> result(new Context());
    result->display_ = display;
    result->context_ = context;
    const int version = gladLoadGLContext(&result->gl_, load_gl);
    if (version == 0) {
        error = "glad could not load OpenGL through eglGetProcAddress";
        return nullptr;
    }
    result->major_ = GLAD_VERSION_MAJOR(version);
    result->minor_ = GLAD_VERSION_MINOR(version);
    return result;
}

Context::~Context() {
    if (context_) {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
    }
}

void (*Context::get_proc(void* /*user*/, const char* name))(void) {
    return eglGetProcAddress(name);
}

}  // namespace eglctx
