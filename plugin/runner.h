// runner.h - executes a FramePlan: pipeline state, then per pass its debug
// group, input bindings, target, program and uniforms, the draw (or the
// clear), and one timestamp after it. Knows no pass by name: everything it
// does comes from the plan.
#pragma once

#include "plan.h"
#include "resources.h"

struct ssao_context;

namespace ssao_impl {

// Runs `plan` (the frame block uploaded, the resources updated; the depth
// and normal textures bound on their units by inspect_textures).
void run_plan(ssao_context& ctx, const FramePlan& plan, const PlanTextures& textures);

}  // namespace ssao_impl
