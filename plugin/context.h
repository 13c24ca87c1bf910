// context.h - the opaque ssao_context: the GL function table, the compiled
// programs, the GL objects, the resolved settings and the timer ring.
#pragma once

#include "gl_state_guard.h"
#include "projection.h"
#include "uniforms.h"

#include <ssao/ssao.h>

#include <glad/gl.h>

#include <string>

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
    bool kernel_dirty = true;   // kernel / noise need uploading

    GLuint program_ao = 0, program_visibility = 0, program_blur = 0;
    // Per-pass uniforms of each program (program state, not the host's).
    struct PassUniforms {
        GLint target_origin = -1, pack_depth = -1;
    } ao_uniforms, visibility_uniforms, blur_uniforms;
    GLint blur_dir_location = -1;
    GLuint vao = 0, fbo = 0, ubo_frame = 0, ubo_kernel = 0, noise_texture = 0, sampler = 0;

    // Intermediate (RG32F: AO and view z) textures and the plugin-owned output, viewport-sized.
    GLuint temp[2] = {0, 0};
    int temp_width = 0, temp_height = 0;
    GLuint output = 0;
    int output_width = 0, output_height = 0;
    ssao_output_format output_format = SSAO_OUTPUT_DEFAULT;

    // Timestamp queries: kFrames frames in flight, kStamps per frame.
    static constexpr int kFrames = 8, kStamps = 3;  // a CPU up to 8 frames ahead is still measured
    GLuint queries[kFrames][kStamps] = {};
    uint64_t query_frame[kFrames] = {};  // which execute filled the slot; 0 = empty
    bool timers = false;
    ssao_timings timings{};
    uint64_t frame = 0;

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
void collect_timings(ssao_context& ctx);

}  // namespace ssao_impl
