#include "gl_fixture.h"

#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace testgl {

DebugErrors::DebugErrors(GladGLContext& gl) {
    if (!gl.DebugMessageCallback) return;
    gl.Enable(GL_DEBUG_OUTPUT);
    gl.Enable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    gl.DebugMessageCallback(&DebugErrors::callback, this);
}

void DebugErrors::callback(GLenum /*source*/, GLenum type, GLuint /*id*/, GLenum /*severity*/, GLsizei /*length*/,
                           const GLchar* message, const void* user) {
    if (type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR)
        static_cast<DebugErrors*>(const_cast<void*>(user))->messages_.push_back(message);
}

GLuint make_host_program(GladGLContext& gl) {
    const char* vs = "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    const char* fs = "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
    const GLuint program = gl.CreateProgram();
    for (auto [type, text] : {std::pair<GLenum, const char*>{GL_VERTEX_SHADER, vs}, {GL_FRAGMENT_SHADER, fs}}) {
        const GLuint sh = gl.CreateShader(type);
        gl.ShaderSource(sh, 1, &text, nullptr);
        gl.CompileShader(sh);
        gl.AttachShader(program, sh);
        gl.DeleteShader(sh);
    }
    gl.LinkProgram(program);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) throw std::runtime_error("the host's test program did not link");
    return program;
}

std::unique_ptr<eglctx::Context> make_debug_context(int major, int minor) {
    std::string error;
    eglctx::Options options;
    options.major = major;
    options.minor = minor;
    options.debug = true;
    auto egl = eglctx::Context::create(options, error);
    if (!egl) throw std::runtime_error(error);
    return egl;
}

void set_viewport(ssao_inputs& in, int x, int y, int w, int h) {
    in.viewport[0] = x;
    in.viewport[1] = y;
    in.viewport[2] = w;
    in.viewport[3] = h;
}

ssao_normal_packing packing_of(GLenum normal_format) {
    return normal_format == GL_RGBA8 ? SSAO_NORMAL_PACKING_UNORM : SSAO_NORMAL_PACKING_SIGNED;
}

ssao_status create_default_context(const ssao_api& api, ssao_context** out) {
    ssao_context_desc desc{};
    desc.size = sizeof desc;
    desc.get_proc_address = &eglctx::Context::get_proc;
    return api.create_context(&desc, out);
}

namespace {

// recreate_context_as: the name GL_RENDERER reports, the real glGetString
// and glBlitFramebuffer, and the blits counted.
const char* g_renderer_name = nullptr;
PFNGLGETSTRINGPROC g_get_string = nullptr;
PFNGLBLITFRAMEBUFFERPROC g_blit = nullptr;
int g_blits = 0;

const GLubyte* GLAD_API_PTR renamed_get_string(GLenum name) {
    return name == GL_RENDERER ? reinterpret_cast<const GLubyte*>(g_renderer_name) : g_get_string(name);
}

void GLAD_API_PTR counted_blit(GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0, GLint dy0, GLint dx1, GLint dy1,
                               GLbitfield mask, GLenum filter) {
    ++g_blits;
    g_blit(sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter);
}

ssao_gl_proc SSAO_CALL renamed_get_proc(void* user, const char* name) {
    if (std::strcmp(name, "glGetString") == 0) return reinterpret_cast<ssao_gl_proc>(&renamed_get_string);
    if (std::strcmp(name, "glBlitFramebuffer") == 0) return reinterpret_cast<ssao_gl_proc>(&counted_blit);
    return eglctx::Context::get_proc(user, name);
}

}  // namespace

void Fixture::recreate_context_as(const char* renderer) {
    g_renderer_name = renderer;
    g_get_string = gl().GetString;
    g_blit = gl().BlitFramebuffer;
    g_blits = 0;
    api().destroy_context(ctx_);
    ctx_ = nullptr;
    ssao_context_desc desc{};
    desc.size = sizeof desc;
    desc.get_proc_address = &renamed_get_proc;
    const ssao_status st = api().create_context(&desc, &ctx_);
    if (st != SSAO_OK) throw std::runtime_error(std::string("create_context: ") + api().status_string(st));
}

int Fixture::blits_as_renamed() { return g_blits; }

Fixture::Fixture(int major, int minor) {
    egl_ = make_debug_context(major, minor);
    std::string error;
    if (!lib_.open(plugin::Library::default_path(), error)) throw std::runtime_error(error);
    errors_ = std::make_unique<DebugErrors>(gl());
    const ssao_status st = create_default_context(api(), &ctx_);
    if (st != SSAO_OK) throw std::runtime_error(std::string("create_context: ") + api().status_string(st));
}

Fixture::~Fixture() {
    if (!textures_.empty()) gl().DeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
    api().destroy_context(ctx_);
}

MesaGl33Override::MesaGl33Override() { setenv("MESA_GL_VERSION_OVERRIDE", "3.3", 1); }

Gl33Fixture::Gl33Fixture() : Fixture(3, 3) {
    const std::string version = reinterpret_cast<const char*>(gl().GetString(GL_VERSION));
    if (version.rfind("3.3", 0) != 0) throw std::runtime_error("asked for GL 3.3 core, got GL_VERSION " + version);
}

GLuint Fixture::make_depth(GLenum internal, int w, int h, const std::vector<float>& depth) {
    auto& g = gl();
    GLuint t = 0;
    g.GenTextures(1, &t);
    textures_.push_back(t);
    g.BindTexture(GL_TEXTURE_2D, t);
    if (internal == GL_DEPTH24_STENCIL8) {
        std::vector<uint32_t> packed(depth.size());
        for (size_t i = 0; i < depth.size(); ++i)
            packed[i] = static_cast<uint32_t>(std::lround(static_cast<double>(depth[i]) * 16777215.0)) << 8;
        g.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), w, h, 0, GL_DEPTH_STENCIL,
                     GL_UNSIGNED_INT_24_8, packed.data());
    } else if (internal == GL_DEPTH32F_STENCIL8) {
        std::vector<float> packed(depth.size() * 2, 0.0f);
        for (size_t i = 0; i < depth.size(); ++i) packed[i * 2] = depth[i];
        g.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), w, h, 0, GL_DEPTH_STENCIL,
                     GL_FLOAT_32_UNSIGNED_INT_24_8_REV, packed.data());
    } else {
        g.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), w, h, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                     depth.data());
    }
    g.BindTexture(GL_TEXTURE_2D, 0);
    return t;
}

GLuint Fixture::make_normals(GLenum internal, int w, int h, const std::vector<glm::vec3>& normals) {
    auto& g = gl();
    GLuint t = 0;
    g.GenTextures(1, &t);
    textures_.push_back(t);
    g.BindTexture(GL_TEXTURE_2D, t);
    std::vector<float> rgba(normals.size() * 4);
    const bool packed = internal == GL_RGBA8;
    for (size_t i = 0; i < normals.size(); ++i) {
        for (int c = 0; c < 3; ++c) rgba[i * 4 + c] = packed ? normals[i][c] * 0.5f + 0.5f : normals[i][c];
        rgba[i * 4 + 3] = 1.0f;
    }
    g.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), w, h, 0, GL_RGBA, GL_FLOAT, rgba.data());
    g.BindTexture(GL_TEXTURE_2D, 0);
    return t;
}

Textures Fixture::upload(const analytic::GBuffer& g, GLenum depth_format, GLenum normal_format) {
    Textures t;
    t.depth = make_depth(depth_format, g.width, g.height, g.depth);
    t.normal = make_normals(normal_format, g.width, g.height, g.normal);
    return t;
}

std::vector<float> Fixture::read_red(GLuint texture, int w, int h) {
    auto& g = gl();
    GLuint fbo = 0;
    g.GenFramebuffers(1, &fbo);
    g.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    g.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
    std::vector<float> out(static_cast<size_t>(w) * h);
    g.PixelStorei(GL_PACK_ALIGNMENT, 4);
    g.ReadPixels(0, 0, w, h, GL_RED, GL_FLOAT, out.data());
    g.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    g.DeleteFramebuffers(1, &fbo);
    return out;
}

ssao_settings Fixture::settings(const ssao_settings& overrides) {
    ssao_settings s = overrides;
    s.size = sizeof s;
    if (api().set_settings(ctx_, &s) != SSAO_OK) throw std::runtime_error(api().last_error(ctx_));
    ssao_settings r{};
    r.size = sizeof r;
    api().get_settings(ctx_, &r);
    return r;
}

ssao_inputs Fixture::inputs(GLuint depth, GLuint normal, const glm::dmat4& proj, ssao_clip_range clip) {
    ssao_inputs in{};
    in.size = sizeof in;
    in.depth_texture = depth;
    in.normal_texture = normal;
    in.normal_space = SSAO_NORMAL_SPACE_VIEW;
    in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
    analytic::to_floats(proj, in.projection);
    in.clip_range = clip;
    return in;
}

Fixture::Result Fixture::run(const analytic::GBuffer& g, const glm::dmat4& proj, ssao_clip_range clip,
                             GLenum depth_format) {
    Result r;
    const Textures t = upload(g, depth_format);
    ssao_inputs in = inputs(t.depth, t.normal, proj, clip);
    r.output.size = sizeof r.output;
    r.status = api().execute(ctx_, &in, &r.output);
    if (r.status == SSAO_OK) r.ao = read_red(r.output.texture, g.width, g.height);
    return r;
}

}  // namespace testgl
