#include "gl_util.h"

#include "fullscreen_vert_embedded.h"

#include <cstdio>

namespace gl_util {

std::string fullscreen_vertex_shader() { return std::string("#version 330 core\n") + k_fullscreen_vert; }

namespace {

std::string log_of(GladGLContext& gl, GLuint object, bool program) {
    GLint length = 0;
    if (program)
        gl.GetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        gl.GetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(length > 1 ? length : 1), '\0');
    if (program)
        gl.GetProgramInfoLog(object, length, nullptr, log.data());
    else
        gl.GetShaderInfoLog(object, length, nullptr, log.data());
    while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
    for (char& c : log)
        if (c == '\n') c = ' ';
    return log;
}

GLuint compile(GladGLContext& gl, const char* what, GLenum type, const char* src) {
    const GLuint shader = gl.CreateShader(type);
    gl.ShaderSource(shader, 1, &src, nullptr);
    gl.CompileShader(shader);
    GLint ok = 0;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = log_of(gl, shader, false);
        gl.DeleteShader(shader);
        throw Error(std::string("the host's ") + what + (type == GL_VERTEX_SHADER ? " vertex" : " fragment") +
                    " shader does not compile: " + log);
    }
    return shader;
}

}  // namespace

GLuint make_program(GladGLContext& gl, const char* what, const char* vertex_src, const char* fragment_src) {
    const GLuint vs = compile(gl, what, GL_VERTEX_SHADER, vertex_src);
    GLuint fs = 0;
    try {
        fs = compile(gl, what, GL_FRAGMENT_SHADER, fragment_src);
    } catch (...) {
        gl.DeleteShader(vs);
        throw;
    }
    const GLuint program = gl.CreateProgram();
    gl.AttachShader(program, vs);
    gl.AttachShader(program, fs);
    gl.LinkProgram(program);
    gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = log_of(gl, program, true);
        gl.DeleteProgram(program);
        throw Error(std::string("the host's ") + what + " program does not link: " + log);
    }
    return program;
}

void check(GladGLContext& gl, const char* where) {
    const GLenum e = gl.GetError();
    if (e == GL_NO_ERROR) return;
    while (gl.GetError() != GL_NO_ERROR) {
    }
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(e));
    std::string name;
    switch (e) {
        case GL_INVALID_ENUM: name = " (GL_INVALID_ENUM)"; break;
        case GL_INVALID_VALUE: name = " (GL_INVALID_VALUE)"; break;
        case GL_INVALID_OPERATION: name = " (GL_INVALID_OPERATION)"; break;
        case GL_INVALID_FRAMEBUFFER_OPERATION: name = " (GL_INVALID_FRAMEBUFFER_OPERATION)"; break;
        case GL_OUT_OF_MEMORY: name = " (GL_OUT_OF_MEMORY: the image is too large for this GPU)"; break;
        default: break;
    }
    throw Error(std::string("OpenGL error ") + code + name + " in " + where);
}

void check_framebuffer(GladGLContext& gl, const char* what) {
    const GLenum status = gl.CheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return;
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(status));
    throw Error(std::string("the ") + what + " framebuffer is incomplete (status " + code +
                "); this driver cannot render to the requested formats");
}

GLuint make_texture(GladGLContext& gl, GLenum internal_format, int width, int height) {
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D, t);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    GLenum format = GL_RGBA, type = GL_FLOAT;
    switch (internal_format) {
        case GL_DEPTH_COMPONENT16:
        case GL_DEPTH_COMPONENT24:
        case GL_DEPTH_COMPONENT32F: format = GL_DEPTH_COMPONENT; break;
        case GL_R8:
        case GL_R16F:
        case GL_R32F: format = GL_RED; break;
        default: break;
    }
    gl.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal_format), width, height, 0, format, type, nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    check(gl, "texture allocation");
    return t;
}

std::vector<float> read_texture(GladGLContext& gl, GLuint texture, int x, int y, int w, int h, int components,
                                bool depth) {
    GLuint fbo = 0;
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_READ_FRAMEBUFFER, depth ? GL_DEPTH_ATTACHMENT : GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                            texture, 0);
    if (!depth) gl.ReadBuffer(GL_COLOR_ATTACHMENT0);
    else gl.ReadBuffer(GL_NONE);
    const GLenum status = gl.CheckFramebufferStatus(GL_READ_FRAMEBUFFER);
    std::vector<float> pixels(static_cast<size_t>(w) * static_cast<size_t>(h) * static_cast<size_t>(components));
    if (status == GL_FRAMEBUFFER_COMPLETE) {
        gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
        const GLenum format = depth ? GL_DEPTH_COMPONENT
                              : components == 1 ? GL_RED
                              : components == 3 ? GL_RGB
                                                : GL_RGBA;
        gl.ReadPixels(x, y, w, h, format, GL_FLOAT, pixels.data());
    }
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    gl.DeleteFramebuffers(1, &fbo);
    if (status != GL_FRAMEBUFFER_COMPLETE) throw Error("a texture cannot be read back (incomplete framebuffer)");
    check(gl, "reading back a texture");
    return pixels;
}

}  // namespace gl_util
