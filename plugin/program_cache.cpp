// program_cache.cpp - compiling and linking the pass programs and their
// variants; the context keeps them in ctx.programs.
#include "program_cache.h"

#include "context.h"
#include "debug.h"
#include "pass_table.h"
#include "shader_source.h"
#include "uniforms.h"

#include <string>
#include <vector>

namespace ssao_impl {

namespace {

// `files`: the file of each source-string number of `source`, named in the
// error so that the driver's "N:LINE" can be read.
bool compile(ssao_context& ctx, GLenum type, const std::string& source, const char* name,
             const std::vector<const char*>& files, GLuint& out) {
    const GladGLContext& gl = ctx.gl;
    GLuint sh = gl.CreateShader(type);
    const char* src = source.c_str();
    gl.ShaderSource(sh, 1, &src, nullptr);
    gl.CompileShader(sh);
    GLint ok = 0;
    gl.GetShaderiv(sh, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        gl.GetShaderInfoLog(sh, sizeof log, nullptr, log);
        gl.DeleteShader(sh);
        ctx.fail(SSAO_ERROR_SHADER, compile_error_message(name, files, log));
        return false;
    }
    out = sh;
    return true;
}

// Points the program's samplers at their texture units. With GL 4.1's
// glProgramUniform the host's current program is never touched. Without it
// the program is made current for the calls; a host program flagged for
// deletion is deleted by that and cannot be made current again (restoring
// its name would raise GL_INVALID_VALUE and leave ours current), so then 0 is.
void set_sampler_units(const GladGLContext& gl, GLuint program) {
    const struct { const char* name; int unit; } samplers[] = {
        {"u_depth_tex", SSAO_UNIT_DEPTH}, {"u_normal_tex", SSAO_UNIT_NORMAL},
        {"u_noise_tex", SSAO_UNIT_NOISE}, {"u_ao_tex", SSAO_UNIT_AO}};
    if (gl.ProgramUniform1i) {
        for (const auto& s : samplers) {
            const GLint loc = gl.GetUniformLocation(program, s.name);
            if (loc >= 0) gl.ProgramUniform1i(program, loc, s.unit);
        }
        return;
    }
    GLint previous = 0;
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &previous);
    if (previous != 0) {
        GLint flagged = GL_FALSE;
        gl.GetProgramiv(static_cast<GLuint>(previous), GL_DELETE_STATUS, &flagged);
        if (flagged) previous = 0;
    }
    gl.UseProgram(program);
    for (const auto& s : samplers) {
        const GLint loc = gl.GetUniformLocation(program, s.name);
        if (loc >= 0) gl.Uniform1i(loc, s.unit);
    }
    gl.UseProgram(static_cast<GLuint>(previous));
}

ssao_status link(ssao_context& ctx, const std::string& fragment, const char* name,
                 const std::vector<const char*>& fragment_files, GLuint& program) {
    const GladGLContext& gl = ctx.gl;
    GLuint vs = 0, fs = 0;
    if (!compile(ctx, GL_VERTEX_SHADER, vertex_source(), "fullscreen.vert", vertex_files(), vs))
        return SSAO_ERROR_SHADER;
    if (!compile(ctx, GL_FRAGMENT_SHADER, fragment, name, fragment_files, fs)) {
        gl.DeleteShader(vs);
        return SSAO_ERROR_SHADER;
    }
    program = gl.CreateProgram();
    gl.AttachShader(program, vs);
    gl.AttachShader(program, fs);
    gl.LinkProgram(program);
    gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    GLint ok = 0;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[4096] = {};
        gl.GetProgramInfoLog(program, sizeof log, nullptr, log);
        return ctx.fail(SSAO_ERROR_SHADER, std::string("program ") + name + " failed to link: " + log);
    }
    // GLSL 3.30 has no layout(binding): bind blocks and samplers here, once.
    const GLuint frame_block = gl.GetUniformBlockIndex(program, "SsaoFrame");
    if (frame_block != GL_INVALID_INDEX) gl.UniformBlockBinding(program, frame_block, SSAO_UBO_FRAME);
    const GLuint kernel_block = gl.GetUniformBlockIndex(program, "SsaoKernel");
    if (kernel_block != GL_INVALID_INDEX) gl.UniformBlockBinding(program, kernel_block, SSAO_UBO_KERNEL);
    set_sampler_units(gl, program);
    return SSAO_OK;
}

// Compiles, links and labels one (program, variant) and appends it.
ssao_status add_program(ssao_context& ctx, ProgramId id, uint32_t variant) {
    const ProgramInfo& info = program_info(id);
    std::string name = info.file_name;
    for (int bit = 0; bit < variant::kBits; ++bit)
        if (variant & (1u << bit)) name += std::string(" +") + variant_name(bit);
    CompiledProgram compiled;
    compiled.id = id;
    compiled.variant = variant;
    // Room first: a push_back that throws after linking would leak the program.
    ctx.programs.reserve(ctx.programs.size() + 1);
    const ssao_status st = link(ctx, fragment_source(id, variant), name.c_str(), fragment_files(id), compiled.program);
    if (st != SSAO_OK) {
        if (compiled.program) ctx.gl.DeleteProgram(compiled.program);
        compiled.program = 0;
        compiled.failed = true;
        ctx.programs.push_back(compiled);
        return st;
    }
    label_object(ctx, GL_PROGRAM, compiled.program, info.label);
    compiled.uniforms = find_pass_uniforms(ctx.gl, compiled.program);
    ctx.programs.push_back(compiled);
    return SSAO_OK;
}

const CompiledProgram* find(const ssao_context& ctx, ProgramId id, uint32_t variant) {
    for (const CompiledProgram& p : ctx.programs)
        if (p.id == id && p.variant == variant) return &p;
    return nullptr;
}

}  // namespace

ssao_status compile_base_programs(ssao_context& ctx) {
    for (int i = 0; i < static_cast<int>(ProgramId::count); ++i) {
        // The debug views' program waits for the first plan that uses one:
        // a context that never shows a view never compiles it.
        const ProgramId id = static_cast<ProgramId>(i);
        if (id == ProgramId::normals_view) continue;
        // A software rasteriser clears the sky instead (plan.h SkyFill).
        if (id == ProgramId::sky_fill && ctx.caps.software_rasterizer) continue;
        const ssao_status st = add_program(ctx, id, program_info(id).base_variant);
        if (st != SSAO_OK) return st;
    }
    return SSAO_OK;
}

ssao_status compile_plan_programs(ssao_context& ctx, const FramePlan& plan) {
    for (int i = 0; i < plan.pass_count; ++i) {
        const Pass& pass = plan.passes[i];
        const ProgramId program = program_of(pass.kind);
        if (program == ProgramId::none) continue;
        if (const CompiledProgram* known = find(ctx, program, pass.variant)) {
            if (known->failed)
                return ctx.fail(SSAO_ERROR_SHADER, std::string("program ") + program_info(program).file_name +
                                                       " (variant " + std::to_string(pass.variant) +
                                                       ") failed to compile on an earlier execute; it is not retried");
            continue;
        }
        const ssao_status st = add_program(ctx, program, pass.variant);
        if (st != SSAO_OK) return st;
    }
    return SSAO_OK;
}

const CompiledProgram& program_for(const ssao_context& ctx, const Pass& pass) {
    const CompiledProgram* p = find(ctx, program_of(pass.kind), pass.variant);
    return p ? *p : ctx.programs.front();  // compile_plan_programs ran: always found
}

const CompiledProgram& sky_fill_program(const ssao_context& ctx) {
    const CompiledProgram* p = find(ctx, ProgramId::sky_fill, 0);
    return p ? *p : ctx.programs.front();  // compile_base_programs ran: always found
}

void delete_programs(ssao_context& ctx) {
    for (const CompiledProgram& p : ctx.programs)
        if (p.program) ctx.gl.DeleteProgram(p.program);
    ctx.programs.clear();
}

}  // namespace ssao_impl
