// execute.cpp - execute: check and analyse the inputs, plan the frame, update
// the resources and constants the plan needs, and run it, all inside one GL
// state guard (and, with KHR_debug, one debug group).
#include "constants.h"
#include "context.h"
#include "inputs.h"
#include "plan.h"
#include "program_cache.h"
#include "resources.h"
#include "runner.h"

static_assert(SSAO_MAX_KERNEL == SSAO_MAX_SAMPLES, "shader and ABI sample limits differ");
static_assert(SSAO_BLUR_MAX_TAPS == SSAO_MAX_BLUR_RADIUS, "shader and ABI blur limits differ");
static_assert(SSAO_UNITS_USED == SSAO_TEXTURE_UNITS_USED, "shader and ABI texture units differ");
static_assert(SSAO_SHADER_KERNEL_SEPARABLE == SSAO_KERNEL_SEPARABLE && SSAO_SHADER_KERNEL_SPHERE == SSAO_KERNEL_SPHERE,
              "kernel enums differ");
static_assert(SSAO_SHADER_ROTATION_NOISE == SSAO_ROTATION_NOISE_4X4 && SSAO_SHADER_ROTATION_HASH == SSAO_ROTATION_HASH &&
                  SSAO_SHADER_ROTATION_NONE == SSAO_ROTATION_NONE, "rotation enums differ");
static_assert(SSAO_SHADER_NORMAL_WORLD == SSAO_NORMAL_SPACE_WORLD && SSAO_SHADER_PACKING_UNORM == SSAO_NORMAL_PACKING_UNORM,
              "normal enums differ");
static_assert(SSAO_SHADER_METHOD_KERNEL == SSAO_METHOD_KERNEL && SSAO_SHADER_METHOD_VISIBILITY == SSAO_METHOD_VISIBILITY,
              "method enums differ");
static_assert(SSAO_SHADER_BLUR_DEPTH_AWARE == SSAO_BLUR_DEPTH_AWARE && SSAO_SHADER_BLUR_BOX == SSAO_BLUR_BOX_4X4 &&
                  SSAO_SHADER_BLUR_GAUSSIAN == SSAO_BLUR_GAUSSIAN, "blur enums differ");

namespace ssao_impl {

namespace {

// Leaves the plugin's framebuffer without an attachment on every way out of
// execute, so it never keeps a host texture alive (declared after the state
// guard, so it runs first, while the plugin's framebuffer is still bound).
struct DetachOnExit {
    const GladGLContext& gl;
    GLuint fbo;
    ~DetachOnExit() {
        gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 0, 0);
    }
};

void record_frame_info(ssao_context& ctx, const AnalysedInputs& in) {
    const ProjectionInfo& proj = in.proj;
    ctx.info.size = sizeof(ssao_frame_info);
    ctx.info.orthographic = proj.orthographic;
    ctx.info.reverse_z = proj.reverse_z;
    ctx.info.infinite_far = proj.infinite_far;
    ctx.info.depth_bits = static_cast<uint32_t>(in.depth.bits);
    ctx.info.near_distance = static_cast<float>(proj.near_distance);
    ctx.info.far_distance = static_cast<float>(proj.far_distance);
}

}  // namespace

ssao_status execute(ssao_context& ctx, const ssao_inputs& in, ssao_output* out) {
    const GladGLContext& gl = ctx.gl;
    // Outermost: its pop comes after the guard restored the host's state.
    const ExecuteGroup debug_group(ctx);

    AnalysedInputs analysed;
    ssao_status st = check_inputs(ctx, in, analysed);  // changes no GL state
    if (st != SSAO_OK) return st;

    GlStateGuard guard(gl, ctx.caps, SSAO_UBO_FRAME, SSAO_UBO_KERNEL);
    const DetachOnExit detach{gl, ctx.fbo};
    st = inspect_textures(ctx, in, guard, analysed);  // binds: from here on the guard restores
    if (st != SSAO_OK) return st;

    const FramePlan plan = plan_frame(ctx.settings, analysed);
    st = compile_plan_programs(ctx, plan);  // a variant's first use compiles it
    if (st != SSAO_OK) return st;

    // Resources: (re)allocate only on change; only then are the unpack state
    // and our framebuffer's completeness looked at. An output the host
    // deleted is a change.
    forget_deleted_output(ctx);
    if (ctx.kernel_dirty || resources_stale(ctx, plan)) {
        guard.save_unpack_state();
        reset_unpack(gl);
    }
    PlanTextures textures;
    st = update_resources(ctx, plan, analysed, textures);
    if (st != SSAO_OK) return st;
    if (ctx.kernel_dirty) upload_kernel(ctx);
    upload_frame_block(ctx, make_frame_block(ctx.settings, analysed));

    run_plan(ctx, plan, textures);

    record_frame_info(ctx, analysed);
    if (out) {
        out->texture = textures.output;
        out->origin[0] = plan.output_origin[0];
        out->origin[1] = plan.output_origin[1];
        out->passes_run = plan.passes_run();
    }
    ctx.last_error.clear();
    return SSAO_OK;
}

}  // namespace ssao_impl
