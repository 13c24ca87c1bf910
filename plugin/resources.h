// resources.h - the textures a plan renders into: its intermediates and the
// plugin-owned output, (re)allocated only when the plan's needs change
// (never freed when a plan needs fewer: a later frame will want them again;
// destroy_context deletes them).
#pragma once

#include "plan.h"

#include <glad/gl.h>

struct ssao_context;

namespace ssao_impl {

// The GL name behind every TexRef of one frame's plan.
struct PlanTextures {
    GLuint depth = 0, normal = 0, noise = 0, output = 0;
    GLuint intermediates[kMaxIntermediates] = {};
    // (1.2) The target of the host's depth and normal: GL_TEXTURE_2D or
    // GL_TEXTURE_2D_MULTISAMPLE. Everything of the library's is GL_TEXTURE_2D.
    GLenum input_target = GL_TEXTURE_2D;
    GLuint resolve(const TexRef& ref) const;
    GLenum target_of(const TexRef& ref) const;
};

// Whether ctx.output still names the library's output texture: the host may
// have deleted it (glIsTexture false), and a texture of the host's may have
// taken the name since (its label is not this context's "ssao: output <n>"; told apart only with
// KHR_debug). Queries only.
bool owned_output_alive(const ssao_context& ctx);

// Forgets an output texture the host deleted (owned_output_alive false), so
// the next update_resources makes a new one; the name is not deleted, it is
// not the library's any more.
void forget_deleted_output(ssao_context& ctx);

// Whether update_resources will (re)allocate anything for `plan`.
bool resources_stale(const ssao_context& ctx, const FramePlan& plan);

// Allocates what `plan` needs and does not have yet (on SSAO_UNIT_AO, with
// the default unpack state set by the caller: reset_unpack). When the owned
// output was (re)allocated its framebuffer completeness is checked:
// SSAO_ERROR_FRAMEBUFFER when incomplete. Leaves the final output attached to
// the library's framebuffer (bound).
ssao_status update_resources(ssao_context& ctx, const FramePlan& plan, const AnalysedInputs& in, PlanTextures& out);

// Default unpack state for the library's uploads (after the guard saved the host's).
void reset_unpack(const GladGLContext& gl);

}  // namespace ssao_impl
