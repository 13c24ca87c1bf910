// uniforms.h - the C++ view of the std140 blocks declared once in
// shaders/ssao_constants.h (which both C++ and GLSL read), with the std140
// offset of every member checked: a member added, moved or retyped in the
// header fails here until its offset is written down.
#pragma once

#include <cstddef>
#include <cstdint>

namespace ssao_std140 {
// std140 base alignments: vec2 8, vec4 and mat4 (four vec4 columns) 16.
struct alignas(16) mat4 { float m[16]; };
struct alignas(16) vec4 { float v[4]; };
struct alignas(8) vec2 { float v[2]; };
struct alignas(8) ivec2 { int32_t v[2]; };
}  // namespace ssao_std140

#include <ssao_constants.h>

#define SSAO_AT(block, member, offset) \
    static_assert(offsetof(block, member) == (offset), #block "::" #member " must sit at its std140 offset")
SSAO_AT(SsaoFrame, proj, 0);
SSAO_AT(SsaoFrame, inv_proj, 64);
SSAO_AT(SsaoFrame, normal_to_view, 128);
SSAO_AT(SsaoFrame, viewport_origin, 192);
SSAO_AT(SsaoFrame, viewport_size, 200);
SSAO_AT(SsaoFrame, sample_count, 208);
SSAO_AT(SsaoFrame, step_count, 212);
SSAO_AT(SsaoFrame, seed, 216);
SSAO_AT(SsaoFrame, rotation, 220);
SSAO_AT(SsaoFrame, normal_space, 224);
SSAO_AT(SsaoFrame, normal_packing, 228);
SSAO_AT(SsaoFrame, blur_radius, 232);
SSAO_AT(SsaoFrame, blur_kind, 236);
SSAO_AT(SsaoFrame, orthographic, 240);
SSAO_AT(SsaoFrame, frame_pick_swap, 244);
SSAO_AT(SsaoFrame, ndc_per_depth, 248);
SSAO_AT(SsaoFrame, sky_depth, 252);
SSAO_AT(SsaoFrame, unorm_depth_step, 256);
SSAO_AT(SsaoFrame, radius, 260);
SSAO_AT(SsaoFrame, bias, 264);
SSAO_AT(SsaoFrame, depth_step_bias, 268);
SSAO_AT(SsaoFrame, strength, 272);
SSAO_AT(SsaoFrame, power, 276);
SSAO_AT(SsaoFrame, thickness, 280);
SSAO_AT(SsaoFrame, blur_sigma, 284);
SSAO_AT(SsaoFrame, blur_depth_tolerance, 288);
SSAO_AT(SsaoFrame, fade_start, 292);
SSAO_AT(SsaoFrame, fade_end, 296);
SSAO_AT(SsaoFrame, radius_pixels, 300);
SSAO_AT(SsaoFrame, frame_rotation, 304);
SSAO_AT(SsaoFrame, frame_step_offset, 312);
SSAO_AT(SsaoFrame, max_step_texels, 316);
SSAO_AT(SsaoFrame, view_mul_z, 320);
SSAO_AT(SsaoFrame, view_mul_1, 336);
SSAO_AT(SsaoFrame, view_add_z, 352);
SSAO_AT(SsaoFrame, view_add_1, 360);
SSAO_AT(SsaoFrame, clip_w_z, 368);
SSAO_AT(SsaoFrame, clip_w_1, 372);
SSAO_AT(SsaoFrame, clip_z_z, 376);
SSAO_AT(SsaoFrame, clip_z_1, 380);
SSAO_AT(SsaoFrame, inv_det, 384);
SSAO_AT(SsaoFrame, pad1, 388);
SSAO_AT(SsaoFrame, pad2, 392);
SSAO_AT(SsaoFrame, pad3, 396);
static_assert(sizeof(SsaoFrame) == 400, "SsaoFrame: 400 bytes, the last member's end rounded up to 16");
SSAO_AT(SsaoKernel, vectors, 0);
static_assert(sizeof(SsaoKernel) == SSAO_MAX_KERNEL * 16, "SsaoKernel: one vec4 per kernel vector");
#undef SSAO_AT
