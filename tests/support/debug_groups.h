// debug_groups.h - records the KHR_debug group messages (push and pop) a GL
// context delivers to its debug callback, and forwards every message to the
// callback installed before (the fixture's error capture keeps working).
#pragma once

#include <glad/gl.h>

#include <string>
#include <vector>

namespace testgl {

class DebugGroupLog {
public:
    struct Event {
        bool push = true;  // false: pop
        GLenum source = 0;
        std::string name;
        bool operator==(const Event& o) const { return push == o.push && source == o.source && name == o.name; }
    };

    explicit DebugGroupLog(GladGLContext& gl);  // needs KHR_debug and GL_DEBUG_OUTPUT enabled
    ~DebugGroupLog();
    DebugGroupLog(const DebugGroupLog&) = delete;
    DebugGroupLog& operator=(const DebugGroupLog&) = delete;

    const std::vector<Event>& events() const { return events_; }
    void clear() { events_.clear(); }
    // The events as "+name" / "-name" lines, for readable failures.
    std::string text() const;

private:
    static void GLAD_API_PTR callback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                      const GLchar* message, const void* user);
    GladGLContext& gl_;
    GLDEBUGPROC previous_ = nullptr;
    const void* previous_user_ = nullptr;
    std::vector<Event> events_;
};

// The stack depth of debug groups (1 = only the default group).
GLint debug_group_depth(GladGLContext& gl);

// The label of a GL object ("" when it has none).
std::string object_label(GladGLContext& gl, GLenum identifier, GLuint name);

}  // namespace testgl
