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
    SsaoFrame frame{};
    set_mat4(frame.u_proj, proj.proj);
    set_mat4(frame.u_inv_proj, proj.inverse);
    set_mat4(frame.u_normal_to_view, in.normal_to_view);
    frame.u_viewport = {{in.viewport[0], in.viewport[1], in.viewport[2], in.viewport[3]}};
    frame.u_method = {{static_cast<int32_t>(s.method), static_cast<int32_t>(s.step_count), 0, 0}};
    frame.u_march = {{s.thickness, 0.0f, 0.0f, 0.0f}};
    frame.u_modes = {{static_cast<int32_t>(s.kernel_shape), static_cast<int32_t>(s.rotation),
                      in.world_normals ? 2 : 1, in.signed_normals ? 2 : 1}};
    frame.u_counts = {{static_cast<int32_t>(s.sample_count), static_cast<int32_t>(s.seed),
                       static_cast<int32_t>(s.blur_radius), static_cast<int32_t>(s.blur)}};
    frame.u_ao = {{s.radius, s.bias, s.depth_step_bias, effective_strength(s)}};
    frame.u_ao2 = {{s.power, s.blur_sigma, s.blur_depth_tolerance, static_cast<float>(proj.ndc_per_depth)}};
    const DepthFormat& fmt = in.depth;
    const float unorm_step = fmt.is_float ? 0.0f : static_cast<float>(1.0 / (std::ldexp(1.0, fmt.bits) - 1.0));
    frame.u_depth = {{proj.sky_depth, unorm_step, proj.reverse_z ? 1.0f : 0.0f, proj.orthographic ? 1.0f : 0.0f}};
    // Read only by the variants the plan sets for them (FADE, RADIUS_PIXELS,
    // FRAME_NOISE); zero otherwise, so the block of a frame without them does
    // not change from frame to frame.
    frame.u_fade = {{s.fade_start, s.fade_end, s.radius_pixels, 0.0f}};
    const ViewFromZ vz = view_from_z(proj, in.viewport[2], in.viewport[3]);
    frame.u_vz_mul_z = {{static_cast<float>(vz.mul_z[0][0]), static_cast<float>(vz.mul_z[0][1]),
                         static_cast<float>(vz.mul_z[1][0]), static_cast<float>(vz.mul_z[1][1])}};
    frame.u_vz_mul_1 = {{static_cast<float>(vz.mul_1[0][0]), static_cast<float>(vz.mul_1[0][1]),
                         static_cast<float>(vz.mul_1[1][0]), static_cast<float>(vz.mul_1[1][1])}};
    frame.u_vz_add = {{static_cast<float>(vz.add_z.x), static_cast<float>(vz.add_z.y), static_cast<float>(vz.add_1.x),
                       static_cast<float>(vz.add_1.y)}};
    frame.u_z_clip = {{static_cast<float>(vz.w_z), static_cast<float>(vz.w_1), static_cast<float>(vz.z_z),
                       static_cast<float>(vz.z_1)}};
    // Clip z with view x or y terms (an oblique near plane): view z is not a
    // function of the depth alone, the upsample reads it through the inverse.
    const bool oblique = proj.proj[0][2] != 0.0 || proj.proj[1][2] != 0.0;
    frame.u_z_det = {{static_cast<float>(1.0 / std::abs(vz.det)), oblique ? 1.0f : 0.0f, 0.0f, 0.0f}};
    if (in.frame_index != 0) {
        const glm::dvec2 off = frame_noise_offsets(in.frame_index);
        const double turn = off.x * 6.283185307179586;
        frame.u_frame = {{static_cast<float>(std::cos(turn)), static_cast<float>(std::sin(turn)),
                          static_cast<float>(off.y), 0.0f}};
    }
    return frame;
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
        block.u_kernel[i] = {{kernel[i].x, kernel[i].y, kernel[i].z, 0.0f}};
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
