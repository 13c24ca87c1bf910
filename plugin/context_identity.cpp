// context_identity.cpp - the vertex array that names the creating GL context.
#include "context_identity.h"

#include "context.h"
#include "debug.h"

#include <atomic>
#include <string>

namespace ssao_impl {

namespace {

// Distinct for every context of the process, whichever thread creates it.
unsigned long long unique_number() {
    static std::atomic<unsigned long long> next{1};
    return next.fetch_add(1);
}

}  // namespace

void mark_creating_context(ssao_context& ctx) {
    const GladGLContext& gl = ctx.gl;
    // A generated name becomes a vertex array at its first bind; glIsVertexArray
    // is false before that.
    GLint host_vao = 0;
    gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &host_vao);
    gl.BindVertexArray(ctx.vao);
    gl.BindVertexArray(static_cast<GLuint>(host_vao));
    const std::string number = std::to_string(unique_number());
    ctx.output_label = std::string(kLabelOutput) + " " + number;
    if (ctx.debug.available && ctx.gl.GetObjectLabel) {
        ctx.vao_label = std::string(kLabelVertexArray) + " " + number;
        label_object(ctx, GL_VERTEX_ARRAY, ctx.vao, ctx.vao_label.c_str());
    }
}

bool on_creating_context(const ssao_context& ctx) {
    const GladGLContext& gl = ctx.gl;
    // Without a current context Mesa's dispatch answers GL_FALSE here too.
    if (ctx.vao == 0 || !gl.IsVertexArray(ctx.vao)) return false;
    // The name exists here, so reading its label raises no error. Without
    // KHR_debug (no label) the name is all there is to go on.
    return ctx.vao_label.empty() || has_label(ctx, GL_VERTEX_ARRAY, ctx.vao, ctx.vao_label.c_str());
}

ssao_status wrong_context(const ssao_context& ctx, const char* call) {
    return ctx.fail(SSAO_ERROR_WRONG_CONTEXT,
                    std::string(call) +
                        ": the GL context current on this thread is not the one this ssao_context was created on "
                        "(another context, one sharing objects with it, or none); make that one current, or create "
                        "an ssao_context on this one");
}

}  // namespace ssao_impl
