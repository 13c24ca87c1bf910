// pass_table.h - one row per pass: everything the library says about a pass
// outside the planner that decides when it runs. The row gives its debug-group
// name, its public ssao_pass bit, the ssao_timings figure its GPU time adds
// to, and the program it draws with (shader file, shared code, label). No GL
// here: the planner, the program cache, the runner and the timers read it.
//
// Adding a pass: a PassKind (plan.h), its bit in ssao_pass (ssao.h), its row
// below (pass_table.cpp); if it draws with a new program, a ProgramId and its
// shader in shaders/ (listed in shaders/CMakeLists.txt); then plan_frame
// emits it. The resources, the runner, the timers and the debug groups follow
// the plan and need no change.
#pragma once

#include "plan.h"
#include "shader_source.h"

#include <cstdint>

namespace ssao_impl {

// Which of ssao_timings' two summary figures a pass's GPU time adds to.
enum class TimingBucket { ao_ms, blur_ms };

// The program a pass draws with (none: the clear pass draws nothing).
struct ProgramInfo {
    ProgramId id;
    const char* fragment_source;  // the embedded shader (after the constants header and `shared`)
    SharedCode shared;
    const char* file_name;        // the shader file: compile errors name it
    const char* label;            // glObjectLabel name
    uint32_t base_variant;        // what create_context compiles: the variant every plan needs (plan.h variant)
};

struct PassInfo {
    PassKind kind;
    const char* debug_group;  // the KHR_debug group around the pass ("ssao: kernel", ...)
    uint32_t bit;             // its ssao_pass bit: ssao_output.passes_run, ssao_timings.pass_kind
    TimingBucket bucket;
    ProgramInfo program;
};

// The row of `kind` (kind != count).
const PassInfo& pass_info(PassKind kind);

// The row of the first pass that draws with `id`, or the sky fill's own
// (id != none).
const ProgramInfo& program_info(ProgramId id);

inline ProgramId program_of(PassKind kind) { return pass_info(kind).program.id; }

}  // namespace ssao_impl
