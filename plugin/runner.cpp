// runner.cpp - the loop over a plan's passes.
#include "runner.h"

#include "context.h"
#include "debug.h"
#include "pass_table.h"
#include "program_cache.h"
#include "timers.h"

namespace ssao_impl {

namespace {

// What each of the library's texture units holds on its two targets
// (GL_TEXTURE_2D and, for multisampled inputs, GL_TEXTURE_2D_MULTISAMPLE), so
// a pass binds only what changes. Every unit starts unknown: whatever the
// host or an earlier step left there. A program samples a unit through one
// sampler type, so a texture left on the unit's other target is never read.
class UnitBindings {
public:
    explicit UnitBindings(const GladGLContext& gl) : gl_(gl) {}

    // Binds the pass's inputs, each on its target; a unit whose 2D target it
    // does not sample keeps its texture there unless that is unknown or the
    // pass's own target (never sample what we render into), which is
    // unbound. The multisample target only ever holds the host's inputs,
    // which are never rendered into, so it is left as it is when unused.
    void bind_for(const Pass& pass, const PlanTextures& t) {
        const GLuint target = t.resolve(pass.target);
        const GLuint target2 = t.resolve(pass.target2);  // 0 when none: never a texture a unit holds known
        for (GLuint u = 0; u < SSAO_UNITS_USED; ++u) {
            const bool sampled = pass.inputs[u].source != TexRef::Source::none;
            const bool sampled_2d = sampled && t.target_of(pass.inputs[u]) == GL_TEXTURE_2D;
            if (sampled && !sampled_2d) bind(u, kMs, t.resolve(pass.inputs[u]));
            const GLuint want = sampled_2d ? t.resolve(pass.inputs[u]) : 0;
            const bool renders_into = texture_[u][k2d] == target || (target2 != 0 && texture_[u][k2d] == target2);
            if (sampled_2d || !known_[u][k2d] || renders_into) bind(u, k2d, want);
        }
    }

private:
    static constexpr int k2d = 0, kMs = 1;
    static int slot(GLenum target) { return target == GL_TEXTURE_2D_MULTISAMPLE ? kMs : k2d; }
    void set_known(GLuint unit, int k, GLuint texture) {
        known_[unit][k] = true;
        texture_[unit][k] = texture;
    }
    void bind(GLuint unit, int k, GLuint texture) {
        if (known_[unit][k] && texture_[unit][k] == texture) return;
        gl_.ActiveTexture(GL_TEXTURE0 + unit);
        gl_.BindTexture(k == kMs ? GLenum(GL_TEXTURE_2D_MULTISAMPLE) : GLenum(GL_TEXTURE_2D), texture);
        set_known(unit, k, texture);
    }

    const GladGLContext& gl_;
    bool known_[SSAO_UNITS_USED][2] = {};
    GLuint texture_[SSAO_UNITS_USED][2] = {};
};

// Strength 0: the pass's rectangle of its target cleared to 1 (scissored:
// the rest of a host's output texture is kept).
void clear_to_one(const GladGLContext& gl, const Pass& pass) {
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(pass.rect.x, pass.rect.y, pass.rect.width, pass.rect.height);
    const GLfloat one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    gl.ClearBufferfv(GL_COLOR, 0, one);
    gl.Disable(GL_SCISSOR_TEST);
}

void draw(const ssao_context& ctx, const Pass& pass) {
    const GladGLContext& gl = ctx.gl;
    const CompiledProgram& program = program_for(ctx, pass);
    gl.Viewport(pass.rect.x, pass.rect.y, pass.rect.width, pass.rect.height);
    gl.UseProgram(program.program);
    set_pass_uniforms(gl, program.uniforms, pass);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

}  // namespace

void run_plan(ssao_context& ctx, const FramePlan& plan, const PlanTextures& textures, TargetFramebuffer& framebuffer) {
    const GladGLContext& gl = ctx.gl;
    for (GLuint u = 0; u < SSAO_UNITS_USED; ++u) gl.BindSampler(u, ctx.sampler);
    set_pass_state(gl, ctx.caps);
    gl.BindVertexArray(ctx.vao);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, SSAO_UBO_FRAME, ctx.ubo_frame);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, SSAO_UBO_KERNEL, ctx.ubo_kernel);

    UnitBindings units(gl);
    const int slot = begin_timed_frame(ctx, plan);
    for (int i = 0; i < plan.pass_count; ++i) {
        const Pass& pass = plan.passes[i];
        {
            const PassGroup group(ctx, pass_info(pass.kind).debug_group);
            framebuffer.attach(textures.resolve(pass.target), textures.resolve(pass.target2));
            if (program_of(pass.kind) == ProgramId::none) {
                clear_to_one(gl, pass);
            } else {
                units.bind_for(pass, textures);
                if (pass.multiply) begin_multiply_blend(gl, ctx.caps);
                draw(ctx, pass);
                if (pass.multiply) end_multiply_blend(gl);
            }
        }
        stamp_pass(ctx, slot, i);
    }
    end_timed_frame(ctx, slot);
}

}  // namespace ssao_impl
