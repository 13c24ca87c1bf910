// other_context.h - a second GL context for the tests of the wrong-context
// checks: an EGL core debug context (4.5 unless asked otherwise) on the display of the context current
// when it is made, sharing objects with that one or not, with its own glad
// table and KHR_debug error capture. Switching between it and the first
// context goes through eglMakeCurrent.
#pragma once

#include "gl_fixture.h"

#include <glad/gl.h>

#include <memory>

namespace testgl {

class OtherContext {
public:
    enum class Sharing { none, with_current };
    // Made while the first context is current (its display is used, and with
    // Sharing::with_current its objects are shared); that one stays current.
    explicit OtherContext(Sharing sharing, int major = 4, int minor = 5);
    ~OtherContext();
    OtherContext(const OtherContext&) = delete;
    OtherContext& operator=(const OtherContext&) = delete;

    // Makes this context current on the calling thread (and loads its table
    // and error capture the first time).
    void make_current();
    // Makes the context that was current at construction current again.
    void make_first_current();
    // Makes no context current on the calling thread.
    void release_current();

    GladGLContext& gl() { return gl_; }
    // GL errors KHR_debug reported on this context.
    const std::vector<std::string>& gl_errors() const;

private:
    void* display_ = nullptr;
    void* first_ = nullptr;
    void* context_ = nullptr;
    GladGLContext gl_{};
    std::unique_ptr<DebugErrors> errors_;
};

}  // namespace testgl
