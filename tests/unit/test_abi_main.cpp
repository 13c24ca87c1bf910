// test_abi_main.cpp - main of unit_abi and the shared helpers (abi_common.h).
// main also has a child mode, used by test_abi_gl.cpp to run create_context
// with a crippled get_proc_address in a fresh process (a crash there must
// fail one test, not take the whole run down).
#define DOCTEST_CONFIG_IMPLEMENT
#include "abi_common.h"

#include <dlfcn.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cstdlib>
#include <cstring>

#ifndef UNIT_SSAO_PLUGIN
#define UNIT_SSAO_PLUGIN "libssao.so"
#endif

namespace unit {

const ssao_api& api() {
    static plugin::Library* library = [] {
        auto* lib = new plugin::Library();
        std::string error;
        if (!lib->open(plugin::Library::default_path(), error)) {
            delete lib;
            return static_cast<plugin::Library*>(nullptr);
        }
        return lib;
    }();
    REQUIRE_MESSAGE(library != nullptr, "cannot load " << plugin::Library::default_path());
    return library->api();
}

PFN_ssao_get_api raw_get_api() {
    static void* handle = dlopen(plugin::Library::default_path().c_str(), RTLD_NOW | RTLD_LOCAL);
    REQUIRE_MESSAGE(handle != nullptr, "dlopen: " << dlerror());
    auto fn = reinterpret_cast<PFN_ssao_get_api>(dlsym(handle, "ssao_get_api"));
    REQUIRE((fn != nullptr));
    return fn;
}

std::unique_ptr<eglctx::Context> make_egl() {
    try {
        return testgl::make_debug_context();
    } catch (const std::exception& e) {
        FAIL("no EGL context: " << e.what());
    }
    return nullptr;
}

GlFixture::GlFixture(const ssao_settings* settings) {
    egl = make_egl();
    gl_errors = std::make_unique<testgl::DebugErrors>(egl->gl());
    ssao_context_desc desc = sized<ssao_context_desc>();
    desc.get_proc_address = eglctx::Context::get_proc;
    desc.log = LogRecorder::callback;
    desc.log_user = &log;
    desc.settings = settings;
    const ssao_status st = api().create_context(&desc, &ctx);
    REQUIRE_MESSAGE(st == SSAO_OK, "create_context: " << api().status_string(st));
    REQUIRE((ctx != nullptr));
}

GlFixture::~GlFixture() {
    if (ctx) api().destroy_context(ctx);
    ctx = nullptr;
    std::string all;
    for (const std::string& m : gl_errors->messages()) all += m + "; ";
    CHECK_MESSAGE(gl_errors->messages().empty(), "GL errors: " << all);
}

GLuint make_depth(GladGLContext& gl, int w, int h, float value, GLenum internal) {
    std::vector<float> data(static_cast<size_t>(w) * h, value);
    GLuint tex = 0;
    gl.GenTextures(1, &tex);
    gl.BindTexture(GL_TEXTURE_2D, tex);
    gl.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), w, h, 0, GL_DEPTH_COMPONENT, GL_FLOAT, data.data());
    gl.BindTexture(GL_TEXTURE_2D, 0);
    return tex;
}

GLuint make_normals(GladGLContext& gl, int w, int h) {
    std::vector<float> data(static_cast<size_t>(w) * h * 4, 0.0f);
    for (size_t i = 0; i < data.size(); i += 4) data[i + 2] = 1.0f;
    GLuint tex = 0;
    gl.GenTextures(1, &tex);
    gl.BindTexture(GL_TEXTURE_2D, tex);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, w, h, 0, GL_RGBA, GL_FLOAT, data.data());
    gl.BindTexture(GL_TEXTURE_2D, 0);
    return tex;
}

GLuint make_color(GladGLContext& gl, int w, int h, GLenum internal) {
    GLuint tex = 0;
    gl.GenTextures(1, &tex);
    gl.BindTexture(GL_TEXTURE_2D, tex);
    gl.TexStorage2D(GL_TEXTURE_2D, 1, internal, w, h);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    return tex;
}

void default_projection(float out[16]) {
    const glm::mat4 p = glm::perspective(glm::radians(60.0f), 1.0f, 1.0f, 100.0f);
    std::memcpy(out, glm::value_ptr(p), sizeof(float) * 16);
}

float depth_at(const float projection[16], float t) {
    glm::mat4 p;
    std::memcpy(glm::value_ptr(p), projection, sizeof(float) * 16);
    const glm::vec4 c = p * glm::vec4(0.0f, 0.0f, -t, 1.0f);
    return c.z / c.w * 0.5f + 0.5f;
}

ssao_inputs make_inputs(GLuint depth, GLuint normal) {
    ssao_inputs in = sized<ssao_inputs>();
    in.depth_texture = depth;
    in.normal_texture = normal;
    in.normal_space = SSAO_NORMAL_SPACE_VIEW;
    in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
    default_projection(in.projection);
    const glm::mat4 identity(1.0f);
    std::memcpy(in.view_matrix, glm::value_ptr(identity), sizeof in.view_matrix);
    in.clip_range = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
    return in;
}

LiveObjects count_live(GladGLContext& gl, GLuint limit) {
    LiveObjects n;
    for (GLuint name = 1; name <= limit; ++name) {
        n.textures += gl.IsTexture(name) == GL_TRUE;
        n.buffers += gl.IsBuffer(name) == GL_TRUE;
        n.framebuffers += gl.IsFramebuffer(name) == GL_TRUE;
        n.vertex_arrays += gl.IsVertexArray(name) == GL_TRUE;
        n.samplers += gl.IsSampler(name) == GL_TRUE;
        n.programs += gl.IsProgram(name) == GL_TRUE;
        n.queries += gl.IsQuery(name) == GL_TRUE;
    }
    return n;
}

bool GlSnapshot::operator==(const GlSnapshot& o) const {
    for (int i = 0; i < SSAO_TEXTURE_UNITS_USED; ++i)
        if (texture_2d[i] != o.texture_2d[i] || sampler[i] != o.sampler[i]) return false;
    for (int i = 0; i < 4; ++i)
        if (viewport[i] != o.viewport[i] || scissor[i] != o.scissor[i]) return false;
    return active_texture == o.active_texture && draw_fbo == o.draw_fbo && read_fbo == o.read_fbo &&
           program == o.program && vao == o.vao && array_buffer == o.array_buffer &&
           uniform_buffer == o.uniform_buffer && scissor_test == o.scissor_test && depth_test == o.depth_test &&
           blend == o.blend && cull_face == o.cull_face && unpack_alignment == o.unpack_alignment;
}

GlSnapshot snapshot(GladGLContext& gl) {
    GlSnapshot s;
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &s.active_texture);
    for (int u = 0; u < SSAO_TEXTURE_UNITS_USED; ++u) {
        gl.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + u));
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &s.texture_2d[u]);
        gl.GetIntegerv(GL_SAMPLER_BINDING, &s.sampler[u]);
    }
    gl.ActiveTexture(static_cast<GLenum>(s.active_texture));
    gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &s.draw_fbo);
    gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &s.read_fbo);
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &s.program);
    gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &s.vao);
    gl.GetIntegerv(GL_ARRAY_BUFFER_BINDING, &s.array_buffer);
    gl.GetIntegerv(GL_UNIFORM_BUFFER_BINDING, &s.uniform_buffer);
    gl.GetIntegerv(GL_VIEWPORT, s.viewport);
    gl.GetIntegerv(GL_SCISSOR_BOX, s.scissor);
    s.scissor_test = gl.IsEnabled(GL_SCISSOR_TEST);
    s.depth_test = gl.IsEnabled(GL_DEPTH_TEST);
    s.blend = gl.IsEnabled(GL_BLEND);
    s.cull_face = gl.IsEnabled(GL_CULL_FACE);
    gl.GetIntegerv(GL_UNPACK_ALIGNMENT, &s.unpack_alignment);
    return s;
}

void set_host_state(GladGLContext& gl) {
    GLuint tex[SSAO_TEXTURE_UNITS_USED] = {};
    gl.GenTextures(SSAO_TEXTURE_UNITS_USED, tex);
    for (int u = 0; u < SSAO_TEXTURE_UNITS_USED; ++u) {
        gl.ActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + u));
        gl.BindTexture(GL_TEXTURE_2D, tex[u]);
    }
    gl.ActiveTexture(GL_TEXTURE2);
    GLuint fbo = 0, vao = 0, buf[2] = {};
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl.GenVertexArrays(1, &vao);
    gl.BindVertexArray(vao);
    gl.GenBuffers(2, buf);
    gl.BindBuffer(GL_ARRAY_BUFFER, buf[0]);
    gl.BindBuffer(GL_UNIFORM_BUFFER, buf[1]);
    gl.Viewport(3, 5, 7, 11);
    gl.Scissor(1, 2, 3, 4);
    gl.Enable(GL_SCISSOR_TEST);
    gl.Enable(GL_DEPTH_TEST);
    gl.Enable(GL_BLEND);
    gl.Enable(GL_CULL_FACE);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
}

// ---- child mode: create_context (and one execute) where get_proc_address
// returns NULL for one GL function. Exits with the status create_context
// returned (0 when it accepted and execute then ran and left the host's
// per-draw-buffer blend functions as they were, 94 when it changed them).
namespace {

const char* g_missing = nullptr;

ssao_gl_proc SSAO_CALL get_proc_missing_one(void*, const char* name) {
    if (std::strcmp(name, g_missing) == 0) return nullptr;
    return eglctx::Context::get_proc(nullptr, name);
}

int child_missing_function(const char* name) {
    g_missing = name;
    std::string error;
    auto egl = eglctx::Context::create(eglctx::Options{}, error);
    if (!egl) return 90;
    plugin::Library lib;
    if (!lib.open(plugin::Library::default_path(), error)) return 91;
    const ssao_api& a = lib.api();
    ssao_context_desc desc = sized<ssao_context_desc>();
    desc.get_proc_address = get_proc_missing_one;
    ssao_context* ctx = nullptr;
    const ssao_status st = a.create_context(&desc, &ctx);
    if (st != SSAO_OK) return ctx == nullptr ? static_cast<int>(st) : 92;
    GladGLContext& gl = egl->gl();
    const GLuint depth = make_depth(gl, 8, 8, 0.9f);
    const GLuint normal = make_normals(gl, 8, 8);
    ssao_inputs in = make_inputs(depth, normal);
    ssao_output out = sized<ssao_output>();
    // The host sets blend functions per draw buffer (its own loader has
    // them); a library that cannot set one buffer's must not set them all.
    gl.BlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO);
    gl.BlendFuncSeparatei(1, GL_ONE, GL_ONE, GL_ZERO, GL_ONE);
    gl.BlendEquationSeparatei(1, GL_MAX, GL_MIN);
    const ssao_status executed = a.execute(ctx, &in, &out);
    GLint src1 = 0, eq1 = 0;
    gl.GetIntegeri_v(GL_BLEND_SRC_RGB, 1, &src1);
    gl.GetIntegeri_v(GL_BLEND_EQUATION_RGB, 1, &eq1);
    a.destroy_context(ctx);
    if (executed != SSAO_OK) return 93;
    return src1 == GL_ONE && eq1 == GL_MAX ? 0 : 94;
}

}  // namespace

}  // namespace unit

int main(int argc, char** argv) {
    // The plugin of this build unless the caller chose another.
    setenv("SSAO_PLUGIN", UNIT_SSAO_PLUGIN, 0);
    if (argc == 3 && std::strcmp(argv[1], "--unit-child-missing") == 0) return unit::child_missing_function(argv[2]);
    doctest::Context context(argc, argv);
    return context.run();
}
