// programs.cpp - one row per pass program. A new pass with its own shader
// adds its row here (and its ProgramId in plan.h); a new per-pass uniform
// adds a Pass field (plan.h) and its two lines below.
#include "programs.h"

#include <ssao_shaders_embedded.h>

namespace ssao_impl {

namespace {

const ProgramInfo kPrograms[] = {
    {ProgramId::ao, k_ao_frag, SharedCode::common_and_sampling, "ao.frag", "ssao: ao program"},
    {ProgramId::visibility, k_visibility_frag, SharedCode::common_and_sampling, "visibility.frag",
     "ssao: visibility program"},
    {ProgramId::blur, k_blur_frag, SharedCode::common, "blur.frag", "ssao: blur program"},
    {ProgramId::downsample, k_downsample_frag, SharedCode::common_and_sampling, "downsample.frag",
     "ssao: downsample program"},
    {ProgramId::upsample, k_upsample_frag, SharedCode::common, "upsample.frag", "ssao: upsample program"},
};
static_assert(sizeof kPrograms / sizeof kPrograms[0] == static_cast<size_t>(ProgramId::count),
              "one row per ProgramId");

}  // namespace

const ProgramInfo& program_info(ProgramId id) {
    for (const ProgramInfo& p : kPrograms)
        if (p.id == id) return p;
    return kPrograms[0];  // not reached: every id has its row
}

PassUniforms find_pass_uniforms(const GladGLContext& gl, GLuint program) {
    PassUniforms u;
    u.target_origin = gl.GetUniformLocation(program, "u_target_origin");
    u.pack_depth = gl.GetUniformLocation(program, "u_pack_depth");
    u.blur_dir = gl.GetUniformLocation(program, "u_blur_dir");
    u.pass_size = gl.GetUniformLocation(program, "u_pass_size");
    u.scale = gl.GetUniformLocation(program, "u_scale");
    u.depth_aware = gl.GetUniformLocation(program, "u_depth_aware");
    return u;
}

void set_pass_uniforms(const GladGLContext& gl, const PassUniforms& u, const Pass& pass) {
    gl.Uniform2i(u.target_origin, pass.rect.x, pass.rect.y);
    gl.Uniform1i(u.pack_depth, pass.pack_depth ? 1 : 0);
    gl.Uniform2i(u.blur_dir, pass.direction[0], pass.direction[1]);
    gl.Uniform2i(u.pass_size, pass.rect.width, pass.rect.height);
    gl.Uniform1i(u.scale, pass.scale);
    gl.Uniform1i(u.depth_aware, pass.depth_aware ? 1 : 0);
}

}  // namespace ssao_impl
