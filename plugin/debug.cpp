// debug.cpp - KHR_debug groups and object labels.
#include "debug.h"

#include "context.h"
#include "plan.h"

#include <cstring>

namespace ssao_impl {

namespace {

// Groups use id 0: the name says what the pass is.
constexpr GLuint kGroupId = 0;

void push(const ssao_context& ctx, const char* name) {
    ctx.gl.PushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, kGroupId, -1, name);
}

}  // namespace

void init_debug(ssao_context& ctx) {
    const GladGLContext& gl = ctx.gl;
    const int v = ctx.caps.major * 10 + ctx.caps.minor;
    ctx.debug.available = (v >= 43 || gl.KHR_debug) && gl.PushDebugGroup && gl.PopDebugGroup && gl.ObjectLabel;
    if (ctx.debug.available) gl.GetIntegerv(GL_MAX_DEBUG_GROUP_STACK_DEPTH, &ctx.debug.max_depth);
}

void label_object(const ssao_context& ctx, GLenum identifier, GLuint name, const char* label) {
    if (ctx.debug.available && name != 0) ctx.gl.ObjectLabel(identifier, name, -1, label);
}

bool has_label(const ssao_context& ctx, GLenum identifier, GLuint name, const char* label) {
    if (!ctx.debug.available || !ctx.gl.GetObjectLabel) return true;
    // One byte more than the label: a longer one is told apart, not
    // truncated into a match.
    char read[96] = {};
    const size_t want = std::strlen(label);
    if (want + 1 >= sizeof read) return false;
    GLsizei length = 0;
    ctx.gl.GetObjectLabel(identifier, name, static_cast<GLsizei>(sizeof read), &length, read);
    return static_cast<size_t>(length) == want && std::memcmp(read, label, want) == 0;
}

ExecuteGroup::ExecuteGroup(ssao_context& ctx) : ctx_(ctx) {
    ctx.debug.groups_on = false;
    if (!ctx.debug.available) return;
    GLint depth = 0;
    ctx.gl.GetIntegerv(GL_DEBUG_GROUP_STACK_DEPTH, &depth);
    // The stack holds the default group too: depth counts it, max bounds it.
    if (depth + 2 > ctx.debug.max_depth) return;
    push(ctx, kExecuteGroupName);
    ctx.debug.groups_on = true;
}

ExecuteGroup::~ExecuteGroup() {
    if (ctx_.debug.groups_on) ctx_.gl.PopDebugGroup();
    ctx_.debug.groups_on = false;
}

PassGroup::PassGroup(const ssao_context& ctx, const char* name) : ctx_(ctx) {
    if (!ctx.debug.groups_on) return;
    push(ctx, name);
    pushed_ = true;
}

PassGroup::~PassGroup() {
    if (pushed_) ctx_.gl.PopDebugGroup();
}

}  // namespace ssao_impl
