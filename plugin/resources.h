// resources.h - the textures a plan renders into: its intermediates, its sky
// masks (depth textures the passes test) and the plugin-owned output, (re)allocated only when the plan's needs change
// (never freed when a plan needs fewer: a later frame will want them again;
// destroy_context deletes them), and the library's framebuffer they are
// attached to: the one owner of attachments and completeness.
#pragma once

#include "plan.h"

#include <glad/gl.h>

struct ssao_context;

namespace ssao_impl {

class GlStateGuard;

// The library's framebuffer during one execute: bound from construction, with
// the colour targets attach() names; on destruction (every way out of
// execute) nothing is left attached, so it never keeps a host texture alive.
// Declare it after the GlStateGuard: it is destroyed first, while its
// framebuffer is still bound.
class TargetFramebuffer {
public:
    explicit TargetFramebuffer(ssao_context& ctx);
    ~TargetFramebuffer();
    TargetFramebuffer(const TargetFramebuffer&) = delete;
    TargetFramebuffer& operator=(const TargetFramebuffer&) = delete;

    // `colour0` on attachment 0 and `colour1` (0: none) on attachment 1,
    // with the draw buffers to match: fragment outputs 0 and 1; `depth` (0:
    // none) on the depth attachment.
    void attach(GLuint colour0, GLuint colour1 = 0, GLuint depth = 0);
    bool complete() const;

private:
    const GladGLContext& gl_;
};

// The GL name behind every TexRef of one frame's plan.
struct PlanTextures {
    GLuint depth = 0, normal = 0, noise = 0, output = 0;
    GLuint intermediates[kMaxIntermediates] = {};
    GLuint masks[kMaxMasks] = {};
    // The target of the host's depth and normal: GL_TEXTURE_2D or
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

// Validation: the host's output texture (if any) is complete on the
// library's framebuffer, else UNSUPPORTED_FORMAT.
ssao_status check_host_output(const ssao_context& ctx, const AnalysedInputs& in, TargetFramebuffer& framebuffer);

// Makes what `plan` needs and does not have yet, and resolves its textures
// into `out`. An owned output the host deleted is forgotten and made again.
// Allocations happen on SSAO_UNIT_AO with the default unpack state
// (the guard saves the host's first); a new owned output found incomplete is
// SSAO_ERROR_FRAMEBUFFER.
ssao_status update_resources(ssao_context& ctx, const FramePlan& plan, const AnalysedInputs& in, GlStateGuard& guard,
                             TargetFramebuffer& framebuffer, PlanTextures& out);

// Saves the host's unpack state in `guard` and sets the default one for the
// library's uploads.
void use_default_unpack(const GladGLContext& gl, GlStateGuard& guard);

}  // namespace ssao_impl
