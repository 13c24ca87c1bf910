// program_cache.h - the compiled pass programs: each ProgramId's base variant
// (pass_table.cpp) at create_context (so a driver that cannot compile the shaders fails
// there), and each other variant the first time a plan asks for it (plan.h,
// namespace variant), kept until destroy_context.
#pragma once

#include "plan.h"
#include "pass_uniforms.h"

#include <ssao/ssao.h>

#include <glad/gl.h>

#include <cstdint>

struct ssao_context;

namespace ssao_impl {

struct CompiledProgram {
    ProgramId id = ProgramId::none;
    uint32_t variant = 0;
    GLuint program = 0;
    PassUniforms uniforms;
    // It failed to compile or link (program 0): kept so that later frames
    // return SHADER at once instead of compiling it again every execute.
    bool failed = false;
};

// create_context: the base variant of every program but the debug views' (compiled
// on first use, like the variants) and, on a software rasteriser, the sky
// fill's. SHADER (last_error holds the
// driver's log) when one fails.
ssao_status compile_base_programs(ssao_context& ctx);

// execute, after planning: every (program, variant) the plan runs. SHADER
// when one fails to compile (then, or on an earlier execute: a failed variant
// is not compiled again); OUT_OF_MEMORY is left to the caller's guard.
ssao_status compile_plan_programs(ssao_context& ctx, const FramePlan& plan);

// The compiled program of a pass (compile_plan_programs ran for its plan).
const CompiledProgram& program_for(const ssao_context& ctx, const Pass& pass);

// The sky fill's program (compiled at create_context where the renderer is
// not a software rasteriser: plans draw it only there).
const CompiledProgram& sky_fill_program(const ssao_context& ctx);

// destroy_context: deletes them all.
void delete_programs(ssao_context& ctx);

}  // namespace ssao_impl
