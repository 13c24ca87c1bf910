// msaa_copy.h - multisampled G-buffers for the MSAA tests: copies
// single-sample depth and normal textures into GL_TEXTURE_2D_MULTISAMPLE ones
// by drawing a fullscreen triangle into a multisampled framebuffer. The
// fragment shader runs once per pixel (it reads no per-sample input) and
// writes gl_FragDepth and the normal, so every covered sample gets the same,
// exactly copied value: D16/D24 depths round-trip through float exactly
// (k / (2^n - 1) is representable and rounds back to k), D32F and RGBA16F bit
// for bit. With one source per sample, the sample mask limits each draw to
// sample s, so sample s holds source s (the sample_index tests).
// Header-only so that test targets use it without a library of their own.
#pragma once

#include "gl_fixture.h"

#include <glad/gl.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace msaa {

using Textures = testgl::Textures;

namespace detail {

inline GLuint compile(GladGLContext& gl, GLenum type, const char* src) {
    const GLuint sh = gl.CreateShader(type);
    gl.ShaderSource(sh, 1, &src, nullptr);
    gl.CompileShader(sh);
    GLint ok = 0;
    gl.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        gl.GetShaderInfoLog(sh, sizeof log, nullptr, log);
        throw std::runtime_error(std::string("msaa copy shader: ") + log);
    }
    return sh;
}

inline GLuint copy_program(GladGLContext& gl) {
    const char* vs = R"(#version 330 core
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
})";
    const char* fs = R"(#version 330 core
uniform sampler2D u_depth;
uniform sampler2D u_normal;
out vec4 o_normal;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    gl_FragDepth = texelFetch(u_depth, p, 0).r;
    o_normal = texelFetch(u_normal, p, 0);
})";
    const GLuint v = compile(gl, GL_VERTEX_SHADER, vs), f = compile(gl, GL_FRAGMENT_SHADER, fs);
    const GLuint prog = gl.CreateProgram();
    gl.AttachShader(prog, v);
    gl.AttachShader(prog, f);
    gl.LinkProgram(prog);
    gl.DeleteShader(v);
    gl.DeleteShader(f);
    gl.UseProgram(prog);
    gl.Uniform1i(gl.GetUniformLocation(prog, "u_depth"), 0);
    gl.Uniform1i(gl.GetUniformLocation(prog, "u_normal"), 1);
    return prog;
}

}  // namespace detail

// Multisampled textures of `samples` samples whose sample s holds sources[s]
// (or sources[0] for every sample when one source is given). Sources are
// single-sample GL_TEXTURE_2D depth and normal textures of w x h. The GL state
// the copy changes is left at GL's defaults (program 0, framebuffer 0, ...).
inline Textures make(GladGLContext& gl, const std::vector<Textures>& sources, int w, int h, int samples,
                     GLenum depth_format, GLenum normal_format) {
    Textures out;
    gl.GenTextures(1, &out.depth);
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, out.depth);
    gl.TexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, depth_format, w, h, GL_TRUE);
    gl.GenTextures(1, &out.normal);
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, out.normal);
    gl.TexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, normal_format, w, h, GL_TRUE);
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);

    GLuint fbo = 0, vao = 0;
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    const bool stencil = depth_format == GL_DEPTH24_STENCIL8 || depth_format == GL_DEPTH32F_STENCIL8;
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, stencil ? GL_DEPTH_STENCIL_ATTACHMENT : GL_DEPTH_ATTACHMENT,
                            GL_TEXTURE_2D_MULTISAMPLE, out.depth, 0);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, out.normal, 0);
    if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("msaa copy: the multisampled framebuffer is incomplete");
    const GLuint prog = detail::copy_program(gl);
    // The sources may have no mipmaps and the default minifying filter
    // (incomplete for sampling): a sampler of their own makes them complete.
    GLuint sampler = 0;
    gl.GenSamplers(1, &sampler);
    gl.SamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.SamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.SamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    gl.BindSampler(0, sampler);
    gl.BindSampler(1, sampler);
    gl.GenVertexArrays(1, &vao);
    gl.BindVertexArray(vao);
    gl.Viewport(0, 0, w, h);
    gl.Enable(GL_DEPTH_TEST);  // depth writes need the test on
    gl.DepthFunc(GL_ALWAYS);
    gl.DepthMask(GL_TRUE);
    const bool per_sample = sources.size() > 1;
    if (per_sample) gl.Enable(GL_SAMPLE_MASK);
    const size_t draws = per_sample ? static_cast<size_t>(samples) : 1u;
    for (size_t s = 0; s < draws; ++s) {
        const Textures& src = sources[per_sample ? s % sources.size() : 0];
        if (per_sample) gl.SampleMaski(0, 1u << s);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_2D, src.depth);
        gl.ActiveTexture(GL_TEXTURE1);
        gl.BindTexture(GL_TEXTURE_2D, src.normal);
        gl.DrawArrays(GL_TRIANGLES, 0, 3);
    }
    gl.Finish();
    if (per_sample) {
        gl.SampleMaski(0, ~0u);
        gl.Disable(GL_SAMPLE_MASK);
    }
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.DepthFunc(GL_LESS);
    gl.Disable(GL_DEPTH_TEST);
    gl.BindVertexArray(0);
    gl.DeleteVertexArrays(1, &vao);
    gl.BindSampler(0, 0);
    gl.BindSampler(1, 0);
    gl.DeleteSamplers(1, &sampler);
    gl.UseProgram(0);
    gl.DeleteProgram(prog);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.DeleteFramebuffers(1, &fbo);
    return out;
}

}  // namespace msaa
