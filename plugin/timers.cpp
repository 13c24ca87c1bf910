// timers.cpp - the timestamp ring and the per-pass times of ssao_timings.
#include "timers.h"

#include "context.h"
#include "pass_table.h"

namespace ssao_impl {

namespace {

void stamp(ssao_context& ctx, int slot, int index) {
    const GLuint query = ctx.queries[slot][index];
    ctx.gl.QueryCounter(query, GL_TIMESTAMP);
    // A query object exists only once used: label it then, once.
    if (!ctx.query_labelled[slot][index]) {
        label_object(ctx, GL_QUERY, query, kLabelTimer);
        ctx.query_labelled[slot][index] = true;
    }
}

}  // namespace

int begin_timed_frame(ssao_context& ctx, const FramePlan& plan) {
    collect_timings(ctx);
    if (!ctx.timers) return -1;
    const int slot = static_cast<int>(ctx.executes % ssao_context::kFrames);
    if (ctx.query_frame[slot] != 0) return -1;
    ssao_context::TimedPasses& passes = ctx.query_passes[slot];
    passes.count = plan.pass_count;
    for (int i = 0; i < plan.pass_count; ++i) passes.kinds[i] = plan.passes[i].kind;
    stamp(ctx, slot, 0);
    return slot;
}

void stamp_pass(ssao_context& ctx, int slot, int pass) {
    if (slot >= 0) stamp(ctx, slot, pass + 1);
}

void end_timed_frame(ssao_context& ctx, int slot) {
    if (slot >= 0) ctx.query_frame[slot] = ctx.executes;
}

void collect_timings(ssao_context& ctx) {
    if (!ctx.timers) return;
    const GladGLContext& gl = ctx.gl;
    const QueryBufferUnbound results_to_memory(gl, ctx.caps);
    // Oldest first, so the newest completed frame wins.
    for (;;) {
        int oldest = -1;
        for (int s = 0; s < ssao_context::kFrames; ++s)
            if (ctx.query_frame[s] != 0 && (oldest < 0 || ctx.query_frame[s] < ctx.query_frame[oldest])) oldest = s;
        if (oldest < 0) return;
        const ssao_context::TimedPasses& passes = ctx.query_passes[oldest];
        GLuint available = 0;
        gl.GetQueryObjectuiv(ctx.queries[oldest][passes.count], GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return;  // never wait: later frames cannot be done either
        GLuint64 t[ssao_context::kStamps] = {};
        for (int i = 0; i <= passes.count; ++i)
            gl.GetQueryObjectui64v(ctx.queries[oldest][i], GL_QUERY_RESULT, &t[i]);
        ssao_timings& out = ctx.timings;
        out = ssao_timings{};
        out.available = 1;
        out.frame = ctx.query_frame[oldest];
        out.pass_count = static_cast<uint32_t>(passes.count);
        for (int i = 0; i < passes.count; ++i) {
            const double ms = static_cast<double>(t[i + 1] - t[i]) * 1e-6;
            const PassInfo& pass = pass_info(passes.kinds[i]);
            out.pass_kind[i] = pass.bit;
            out.pass_ms[i] = ms;
            (pass.bucket == TimingBucket::blur_ms ? out.blur_ms : out.ao_ms) += ms;
        }
        out.total_ms = static_cast<double>(t[passes.count] - t[0]) * 1e-6;
        ctx.query_frame[oldest] = 0;
    }
}

}  // namespace ssao_impl
