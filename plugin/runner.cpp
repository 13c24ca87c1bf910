// runner.cpp - the loop over a plan's passes.
#include "runner.h"

#include "context.h"
#include "debug.h"
#include "program_cache.h"
#include "timers.h"

namespace ssao_impl {

namespace {

// What each of the library's texture units holds on its two targets
// (GL_TEXTURE_2D and, for multisampled inputs, GL_TEXTURE_2D_MULTISAMPLE), so
// a pass binds only what changes. Unknown: whatever the host or an upload
// left there. A program samples a unit through one sampler type, so a
// texture left on the unit's other target is never read.
class UnitBindings {
public:
    UnitBindings(const GladGLContext& gl, const PlanTextures& t) : gl_(gl) {
        // inspect_textures left the host's depth and normal textures bound;
        // without a normal texture (depth-only input) it did not touch the
        // normal unit, which then holds whatever the host left: unknown.
        const int k = slot(t.input_target);
        set_known(SSAO_UNIT_DEPTH, k, t.depth);
        if (t.normal != 0) set_known(SSAO_UNIT_NORMAL, k, t.normal);
    }

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

// Attachment 1 of the library's framebuffer: `texture` written by fragment
// output 1 beside attachment 0, or (0) detached with only attachment 0 drawn.
// The draw-buffer list is the library's framebuffer's own state, not the host's.
void set_second_target(const GladGLContext& gl, GLuint texture) {
    static const GLenum one[1] = {GL_COLOR_ATTACHMENT0};
    static const GLenum two[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, texture, 0);
    gl.DrawBuffers(texture != 0 ? 2 : 1, texture != 0 ? two : one);
}

void draw(const ssao_context& ctx, const Pass& pass) {
    const GladGLContext& gl = ctx.gl;
    const CompiledProgram& program = program_for(ctx, pass);
    gl.Viewport(pass.rect.x, pass.rect.y, pass.rect.width, pass.rect.height);
    gl.UseProgram(program.program);
    set_pass_uniforms(gl, program.uniforms, pass);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

// The framebuffer exists only after its first bind: label it then (the
// vertex array was made and labelled at creation: context_identity.cpp).
void label_bound_objects(ssao_context& ctx) {
    if (ctx.debug.objects_labelled) return;
    label_object(ctx, GL_FRAMEBUFFER, ctx.fbo, kLabelFramebuffer);
    ctx.debug.objects_labelled = true;
}

}  // namespace

void run_plan(ssao_context& ctx, const FramePlan& plan, const PlanTextures& textures) {
    const GladGLContext& gl = ctx.gl;
    for (GLuint u = 0; u < SSAO_UNITS_USED; ++u) gl.BindSampler(u, ctx.sampler);
    set_pass_state(gl, ctx.caps);
    gl.BindVertexArray(ctx.vao);
    label_bound_objects(ctx);

    UnitBindings units(gl, textures);
    const int slot = begin_timed_frame(ctx, plan);
    for (int i = 0; i < plan.pass_count; ++i) {
        const Pass& pass = plan.passes[i];
        {
            const PassGroup group(ctx, pass_name(pass.kind));
            gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                                    textures.resolve(pass.target), 0);
            set_second_target(gl, textures.resolve(pass.target2));
            if (pass.program == ProgramId::none) {
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
