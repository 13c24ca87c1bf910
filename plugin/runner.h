// runner.h - executes a FramePlan: pipeline state, the uniform blocks,
// then per pass its debug group, input bindings, targets, program and
// uniforms, the draw (or the clear), and one timestamp after it. Knows no
// pass by name and assumes nothing bound: everything it binds comes from the
// plan and the resolved textures.
#pragma once

#include "plan.h"
#include "resources.h"

struct ssao_context;

namespace ssao_impl {

// Runs `plan` into `framebuffer` (the constants uploaded, the resources
// updated and resolved in `textures`).
void run_plan(ssao_context& ctx, const FramePlan& plan, const PlanTextures& textures, TargetFramebuffer& framebuffer);

}  // namespace ssao_impl
