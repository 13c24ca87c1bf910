// context.h - the opaque ssao_context: the GL function table, the compiled
// programs, the GL objects, the resolved settings and the timer ring.
// execute (execute.cpp) runs: check_inputs / inspect_textures (inputs.cpp) ->
// plan_frame (plan.cpp, pure) -> compile_plan_programs (program_cache.cpp) ->
// update_resources (resources.cpp) -> constants (constants.cpp) -> run_plan
// (runner.cpp, with timers.cpp and the debug groups of debug.cpp).
#pragma once

#include "constants.h"
#include "debug.h"
#include "gl_state_guard.h"
#include "plan.h"
#include "program_cache.h"
#include "projection.h"
#include "uniforms.h"

#include <ssao/ssao.h>

#include <glad/gl.h>

#include <string>
#include <vector>

struct ssao_context {
    GladGLContext gl{};
    bool gl_ready = false;      // every required GL function was loaded
    ssao_impl::GlCaps caps;
    ssao_log_fn log = nullptr;
    void* log_user = nullptr;
    mutable std::string last_error;  // const getters report their failures too

    ssao_settings settings{};   // resolved
    SsaoFrame last_frame{};     // the frame block last uploaded
    bool frame_uploaded = false;
    // The settings the kernel block and noise texture were last made from.
    ssao_impl::KernelKey kernel_uploaded_for;
    bool kernel_uploaded = false;
    // The target the last successful execute's inputs had (GL_TEXTURE_2D or
    // GL_TEXTURE_2D_MULTISAMPLE). Below GL 4.5 inputs are told apart by
    // binding them, and that target is tried first: a host that keeps
    // multisampled inputs raises no failed-bind GL error frame after frame.
    GLenum last_input_target = GL_TEXTURE_2D;

    // The compiled programs (program_cache.cpp): each ProgramId's base
    // variant first, then each variant a plan has used.
    std::vector<ssao_impl::CompiledProgram> programs;
    GLuint vao = 0, fbo = 0, ubo_frame = 0, ubo_kernel = 0, noise_texture = 0, sampler = 0;
    // The framebuffer the host's depth is copied from (runner.cpp,
    // DepthUse::depth_copy); its read buffer is set to none at its first bind.
    GLuint read_fbo = 0;
    bool read_fbo_ready = false;
    // The vertex array's label, unique in the process (empty without
    // KHR_debug): how execute recognises the creating GL context
    // (context_identity.cpp). The output texture's label carries the same
    // number, so a second context's output is never taken for this one's.
    std::string vao_label;
    std::string output_label;

    // The plan's intermediate textures, each with the size and format it was
    // last allocated at, and the plugin-owned output (resources.cpp). They
    // are reallocated only when the plan's needs change.
    GLuint intermediates[ssao_impl::kMaxIntermediates] = {};
    ssao_impl::Intermediate intermediate_specs[ssao_impl::kMaxIntermediates] = {};
    // The plan's sky masks (depth textures), kept the same way.
    GLuint masks[ssao_impl::kMaxMasks] = {};
    ssao_impl::Intermediate mask_specs[ssao_impl::kMaxMasks] = {};
    GLuint output = 0;
    int output_width = 0, output_height = 0;
    ssao_impl::TexFormat output_format = ssao_impl::TexFormat::r8;

    // Timestamp queries (timers.cpp): kFrames frames in flight, one stamp
    // before the first pass and one after each pass.
    static constexpr int kFrames = 8, kStamps = ssao_impl::kMaxPasses + 1;  // a CPU up to 8 frames ahead is still measured
    GLuint queries[kFrames][kStamps] = {};
    uint64_t query_frame[kFrames] = {};  // which execute filled the slot; 0 = empty
    struct TimedPasses {
        int count = 0;
        ssao_impl::PassKind kinds[ssao_impl::kMaxPasses] = {};
    } query_passes[kFrames];             // the passes the slot's stamps follow
    bool query_labelled[kFrames][kStamps] = {};
    bool timers = false;
    ssao_timings timings{};
    uint64_t executes = 0;  // executes that ran their plan: ssao_timings.frame numbers them

    // KHR_debug (debug.cpp): groups and labels, or nothing without it.
    ssao_impl::DebugState debug;

    ssao_frame_info info{};

    // Records an error for last_error and the log callback; returns `status`.
    ssao_status fail(ssao_status status, const std::string& message) const;
};

namespace ssao_impl {

// Creation: loads GL and makes every GL object. On failure returns the status
// with ctx.last_error set; the caller destroys the partial context.
ssao_status initialise(ssao_context& ctx, const ssao_context_desc& desc);
void release(ssao_context& ctx);
ssao_status execute(ssao_context& ctx, const ssao_inputs& inputs, ssao_output* out);

}  // namespace ssao_impl
