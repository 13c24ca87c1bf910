// context.cpp - creation and destruction of a context: GL loading, capability
// checks, shader compilation, and every GL object made once up front.
#include "context.h"

#include "context_identity.h"
#include "debug.h"
#include "program_cache.h"
#include "renderer.h"
#include "resources.h"
#include "uniforms.h"


#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

ssao_status ssao_context::fail(ssao_status status, const std::string& message) const {
    last_error = message;
    if (log) log(log_user, SSAO_LOG_ERROR, message.c_str());
    return status;
}

namespace ssao_impl {

namespace {

struct LoaderUser {
    ssao_get_proc_address_fn fn;
    void* user;
};

GLADapiproc load_with_user(void* userptr, const char* name) {
    auto* u = static_cast<LoaderUser*>(userptr);
    return reinterpret_cast<GLADapiproc>(u->fn(u->user, name));
}

// Every GL 3.3 core function the plugin calls: a loader that hands back NULL
// for any of them gets GL_LOAD at creation instead of a crash in execute.
bool all_required_loaded(const GladGLContext& gl, std::string& missing) {
#define SSAO_REQUIRE_GL(fn) if (!gl.fn) { missing = "gl" #fn; return false; }
    SSAO_REQUIRE_GL(ActiveTexture) SSAO_REQUIRE_GL(AttachShader) SSAO_REQUIRE_GL(BindBuffer)
    SSAO_REQUIRE_GL(BindBufferBase) SSAO_REQUIRE_GL(BindBufferRange) SSAO_REQUIRE_GL(BindFramebuffer)
    SSAO_REQUIRE_GL(BindSampler) SSAO_REQUIRE_GL(BindTexture) SSAO_REQUIRE_GL(BindVertexArray)
    SSAO_REQUIRE_GL(BlendEquationSeparate) SSAO_REQUIRE_GL(BlendFuncSeparate) SSAO_REQUIRE_GL(BlitFramebuffer)
    SSAO_REQUIRE_GL(BufferData) SSAO_REQUIRE_GL(CheckFramebufferStatus) SSAO_REQUIRE_GL(ClearBufferfv)
    SSAO_REQUIRE_GL(ColorMaski) SSAO_REQUIRE_GL(CompileShader) SSAO_REQUIRE_GL(CreateProgram)
    SSAO_REQUIRE_GL(CreateShader) SSAO_REQUIRE_GL(DeleteBuffers) SSAO_REQUIRE_GL(DeleteFramebuffers)
    SSAO_REQUIRE_GL(DeleteProgram) SSAO_REQUIRE_GL(DeleteQueries) SSAO_REQUIRE_GL(DeleteSamplers)
    SSAO_REQUIRE_GL(DeleteShader) SSAO_REQUIRE_GL(DeleteTextures) SSAO_REQUIRE_GL(DeleteVertexArrays)
    SSAO_REQUIRE_GL(DepthFunc) SSAO_REQUIRE_GL(DepthMask) SSAO_REQUIRE_GL(DepthRange) SSAO_REQUIRE_GL(Disable)
    SSAO_REQUIRE_GL(Disablei) SSAO_REQUIRE_GL(DrawArrays) SSAO_REQUIRE_GL(DrawBuffers)
    SSAO_REQUIRE_GL(Enable) SSAO_REQUIRE_GL(Enablei) SSAO_REQUIRE_GL(FramebufferTexture2D)
    SSAO_REQUIRE_GL(GenBuffers) SSAO_REQUIRE_GL(GenFramebuffers) SSAO_REQUIRE_GL(GenQueries)
    SSAO_REQUIRE_GL(GenSamplers) SSAO_REQUIRE_GL(GenTextures) SSAO_REQUIRE_GL(GenVertexArrays)
    SSAO_REQUIRE_GL(GetBooleani_v) SSAO_REQUIRE_GL(GetBooleanv) SSAO_REQUIRE_GL(GetDoublev)
    SSAO_REQUIRE_GL(GetInteger64i_v)
    SSAO_REQUIRE_GL(GetIntegeri_v) SSAO_REQUIRE_GL(GetIntegerv) SSAO_REQUIRE_GL(GetProgramInfoLog)
    SSAO_REQUIRE_GL(GetProgramiv) SSAO_REQUIRE_GL(GetQueryObjectuiv) SSAO_REQUIRE_GL(GetShaderInfoLog)
    SSAO_REQUIRE_GL(GetShaderiv) SSAO_REQUIRE_GL(GetStringi) SSAO_REQUIRE_GL(GetTexLevelParameteriv)
    SSAO_REQUIRE_GL(GetTexParameteriv) SSAO_REQUIRE_GL(GetUniformBlockIndex) SSAO_REQUIRE_GL(GetUniformLocation)
    SSAO_REQUIRE_GL(IsEnabled) SSAO_REQUIRE_GL(IsEnabledi) SSAO_REQUIRE_GL(IsTexture) SSAO_REQUIRE_GL(IsVertexArray) SSAO_REQUIRE_GL(LinkProgram)
    SSAO_REQUIRE_GL(PixelStorei) SSAO_REQUIRE_GL(PolygonMode) SSAO_REQUIRE_GL(ReadBuffer) SSAO_REQUIRE_GL(SamplerParameteri)
    SSAO_REQUIRE_GL(Scissor) SSAO_REQUIRE_GL(ShaderSource) SSAO_REQUIRE_GL(StencilMaskSeparate)
    SSAO_REQUIRE_GL(TexImage2D) SSAO_REQUIRE_GL(TexParameteri) SSAO_REQUIRE_GL(Uniform1i) SSAO_REQUIRE_GL(Uniform2i)
    SSAO_REQUIRE_GL(UniformBlockBinding) SSAO_REQUIRE_GL(UseProgram) SSAO_REQUIRE_GL(Viewport)
#undef SSAO_REQUIRE_GL
    return true;
}

bool has_gl_extension(const GladGLContext& gl, const char* name) {
    GLint count = 0;
    gl.GetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const char* e = reinterpret_cast<const char*>(gl.GetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (e && std::strcmp(e, name) == 0) return true;
    }
    return false;
}

}  // namespace

ssao_status initialise(ssao_context& ctx, const ssao_context_desc& desc) {
    // Before loading everything: is a context current, and is it new enough?
    auto get_string = reinterpret_cast<PFNGLGETSTRINGPROC>(
        desc.get_proc_address(desc.get_proc_address_user, "glGetString"));
    if (!get_string)
        return ctx.fail(SSAO_ERROR_GL_LOAD, "get_proc_address returned NULL for glGetString");
    const char* version = reinterpret_cast<const char*>(get_string(GL_VERSION));
    if (!version)
        return ctx.fail(SSAO_ERROR_GL_VERSION, "no GL context is current (glGetString(GL_VERSION) returned NULL)");
    int major = 0, minor = 0;
    if (std::sscanf(version, "%d.%d", &major, &minor) != 2 || major * 10 + minor < 33)
        return ctx.fail(SSAO_ERROR_GL_VERSION,
                        std::string("GL 3.3 core or newer is required; the current context is ") + version);

    LoaderUser user{desc.get_proc_address, desc.get_proc_address_user};
    const int loaded = gladLoadGLContextUserPtr(&ctx.gl, load_with_user, &user);
    std::string missing;
    if (loaded == 0 || !all_required_loaded(ctx.gl, missing))
        return ctx.fail(SSAO_ERROR_GL_LOAD, "get_proc_address returned NULL for " +
                                                (missing.empty() ? std::string("GL 3.3 core functions") : missing));
    ctx.gl_ready = true;
    GladGLContext& gl = ctx.gl;
    ctx.caps.major = major;
    ctx.caps.minor = minor;
    const int v = major * 10 + minor;
    ctx.caps.clip_control = gl.ClipControl != nullptr && (v >= 45 || has_gl_extension(gl, "GL_ARB_clip_control"));
    ctx.caps.depth_stencil_mode = v >= 43;
    ctx.caps.texture_target_query = v >= 45 && gl.GetTextureParameteriv != nullptr && gl.GetTextureLevelParameteriv != nullptr;
    ctx.caps.query_buffer = v >= 44 || has_gl_extension(gl, "GL_ARB_query_buffer_object");
    // Per-draw-buffer blend functions: GL 4.0, or GL_ARB_draw_buffers_blend
    // below it (Mesa offers it at 3.3), whose calls carry the ARB suffix;
    // there the global glBlendFunc* calls set every buffer.
    if (v < 40 && gl.ARB_draw_buffers_blend) {
        gl.BlendFuncSeparatei = gl.BlendFuncSeparateiARB;
        gl.BlendEquationSeparatei = gl.BlendEquationSeparateiARB;
    }
    ctx.caps.indexed_blend = (v >= 40 || gl.ARB_draw_buffers_blend) && gl.BlendFuncSeparatei != nullptr &&
                             gl.BlendEquationSeparatei != nullptr;
    // Viewport arrays: GL 4.1, or GL_ARB_viewport_array below it (Mesa offers
    // it at 3.3), where glViewport, glScissor and glDepthRange set every index.
    if ((v >= 41 || gl.ARB_viewport_array) && gl.GetFloati_v && gl.ViewportIndexedfv && gl.ScissorIndexedv &&
        gl.GetDoublei_v && gl.DepthRangeIndexed) {
        gl.GetIntegerv(GL_MAX_VIEWPORTS, &ctx.caps.viewports);
        ctx.caps.viewports = std::max(1, std::min(ctx.caps.viewports, 16));
    }
    gl.GetIntegerv(GL_MAX_DRAW_BUFFERS, &ctx.caps.max_draw_buffers);
    gl.GetIntegerv(GL_MAX_CLIP_DISTANCES, &ctx.caps.max_clip_distances);
    ctx.caps.software_rasterizer = is_software_rasterizer(reinterpret_cast<const char*>(get_string(GL_RENDERER)));

    ssao_impl::init_debug(ctx);

    const ssao_status st = compile_base_programs(ctx);
    if (st != SSAO_OK) return st;

    // Object creation binds nothing here but the vertex array, whose binding
    // is put back at once (mark_creating_context): buffers and textures are
    // first bound inside execute, under the state guard.
    gl.GenVertexArrays(1, &ctx.vao);
    gl.GenFramebuffers(1, &ctx.fbo);
    gl.GenFramebuffers(1, &ctx.read_fbo);
    gl.GenBuffers(1, &ctx.ubo_frame);
    gl.GenBuffers(1, &ctx.ubo_kernel);
    gl.GenTextures(1, &ctx.noise_texture);
    gl.GenSamplers(1, &ctx.sampler);
    mark_creating_context(ctx);
    // Bound on every unit a pass uses (runner.cpp). The host's textures are
    // read with texelFetch, which ignores filtering and wrapping, but a depth
    // texture with a compare mode would read as a shadow test: the sampler
    // turns that off. The library's own textures are sampled through it at
    // their texels' centres (shaders/common.glsl owned_texel), so it must
    // stay nearest and clamped.
    gl.SamplerParameteri(ctx.sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.SamplerParameteri(ctx.sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.SamplerParameteri(ctx.sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.SamplerParameteri(ctx.sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.SamplerParameteri(ctx.sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    label_object(ctx, GL_SAMPLER, ctx.sampler, kLabelSampler);  // exists since its first SamplerParameter

    ctx.timers = gl.QueryCounter != nullptr && gl.GetQueryObjectui64v != nullptr && gl.GetQueryObjectuiv != nullptr;
    if (ctx.timers) gl.GenQueries(ssao_context::kFrames * ssao_context::kStamps, &ctx.queries[0][0]);
    return SSAO_OK;
}

void release(ssao_context& ctx) {
    GladGLContext& gl = ctx.gl;
    if (!ctx.gl_ready) return;  // GL never (fully) loaded: nothing was made
    delete_programs(ctx);
    if (ctx.vao) gl.DeleteVertexArrays(1, &ctx.vao);
    if (ctx.fbo) gl.DeleteFramebuffers(1, &ctx.fbo);
    if (ctx.read_fbo) gl.DeleteFramebuffers(1, &ctx.read_fbo);
    if (ctx.ubo_frame) gl.DeleteBuffers(1, &ctx.ubo_frame);
    if (ctx.ubo_kernel) gl.DeleteBuffers(1, &ctx.ubo_kernel);
    if (ctx.noise_texture) gl.DeleteTextures(1, &ctx.noise_texture);
    if (ctx.sampler) gl.DeleteSamplers(1, &ctx.sampler);
    for (GLuint texture : ctx.intermediates)
        if (texture) gl.DeleteTextures(1, &texture);
    for (GLuint texture : ctx.masks)
        if (texture) gl.DeleteTextures(1, &texture);
    // The host may have deleted the output it was handed (and reused the name).
    if (owned_output_alive(ctx)) gl.DeleteTextures(1, &ctx.output);
    if (ctx.timers) gl.DeleteQueries(ssao_context::kFrames * ssao_context::kStamps, &ctx.queries[0][0]);
}

}  // namespace ssao_impl
