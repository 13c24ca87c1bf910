// execute.cpp - execute, one way through: check and analyse the inputs
// (every refusal of the inputs happens first, before planning),
// plan the frame (pure), compile its programs, update its resources and
// constants, and run it, all inside one GL state guard (and, with KHR_debug,
// one debug group). Each step binds what it uses; none relies on what an
// earlier one left bound.
#include "constants.h"
#include "context.h"
#include "inputs.h"
#include "plan.h"
#include "program_cache.h"
#include "resources.h"
#include "runner.h"

static_assert(SSAO_MAX_KERNEL == SSAO_MAX_SAMPLES, "shader and ABI sample limits differ");
static_assert(SSAO_BLUR_MAX_TAPS == SSAO_MAX_BLUR_RADIUS, "shader and ABI blur limits differ");
static_assert(SSAO_MARCH_MAX_STEPS == SSAO_MAX_STEPS, "shader and ABI step limits differ");
static_assert(SSAO_UNITS_USED == SSAO_TEXTURE_UNITS_USED, "shader and ABI texture units differ");
static_assert(SSAO_SHADER_KERNEL_SEPARABLE == SSAO_KERNEL_SEPARABLE && SSAO_SHADER_KERNEL_SPHERE == SSAO_KERNEL_SPHERE,
              "kernel enums differ");
static_assert(SSAO_SHADER_ROTATION_NOISE == SSAO_ROTATION_NOISE_4X4 && SSAO_SHADER_ROTATION_HASH == SSAO_ROTATION_HASH &&
                  SSAO_SHADER_ROTATION_NONE == SSAO_ROTATION_NONE &&
                  SSAO_SHADER_ROTATION_GRADIENT_NOISE == SSAO_ROTATION_GRADIENT_NOISE,
              "rotation enums differ");
static_assert(SSAO_SHADER_NORMAL_WORLD == SSAO_NORMAL_SPACE_WORLD && SSAO_SHADER_PACKING_UNORM == SSAO_NORMAL_PACKING_UNORM,
              "normal enums differ");
static_assert(SSAO_SHADER_METHOD_KERNEL == SSAO_METHOD_KERNEL && SSAO_SHADER_METHOD_VISIBILITY == SSAO_METHOD_VISIBILITY,
              "method enums differ");
static_assert(SSAO_SHADER_BLUR_DEPTH_AWARE == SSAO_BLUR_DEPTH_AWARE && SSAO_SHADER_BLUR_BOX == SSAO_BLUR_BOX_4X4 &&
                  SSAO_SHADER_BLUR_GAUSSIAN == SSAO_BLUR_GAUSSIAN, "blur enums differ");

namespace ssao_impl {

namespace {

// Settings that ask something of the inputs: a normals debug view writes x,
// y and z into red, green and blue (ssao.h), so a host output needs them.
ssao_status check_settings_against_inputs(const ssao_context& ctx, const AnalysedInputs& in) {
    if (in.output_texture != 0 && writes_normals(ctx.settings) && !in.output_rgb)
        return ctx.fail(SSAO_ERROR_UNSUPPORTED_FORMAT,
                        "a normals debug view needs an output_texture with red, green and blue channels");
    return SSAO_OK;
}

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
    // Outermost: its pop comes after the guard restored the host's state.
    const ExecuteGroup debug_group(ctx);

    AnalysedInputs analysed;
    ssao_status st = check_inputs(ctx, in, analysed);  // changes no GL state
    if (st != SSAO_OK) return st;
    GlStateGuard guard(ctx.gl, ctx.caps, SSAO_UBO_FRAME, SSAO_UBO_KERNEL);
    TargetFramebuffer framebuffer(ctx);  // after the guard: detaches before the guard restores
    st = inspect_textures(ctx, in, guard, analysed);  // from here on the guard restores
    if (st == SSAO_OK) st = check_settings_against_inputs(ctx, analysed);
    if (st == SSAO_OK) st = check_host_output(ctx, analysed, framebuffer);
    if (st != SSAO_OK) return st;

    analysed.software_rasterizer = ctx.caps.software_rasterizer;
    const FramePlan plan = plan_frame(ctx.settings, analysed);
    st = compile_plan_programs(ctx, plan);  // a variant's first use compiles it
    if (st != SSAO_OK) return st;

    PlanTextures textures;
    st = update_resources(ctx, plan, analysed, guard, framebuffer, textures);
    if (st != SSAO_OK) return st;
    update_kernel(ctx, guard);
    upload_frame_block(ctx, make_frame_block(ctx.settings, analysed));

    ++ctx.executes;
    run_plan(ctx, plan, textures, framebuffer, guard);

    record_frame_info(ctx, analysed);
    ctx.last_input_target = analysed.multisample ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
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
