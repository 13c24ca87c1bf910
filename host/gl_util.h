// gl_util.h - small GL helpers of the host: shader programs, error checks,
// texture creation and read-back. Every failure throws gl_util::Error with one
// sentence, which main() prints.
#pragma once

#include <glad/gl.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace gl_util {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The vertex shader of a full-screen pass for GLSL 3.30: one triangle covering
// the viewport, drawn with an empty vertex array (shaders/fullscreen.vert, the
// plugin's own).
std::string fullscreen_vertex_shader();

// Compiles and links a vertex + fragment program; throws with the driver's log.
GLuint make_program(GladGLContext& gl, const char* what, const char* vertex_src, const char* fragment_src);

// Throws when glGetError reports something, naming `where`.
void check(GladGLContext& gl, const char* where);

// Throws when the bound draw framebuffer is incomplete.
void check_framebuffer(GladGLContext& gl, const char* what);

// A 2D texture with one level, nearest filtering and clamp-to-edge.
GLuint make_texture(GladGLContext& gl, GLenum internal_format, int width, int height);

// Reads `components` float channels (1 = RED, 3 = RGB, 4 = RGBA; or depth when
// `depth` is set) of the rectangle (x, y, w, h) of `texture`, bottom row first.
std::vector<float> read_texture(GladGLContext& gl, GLuint texture, int x, int y, int w, int h,
                                int components, bool depth = false);

}  // namespace gl_util
