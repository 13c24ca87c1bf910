// pass_uniforms.h - the per-pass uniforms every pass program may declare, set
// from the plan's Pass by the runner (a program's shader and label are its
// row in pass_table.cpp, its compiled variants in program_cache.cpp).
#pragma once

#include "plan.h"
#include "shader_source.h"

#include <glad/gl.h>

namespace ssao_impl {

// Locations of the per-pass uniforms in one program (-1: it does not use it;
// glUniform* ignores location -1).
struct PassUniforms {
    GLint target_origin = -1;  // u_target_origin: Pass::rect's origin
    GLint pack_depth = -1;     // u_pack_depth: Pass::pack_depth
    GLint blur_dir = -1;       // u_blur_dir: Pass::direction
    GLint pass_size = -1;      // u_pass_size: Pass::rect's size (the grid a blur walks)
    GLint scale = -1;          // u_scale: Pass::scale
    GLint depth_aware = -1;    // u_depth_aware: Pass::depth_aware
    GLint sample_index = -1;   // u_sample_index: Pass::sample_index (variant MULTISAMPLE)
};

PassUniforms find_pass_uniforms(const GladGLContext& gl, GLuint program);
// Sets them for `pass` (its program current).
void set_pass_uniforms(const GladGLContext& gl, const PassUniforms& u, const Pass& pass);

}  // namespace ssao_impl
