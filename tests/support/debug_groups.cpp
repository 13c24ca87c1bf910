#include "debug_groups.h"

namespace testgl {

DebugGroupLog::DebugGroupLog(GladGLContext& gl) : gl_(gl) {
    void* fn = nullptr;
    void* user = nullptr;
    gl.GetPointerv(GL_DEBUG_CALLBACK_FUNCTION, &fn);
    gl.GetPointerv(GL_DEBUG_CALLBACK_USER_PARAM, &user);
    previous_ = reinterpret_cast<GLDEBUGPROC>(fn);
    previous_user_ = user;
    gl.DebugMessageCallback(&DebugGroupLog::callback, this);
}

DebugGroupLog::~DebugGroupLog() {
    gl_.DebugMessageCallback(previous_, previous_user_);
}

void DebugGroupLog::callback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                             const GLchar* message, const void* user) {
    auto* self = static_cast<DebugGroupLog*>(const_cast<void*>(user));
    if (type == GL_DEBUG_TYPE_PUSH_GROUP || type == GL_DEBUG_TYPE_POP_GROUP)
        self->events_.push_back({type == GL_DEBUG_TYPE_PUSH_GROUP, source, message});
    if (self->previous_) self->previous_(source, type, id, severity, length, message, self->previous_user_);
}

std::string DebugGroupLog::text() const {
    std::string s;
    for (const Event& e : events_) s += (e.push ? "+" : "-") + e.name + "\n";
    return s;
}

GLint debug_group_depth(GladGLContext& gl) {
    GLint depth = 0;
    gl.GetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH, &depth);
    return depth;
}

std::string object_label(GladGLContext& gl, GLenum identifier, GLuint name) {
    char buffer[256] = {};
    GLsizei length = 0;
    gl.GetObjectLabel(identifier, name, sizeof buffer, &length, buffer);
    return std::string(buffer, static_cast<size_t>(length));
}

}  // namespace testgl
