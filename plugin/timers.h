// timers.h - GPU times from timestamp queries, never waited for: a ring of
// ssao_context::kFrames slots, each with one stamp before the first pass and
// one after each pass of that frame's plan.
#pragma once

#include "plan.h"

struct ssao_context;

namespace ssao_impl {

// Starts measuring execute number ctx.executes running `plan`: reads
// finished slots first, and returns the slot to stamp (-1: no timers, or no
// free slot; a slot is reused only once its results were read) after
// stamping it once.
int begin_timed_frame(ssao_context& ctx, const FramePlan& plan);
// The stamp after pass `pass` of the slot's plan.
void stamp_pass(ssao_context& ctx, int slot, int pass);
// Marks the slot as waiting for its results.
void end_timed_frame(ssao_context& ctx, int slot);
// Moves every completed frame's results into ctx.timings, oldest first.
void collect_timings(ssao_context& ctx);

}  // namespace ssao_impl
