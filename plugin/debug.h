// debug.h - names a debugger shows (KHR_debug: GL 4.3 or the extension).
// Each pass runs inside a debug group named after it ("ssao: grid", "ssao:
// kernel", ...: pass_table.cpp), the whole
// execute inside "ssao", and the library's GL objects carry glObjectLabel
// names "ssao: ...". Without KHR_debug none of it calls GL.
#pragma once

#include <glad/gl.h>

struct ssao_context;

namespace ssao_impl {

struct DebugState {
    bool available = false;   // KHR_debug's functions are loaded (set at creation)
    GLint max_depth = 0;      // GL_MAX_DEBUG_GROUP_STACK_DEPTH
    bool groups_on = false;   // inside an execute whose outer group was pushed
    bool objects_labelled = false;  // the framebuffer (labelled after its first bind)
};

// Labels of the library's objects (programs carry their pass-table label: pass_table.cpp).
constexpr const char* kLabelFramebuffer = "ssao: framebuffer";
constexpr const char* kLabelReadFramebuffer = "ssao: depth copy source";
constexpr const char* kLabelVertexArray = "ssao: vertex array";  // + " <n>", unique in the process
constexpr const char* kLabelSampler = "ssao: sampler";
constexpr const char* kLabelFrameBlock = "ssao: frame constants";
constexpr const char* kLabelKernelBlock = "ssao: kernel";
constexpr const char* kLabelNoise = "ssao: noise";
constexpr const char* kLabelOutput = "ssao: output";  // + " <n>", the vertex array's number
constexpr const char* kLabelTimer = "ssao: timer";
// Intermediates are "ssao: intermediate <i>" (resources.cpp).

// Finds KHR_debug on the current context (after loading GL).
void init_debug(ssao_context& ctx);

// glObjectLabel where KHR_debug is present. `name` must exist (been bound or
// created once): a name that is only generated is not an object yet.
void label_object(const ssao_context& ctx, GLenum identifier, GLuint name, const char* label);

// Whether object `name` (which must exist in the current context) carries
// exactly `label`. Without KHR_debug labels cannot be read: true.
bool has_label(const ssao_context& ctx, GLenum identifier, GLuint name, const char* label);

// The group around a whole execute: pushed only when the host's stack has
// room for it and one pass group, so the library never overflows the stack;
// popped by the destructor on every return.
class ExecuteGroup {
public:
    explicit ExecuteGroup(ssao_context& ctx);
    ~ExecuteGroup();
    ExecuteGroup(const ExecuteGroup&) = delete;
    ExecuteGroup& operator=(const ExecuteGroup&) = delete;

private:
    ssao_context& ctx_;
};

// The group around one pass, inside an ExecuteGroup that was pushed.
class PassGroup {
public:
    PassGroup(const ssao_context& ctx, const char* name);
    ~PassGroup();
    PassGroup(const PassGroup&) = delete;
    PassGroup& operator=(const PassGroup&) = delete;

private:
    const ssao_context& ctx_;
    bool pushed_ = false;
};

}  // namespace ssao_impl
