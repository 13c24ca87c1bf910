// pass_uniforms.cpp - the per-pass uniforms. A new per-pass uniform adds a Pass
// field (plan.h) and its two lines below.
#include "pass_uniforms.h"

namespace ssao_impl {

PassUniforms find_pass_uniforms(const GladGLContext& gl, GLuint program) {
    PassUniforms u;
    u.target_origin = gl.GetUniformLocation(program, "u_target_origin");
    u.pack_depth = gl.GetUniformLocation(program, "u_pack_depth");
    u.blur_dir = gl.GetUniformLocation(program, "u_blur_dir");
    u.pass_size = gl.GetUniformLocation(program, "u_pass_size");
    u.scale = gl.GetUniformLocation(program, "u_scale");
    u.depth_aware = gl.GetUniformLocation(program, "u_depth_aware");
    u.sample_index = gl.GetUniformLocation(program, "u_sample_index");
    return u;
}

void set_pass_uniforms(const GladGLContext& gl, const PassUniforms& u, const Pass& pass) {
    gl.Uniform2i(u.target_origin, pass.rect.x, pass.rect.y);
    gl.Uniform1i(u.pack_depth, pass.pack_depth ? 1 : 0);
    gl.Uniform2i(u.blur_dir, pass.direction[0], pass.direction[1]);
    gl.Uniform2i(u.pass_size, pass.rect.width, pass.rect.height);
    gl.Uniform1i(u.scale, pass.scale);
    gl.Uniform1i(u.depth_aware, pass.depth_aware ? 1 : 0);
    gl.Uniform1i(u.sample_index, pass.sample_index);
}

}  // namespace ssao_impl
