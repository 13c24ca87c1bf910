// constants.cpp - the frame and kernel uniform blocks.
#include "constants.h"

#include "context.h"
#include "kernel.h"
#include "resources.h"
#include "settings.h"

#include <cmath>
#include <cstring>
#include <vector>

namespace ssao_impl {

namespace {

void set_mat4(ssao_std140::mat4& dst, const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) dst.m[c * 4 + r] = static_cast<float>(m[c][r]);
}

}  // namespace

SsaoFrame make_frame_block(const ssao_settings& s, const AnalysedInputs& in) {
    const ProjectionInfo& proj = in.proj;
    SsaoFrame c{};  // value-initialised: the padding is zero, so equal blocks compare equal bytewise
    set_mat4(c.proj, proj.proj);
    set_mat4(c.inv_proj, proj.inverse);
    set_mat4(c.normal_to_view, in.normal_to_view);
    c.viewport_origin = {{in.viewport[0], in.viewport[1]}};
    c.viewport_size = {{in.viewport[2], in.viewport[3]}};
    c.sample_count = static_cast<int32_t>(s.sample_count);
    c.step_count = static_cast<int32_t>(s.step_count);
    c.seed = static_cast<int32_t>(s.seed);
    c.rotation = static_cast<int32_t>(s.rotation);
    c.normal_space = in.world_normals ? SSAO_SHADER_NORMAL_WORLD : SSAO_SHADER_NORMAL_VIEW;
    c.normal_packing = in.signed_normals ? SSAO_SHADER_PACKING_SIGNED : SSAO_SHADER_PACKING_UNORM;
    c.blur_radius = static_cast<int32_t>(s.blur_radius);
    c.blur_kind = static_cast<int32_t>(s.blur);
    c.orthographic = proj.orthographic ? 1 : 0;
    c.ndc_per_depth = static_cast<float>(proj.ndc_per_depth);
    c.sky_depth = proj.sky_depth;
    const DepthFormat& fmt = in.depth;
    c.unorm_depth_step = fmt.is_float ? 0.0f : static_cast<float>(1.0 / (std::ldexp(1.0, fmt.bits) - 1.0));
    c.radius = s.radius;
    c.bias = s.bias;
    c.depth_step_bias = s.depth_step_bias;
    c.strength = effective_strength(s);
    c.power = s.power;
    c.thickness = s.thickness;
    c.blur_sigma = s.blur_sigma;
    c.blur_depth_tolerance = s.blur_depth_tolerance;
    c.fade_start = s.fade_start;
    c.fade_end = s.fade_end;
    c.radius_pixels = s.radius_pixels;
    c.max_step_texels = s.max_step_texels;
    if (in.frame_index != 0) {
        const glm::dvec2 off = frame_noise_offsets(in.frame_index);
        const double turn = off.x * 6.283185307179586;
        c.frame_rotation = {{static_cast<float>(std::cos(turn)), static_cast<float>(std::sin(turn))}};
        c.frame_step_offset = static_cast<float>(off.y);
        // Below full resolution the picked pixel of each block swaps to the
        // other diagonal corner every other frame, so that a host averaging
        // frames sees both (common.glsl grid_pixel).
        c.frame_pick_swap = static_cast<int32_t>(in.frame_index & 1u);
    }
    const ViewFromZ vz = view_from_z(proj, in.viewport[2], in.viewport[3]);
    c.view_mul_z = {{static_cast<float>(vz.mul_z[0][0]), static_cast<float>(vz.mul_z[0][1]),
                     static_cast<float>(vz.mul_z[1][0]), static_cast<float>(vz.mul_z[1][1])}};
    c.view_mul_1 = {{static_cast<float>(vz.mul_1[0][0]), static_cast<float>(vz.mul_1[0][1]),
                     static_cast<float>(vz.mul_1[1][0]), static_cast<float>(vz.mul_1[1][1])}};
    c.view_add_z = {{static_cast<float>(vz.add_z.x), static_cast<float>(vz.add_z.y)}};
    c.view_add_1 = {{static_cast<float>(vz.add_1.x), static_cast<float>(vz.add_1.y)}};
    c.clip_w_z = static_cast<float>(vz.w_z);
    c.clip_w_1 = static_cast<float>(vz.w_1);
    c.clip_z_z = static_cast<float>(vz.z_z);
    c.clip_z_1 = static_cast<float>(vz.z_1);
    c.inv_det = static_cast<float>(1.0 / std::abs(vz.det));
    return c;
}

void upload_frame_block(ssao_context& ctx, const SsaoFrame& frame) {
    const GladGLContext& gl = ctx.gl;
    // A static camera and settings upload nothing: the block changes only
    // when the projection, viewport, inputs' encoding or settings do.
    if (!ctx.frame_uploaded || std::memcmp(&frame, &ctx.last_frame, sizeof frame) != 0) {
        gl.BindBuffer(GL_UNIFORM_BUFFER, ctx.ubo_frame);
        gl.BufferData(GL_UNIFORM_BUFFER, sizeof frame, &frame, GL_DYNAMIC_DRAW);
        if (!ctx.frame_uploaded) label_object(ctx, GL_BUFFER, ctx.ubo_frame, kLabelFrameBlock);
        ctx.last_frame = frame;
        ctx.frame_uploaded = true;
    }
}

KernelKey kernel_key(const ssao_settings& s) {
    return KernelKey{s.sample_count, static_cast<uint32_t>(s.kernel_shape), static_cast<uint32_t>(s.distribution),
                     s.seed, static_cast<uint32_t>(s.method)};
}

void update_kernel(ssao_context& ctx, GlStateGuard& guard) {
    const KernelKey key = kernel_key(ctx.settings);
    if (ctx.kernel_uploaded && key == ctx.kernel_uploaded_for) return;
    const GladGLContext& gl = ctx.gl;
    use_default_unpack(gl, guard);
    SsaoKernel block{};
    // The kernel estimator reads sample points, the visibility estimator directions.
    const std::vector<glm::vec3> kernel = ctx.settings.method == SSAO_METHOD_VISIBILITY
                                              ? make_directions(ctx.settings)
                                              : make_kernel(ctx.settings);
    for (size_t i = 0; i < kernel.size(); ++i) {
        block.vectors[i] = {{kernel[i].x, kernel[i].y, kernel[i].z, 0.0f}};
    }
    gl.BindBuffer(GL_UNIFORM_BUFFER, ctx.ubo_kernel);
    gl.BufferData(GL_UNIFORM_BUFFER, sizeof block, &block, GL_STATIC_DRAW);
    label_object(ctx, GL_BUFFER, ctx.ubo_kernel, kLabelKernelBlock);

    const std::vector<glm::vec2> noise = make_noise(ctx.settings.seed);
    gl.ActiveTexture(GL_TEXTURE0 + SSAO_UNIT_NOISE);
    gl.BindTexture(GL_TEXTURE_2D, ctx.noise_texture);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, SSAO_NOISE_SIZE, SSAO_NOISE_SIZE, 0, GL_RG, GL_FLOAT, noise.data());
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    label_object(ctx, GL_TEXTURE, ctx.noise_texture, kLabelNoise);
    ctx.kernel_uploaded_for = key;
    ctx.kernel_uploaded = true;
}

}  // namespace ssao_impl
