// abi_common.h - shared by the unit_abi tests: the dlopened plugin, a headless
// EGL context with a plugin context on it, input textures, a log recorder and
// a snapshot of the GL state a failing call must leave alone.
#pragma once

#include "gl_fixture.h"

#include <ssao/ssao.h>

#include "egl_context.h"
#include "plugin_loader.h"

#include <doctest/doctest.h>

#include <glad/gl.h>

#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace unit {

// The table of the plugin under test, loaded once per process through
// plugin::Library::default_path() ($SSAO_PLUGIN, set by main and by CTest).
const ssao_api& api();
// ssao_get_api itself, looked up with dlsym in the same library.
PFN_ssao_get_api raw_get_api();

struct LogEntry {
    ssao_log_level level;
    std::string message;
};
struct LogRecorder {
    std::vector<LogEntry> entries;
    static void SSAO_CALL callback(void* user, ssao_log_level level, const char* message) {
        static_cast<LogRecorder*>(user)->entries.push_back({level, message ? message : "(null)"});
    }
};

inline bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

template <typename T>
T sized() {
    T t;
    std::memset(&t, 0, sizeof t);
    t.size = sizeof(T);
    return t;
}

// A struct full of a recognisable pattern (with a correct size), to see
// whether a call wrote into it.
template <typename T>
T sentinel() {
    T t;
    std::memset(&t, 0xA5, sizeof t);
    t.size = sizeof(T);
    return t;
}

template <typename T>
bool same_bytes(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

// Writes an arbitrary value into an enum field without an out-of-range enum
// conversion (undefined in C++17).
template <typename E>
void set_raw(E& field, int32_t value) {
    static_assert(sizeof(E) == sizeof(int32_t), "enum fields are 4 bytes");
    std::memcpy(&field, &value, sizeof value);
}

// A 4.5 core EGL context (current on this thread) and a plugin context on it.
struct GlFixture {
    std::unique_ptr<eglctx::Context> egl;
    std::unique_ptr<testgl::DebugErrors> gl_errors;  // any GL error fails the test (checked at the end)
    LogRecorder log;
    ssao_context* ctx = nullptr;

    explicit GlFixture(const ssao_settings* settings = nullptr);
    ~GlFixture();
    GlFixture(const GlFixture&) = delete;
    GlFixture& operator=(const GlFixture&) = delete;

    GladGLContext& gl() { return egl->gl(); }
    std::string last_error() const { return api().last_error(ctx); }
};

// Makes a current 4.5 core debug context or fails the test.
std::unique_ptr<eglctx::Context> make_egl();

// Textures of the host.
GLuint make_depth(GladGLContext& gl, int w, int h, float value, GLenum internal = GL_DEPTH_COMPONENT32F);
GLuint make_normals(GladGLContext& gl, int w, int h);  // RGBA16F, (0, 0, 1) everywhere
GLuint make_color(GladGLContext& gl, int w, int h, GLenum internal = GL_RGBA8);

// The depth-buffer value of view distance t under `projection` (GL [-1,1] clip).
float depth_at(const float projection[16], float t);

// A valid perspective (60 degrees, square, near 1, far 100), GL clip range.
void default_projection(float out[16]);

// Inputs for execute over the whole of the given textures.
ssao_inputs make_inputs(GLuint depth, GLuint normal);

// Number of live GL object names among 1..limit, per kind.
struct LiveObjects {
    int textures = 0, buffers = 0, framebuffers = 0, vertex_arrays = 0, samplers = 0, programs = 0, queries = 0;
};
LiveObjects count_live(GladGLContext& gl, GLuint limit = 2000);

// The GL state a failing execute must not change (a representative subset of
// the list in ssao.h).
struct GlSnapshot {
    GLint active_texture = 0;
    GLint texture_2d[SSAO_TEXTURE_UNITS_USED] = {};
    GLint sampler[SSAO_TEXTURE_UNITS_USED] = {};
    GLint draw_fbo = 0, read_fbo = 0, program = 0, vao = 0, array_buffer = 0, uniform_buffer = 0;
    GLint viewport[4] = {};
    GLint scissor[4] = {};
    GLboolean scissor_test = 0, depth_test = 0, blend = 0, cull_face = 0;
    GLint unpack_alignment = 0;
    bool operator==(const GlSnapshot& o) const;
};
GlSnapshot snapshot(GladGLContext& gl);
// Puts distinctive host state in place (textures on every unit the plugin
// uses, a host framebuffer, odd viewport and scissor, a few enables).
void set_host_state(GladGLContext& gl);

}  // namespace unit
