#include "floor_pass.h"

#include "gl_util.h"

namespace bench {

namespace {

// One texelFetch of each input and a value that depends on both, so neither
// read can be optimised away.
const char* kFs = R"(#version 330 core
uniform sampler2D u_depth;
uniform sampler2D u_normal;
out float o_value;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float d = texelFetch(u_depth, p, 0).r;
    vec3 n = texelFetch(u_normal, p, 0).xyz;
    o_value = clamp(d * 0.5 + n.z * 0.25 + 0.25, 0.0, 1.0);
})";

}  // namespace

FloorPass::FloorPass(GladGLContext& gl, int width, int height) : gl_(gl), width_(width), height_(height) {
    target_ = gl_util::make_texture(gl, GL_R8, width, height);
    gl.GenFramebuffers(1, &fbo_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target_, 0);
    gl_util::check_framebuffer(gl, "bandwidth floor target");
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    program_ = gl_util::make_program(gl, "bandwidth floor", gl_util::fullscreen_vertex_shader().c_str(), kFs);
    gl.UseProgram(program_);
    gl.Uniform1i(gl.GetUniformLocation(program_, "u_depth"), 0);
    gl.Uniform1i(gl.GetUniformLocation(program_, "u_normal"), 1);
    gl.UseProgram(0);
    gl.GenVertexArrays(1, &vao_);
    gl.GenQueries(2, queries_);
    gl_util::check(gl, "bandwidth floor setup");
}

FloorPass::~FloorPass() {
    gl_.DeleteQueries(2, queries_);
    gl_.DeleteVertexArrays(1, &vao_);
    gl_.DeleteProgram(program_);
    gl_.DeleteFramebuffers(1, &fbo_);
    gl_.DeleteTextures(1, &target_);
}

void FloorPass::run(GLuint depth_texture, GLuint normal_texture) {
    GladGLContext& gl = gl_;
    gl.QueryCounter(queries_[0], GL_TIMESTAMP);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    gl.Viewport(0, 0, width_, height_);
    gl.Disable(GL_DEPTH_TEST);
    gl.UseProgram(program_);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, depth_texture);
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, normal_texture);
    gl.BindVertexArray(vao_);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.BindVertexArray(0);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.UseProgram(0);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.QueryCounter(queries_[1], GL_TIMESTAMP);
}

double FloorPass::last_ms() {
    GLuint64 t0 = 0, t1 = 0;
    gl_.GetQueryObjectui64v(queries_[0], GL_QUERY_RESULT, &t0);
    gl_.GetQueryObjectui64v(queries_[1], GL_QUERY_RESULT, &t1);
    return static_cast<double>(t1 - t0) * 1e-6;
}

}  // namespace bench
