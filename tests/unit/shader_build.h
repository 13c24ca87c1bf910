// shader_build.h - compiling and linking the plugin's assembled shaders
// (plugin/shader_source.h) in a test's GL context, the way the plugin does.
#pragma once

#include "plan.h"
#include "shader_source.h"

#include <glad/gl.h>

#include <cstdint>
#include <string>

namespace shader_build {

// Compiles `source` into `shader` (the caller deletes it): "" when it
// compiles, else "compile: " and the driver's log.
inline std::string compile_log(GladGLContext& gl, GLenum type, const std::string& source, GLuint& shader) {
    shader = gl.CreateShader(type);
    const char* src = source.c_str();
    gl.ShaderSource(shader, 1, &src, nullptr);
    gl.CompileShader(shader);
    GLint ok = 0;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok) return "";
    char log[4096] = {};
    gl.GetShaderInfoLog(shader, sizeof log, nullptr, log);
    return std::string("compile: ") + log;
}

// Links the full-screen triangle with pass program `id` in `variant` into
// `program` (the caller deletes it; 0 when a shader failed to compile): ""
// when it links, else what failed and the driver's log.
inline std::string link_pass_program(GladGLContext& gl, ssao_impl::ProgramId id, uint32_t variant, GLuint& program) {
    program = 0;
    GLuint vs = 0, fs = 0;
    std::string log = compile_log(gl, GL_VERTEX_SHADER, ssao_impl::vertex_source(), vs);
    if (log.empty()) log = compile_log(gl, GL_FRAGMENT_SHADER, ssao_impl::fragment_source(id, variant), fs);
    if (log.empty()) {
        program = gl.CreateProgram();
        gl.AttachShader(program, vs);
        gl.AttachShader(program, fs);
        gl.LinkProgram(program);
        GLint ok = 0;
        gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
        if (!ok) {
            char text[4096] = {};
            gl.GetProgramInfoLog(program, sizeof text, nullptr, text);
            log = std::string("link: ") + text;
        }
    }
    gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    return log;
}

}  // namespace shader_build
