// runner.h - executes a FramePlan: pipeline state, the uniform blocks,
// then per pass its debug group, input bindings, targets, program and
// uniforms, the draw (or the clear), and one timestamp after it. Knows no
// pass by name and assumes nothing bound: everything it binds comes from the
// plan and the resolved textures.
#pragma once

#include "gl_state_guard.h"
#include "plan.h"
#include "resources.h"

struct ssao_context;

namespace ssao_impl {

// Runs `plan` into `framebuffer` (the constants uploaded, the resources
// updated and resolved in `textures`); `guard` saves the blend function
// before a pass multiplies into the output.
void run_plan(ssao_context& ctx, const FramePlan& plan, const PlanTextures& textures, TargetFramebuffer& framebuffer,
              GlStateGuard& guard);

}  // namespace ssao_impl
