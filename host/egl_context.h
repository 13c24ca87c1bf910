// egl_context.h - a headless OpenGL context on EGL (Mesa's surfaceless
// platform, else the device platform, else the default display), with a glad
// function table for the caller. Used by ssao-host, the tools and the tests.
#pragma once

#include <glad/gl.h>

#include <memory>
#include <string>

namespace eglctx {

struct Options {
    int major = 4;             // 4.5 core by default; 3.3 core on request
    int minor = 5;
    bool debug = false;        // a debug context (KHR_debug messages)
};

class Context {
public:
    // Returns nullptr and sets `error` when no context can be made.
    static std::unique_ptr<Context> create(const Options& options, std::string& error);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    GladGLContext& gl() { return gl_; }
    int major() const { return major_; }
    int minor() const { return minor_; }
    // The proc-address function in the shape ssao_context_desc wants.
    static void (*get_proc(void* user, const char* name))(void);

private:
    Context() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
    GladGLContext gl_{};
    int major_ = 0, minor_ = 0;
};

}  // namespace eglctx
