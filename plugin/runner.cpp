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

// The pass's rectangle of its colour target 0 cleared to `value`. A
// library texture is the rectangle's size and cleared whole (a software
// rasteriser clears a whole surface fastest); the host's output is scissored,
// keeping the rest of it.
void clear_rect(const GladGLContext& gl, const FramePlan& plan, const Pass& pass, const GLfloat value[4]) {
    const bool scissored = pass.target.source == TexRef::Source::output && !plan.owned_output;
    if (scissored) {
        gl.Enable(GL_SCISSOR_TEST);
        gl.Scissor(pass.rect.x, pass.rect.y, pass.rect.width, pass.rect.height);
    }
    gl.ClearBufferfv(GL_COLOR, 0, value);
    if (scissored) gl.Disable(GL_SCISSOR_TEST);
}

// SkyFill::clear: the pass's rectangle cleared to what its shader writes at
// the sky (ao_texture.glsl result(1.0, SKY_Z), or 1).
void clear_to_sky(const GladGLContext& gl, const FramePlan& plan, const Pass& pass) {
    const GLfloat packed[4] = {1.0f, static_cast<GLfloat>(SSAO_SKY_Z), 0.0f, 0.0f};
    const GLfloat one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    clear_rect(gl, plan, pass, pass.pack_depth ? packed : one);
}

// DepthUse::depth_copy: the host's depth in the viewport copied to the
// pass's rectangle of its depth attachment (attached to the bound draw
// framebuffer), through the library's read framebuffer.
void copy_host_depth(ssao_context& ctx, const FramePlan& plan, const Pass& pass, const PlanTextures& t) {
    const GladGLContext& gl = ctx.gl;
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, ctx.read_fbo);
    if (!ctx.read_fbo_ready) {
        // Below GL 4.1 a read buffer naming no attachment leaves the
        // framebuffer incomplete; it has only a depth attachment.
        gl.ReadBuffer(GL_NONE);
        label_object(ctx, GL_FRAMEBUFFER, ctx.read_fbo, kLabelReadFramebuffer);
        ctx.read_fbo_ready = true;
    }
    gl.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, t.depth, 0);
    const Rect& v = plan.viewport;
    const Rect& r = pass.rect;
    gl.BlitFramebuffer(v.x, v.y, v.x + v.width, v.y + v.height, r.x, r.y, r.x + r.width, r.y + r.height,
                       GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    // Never left holding the host's texture.
    gl.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, ctx.fbo);
}

// The depth function of a sky test: passing where the stored depth is not
// the sky's, or, for the sky fill, exactly where that test fails. Every
// fragment is at the sky's depth (set_depth_use), so the test passes below
// it when the sky is at 1 and above it when the sky is at 0 (reverse-Z). The
// grid's mask holds 1 at the sky.
GLenum sky_test_func(DepthUse use, float sky_depth, bool at_sky) {
    const bool sky_at_one = use == DepthUse::grid_mask || sky_depth == 1.0f;
    if (sky_at_one) return at_sky ? GL_LEQUAL : GL_GREATER;
    return at_sky ? GL_GEQUAL : GL_LESS;
}

// The depth state of a pass's DepthUse.
void set_depth_use(const GladGLContext& gl, DepthUse use, float sky_depth) {
    if (use == DepthUse::none) {
        gl.Disable(GL_DEPTH_TEST);
        return;
    }
    gl.Enable(GL_DEPTH_TEST);
    if (use == DepthUse::write_grid_mask) {
        // gl_FragDepth (grid.frag) is clamped to the depth range.
        gl.DepthRange(0.0, 1.0);
        gl.DepthFunc(GL_ALWAYS);
        gl.DepthMask(GL_TRUE);
        return;
    }
    // A depth range of one value puts every fragment at the sky's depth.
    const double sky = use == DepthUse::grid_mask ? 1.0 : static_cast<double>(sky_depth);
    gl.DepthRange(sky, sky);
    gl.DepthFunc(sky_test_func(use, sky_depth, false));
    gl.DepthMask(GL_FALSE);
}

void draw_with(const GladGLContext& gl, const CompiledProgram& program, const Pass& pass) {
    gl.Viewport(pass.rect.x, pass.rect.y, pass.rect.width, pass.rect.height);
    gl.UseProgram(program.program);
    set_pass_uniforms(gl, program.uniforms, pass);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

// SkyFill::draw: the sky fill drawn over the pass's rectangle where its
// depth test fails, the test set back after.
void draw_sky_fill(const ssao_context& ctx, const FramePlan& plan, const Pass& pass) {
    const GladGLContext& gl = ctx.gl;
    gl.DepthFunc(sky_test_func(pass.depth, plan.sky_depth, true));
    draw_with(gl, sky_fill_program(ctx), pass);
    gl.DepthFunc(sky_test_func(pass.depth, plan.sky_depth, false));
}

}  // namespace

void run_plan(ssao_context& ctx, const FramePlan& plan, const PlanTextures& textures, TargetFramebuffer& framebuffer,
              GlStateGuard& guard) {
    const GladGLContext& gl = ctx.gl;
    for (GLuint u = 0; u < SSAO_UNITS_USED; ++u) gl.BindSampler(u, ctx.sampler);
    set_pass_state(gl, ctx.caps);
    gl.BindVertexArray(ctx.vao);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, SSAO_UBO_FRAME, ctx.ubo_frame);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, SSAO_UBO_KERNEL, ctx.ubo_kernel);

    UnitBindings units(gl);
    bool depth_copied = false;
    const int slot = begin_timed_frame(ctx, plan);
    for (int i = 0; i < plan.pass_count; ++i) {
        const Pass& pass = plan.passes[i];
        {
            const PassGroup group(ctx, pass_info(pass.kind).debug_group);
            framebuffer.attach(textures.resolve(pass.target), textures.resolve(pass.target2),
                               textures.resolve(pass.depth_target));
            if (program_of(pass.kind) == ProgramId::none) {
                const GLfloat one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
                clear_rect(gl, plan, pass, one);
            } else {
                if (pass.depth == DepthUse::depth_copy && !depth_copied) {
                    copy_host_depth(ctx, plan, pass, textures);
                    depth_copied = true;
                }
                if (pass.fills_sky() && plan.sky_fill == SkyFill::clear) clear_to_sky(gl, plan, pass);
                set_depth_use(gl, pass.depth, plan.sky_depth);
                units.bind_for(pass, textures);
                if (pass.fills_sky() && plan.sky_fill == SkyFill::draw) draw_sky_fill(ctx, plan, pass);
                if (pass.multiply) {
                    guard.save_blend_function();
                    begin_multiply_blend(gl, ctx.caps);
                }
                draw_with(gl, program_for(ctx, pass), pass);
                if (pass.multiply) end_multiply_blend(gl);
            }
        }
        stamp_pass(ctx, slot, i);
    }
    end_timed_frame(ctx, slot);
}

}  // namespace ssao_impl
