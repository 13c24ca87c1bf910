// inputs.h - what execute learns from its ssao_inputs before anything runs:
// the enums, the projection, the host's textures (targets, formats, sizes) and
// the viewport, checked and condensed into an AnalysedInputs that the planner
// and the frame constants read. The struct is plain data (no GL), so unit
// tests can build one by hand for plan_frame.
#pragma once

#include "projection.h"

#include <ssao/ssao.h>

#include <cstdint>

struct ssao_context;

namespace ssao_impl {

class GlStateGuard;

struct DepthFormat {
    int bits = 0;  // 16, 24, 32
    bool is_float = false;
    bool has_stencil = false;
};

struct AnalysedInputs {
    ProjectionInfo proj;
    bool world_normals = false;   // normal_space == WORLD (view_matrix checked finite)
    glm::dmat4 normal_to_view{1.0};  // view_matrix's upper 3x3 for world normals, identity else
    bool signed_normals = false;  // normal_packing == SIGNED
    DepthFormat depth;
    int texture_width = 0, texture_height = 0;  // the depth (= normal) texture's level 0
    // The viewport resolved (all zero = the whole texture) and checked to lie
    // inside the input textures.
    int viewport[4] = {0, 0, 0, 0};
    uint32_t depth_texture = 0, normal_texture = 0;  // the host's inputs (checked)
    uint32_t output_texture = 0;  // the host's output texture (checked), 0 = the library's own
    bool output_rgb = false;      // the host's output texture has red, green and blue channels
    // Multisampled depth and normal (GL_TEXTURE_2D_MULTISAMPLE): the grid
    // pass and the upsample read sample `sample_index` of each pixel.
    bool multisample = false;
    int sample_index = 0;
    int samples = 0;  // the inputs' sample count (0: single-sample GL_TEXTURE_2D)
    // output_mode MULTIPLY: the final pass multiplies AO into the host's
    // output texture instead of overwriting it.
    bool multiply_output = false;
    // No normal texture: the grid pass rebuilds normals from depth.
    bool normals_from_depth = false;
    // inputs.frame_index: 0 = the fixed noise pattern, else the sampling
    // pass's rotation and jitter move with it and, below full resolution, the
    // grid's picks swap corners every other frame (variant FRAME_NOISE on
    // every pass that maps grid texels to pixels).
    uint32_t frame_index = 0;
    // Not the inputs' but the context's (GlCaps::software_rasterizer): the
    // renderer runs every instruction of a batch of pixels whose lanes are
    // all masked off, so the pass writing the output tests a copy of the
    // host's depth to skip the sky, and tested targets are cleared to the
    // sky's value rather than filled by a draw (plan.h DepthUse, SkyFill).
    bool software_rasterizer = false;
};

// Checks that need no GL state change: the enums, view matrix and projection,
// and which texture names are 2D textures. Fills every field of `out` but
// those inspect_textures fills (below). On failure returns the status with ctx.fail() called.
ssao_status check_inputs(ssao_context& ctx, const ssao_inputs& in, AnalysedInputs& out);

// Inspects the textures (binds them on the library's units to query them:
// call it inside the state guard, which also saves a D24S8/D32FS8 input's
// depth-stencil mode before it is changed to read depth). Fills depth,
// texture size, viewport, the three texture names, output_rgb, multisample,
// samples and sample_index. Leaves nothing a
// later step relies on: each binds what it uses.
ssao_status inspect_textures(ssao_context& ctx, const ssao_inputs& in, GlStateGuard& guard, AnalysedInputs& out);

}  // namespace ssao_impl
