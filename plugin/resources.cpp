// resources.cpp - allocation of the plan's textures and the framebuffer
// they are attached to.
#include "resources.h"

#include "context.h"
#include "gl_state_guard.h"

#include <string>

namespace ssao_impl {

namespace {

struct GlFormat {
    GLenum internal, format, type;
};

GlFormat gl_format(TexFormat f) {
    switch (f) {
        case TexFormat::rg32f: return {GL_RG32F, GL_RG, GL_FLOAT};
        case TexFormat::rgba32f: return {GL_RGBA32F, GL_RGBA, GL_FLOAT};
        case TexFormat::r16f: return {GL_R16F, GL_RED, GL_FLOAT};
        case TexFormat::r8: return {GL_R8, GL_RED, GL_UNSIGNED_BYTE};
        case TexFormat::rgba8: return {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE};
        case TexFormat::d16: return {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT};
        case TexFormat::d24: return {GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT};
        case TexFormat::d24s8: return {GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8};
        case TexFormat::d32f: return {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT};
        case TexFormat::d32fs8: return {GL_DEPTH32F_STENCIL8, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV};
    }
    return {GL_R8, GL_RED, GL_UNSIGNED_BYTE};
}

// (Re)specifies level 0 of `tex` (made on first use and labelled then).
void allocate(const ssao_context& ctx, GLuint& tex, TexFormat format, int w, int h, const char* label) {
    const GladGLContext& gl = ctx.gl;
    const bool made = tex == 0;
    if (made) gl.GenTextures(1, &tex);
    gl.BindTexture(GL_TEXTURE_2D, tex);
    if (made) label_object(ctx, GL_TEXTURE, tex, label);
    const GlFormat f = gl_format(format);
    // Re-specifying level 0 reallocates in place: no new name, nothing leaks.
    gl.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(f.internal), w, h, 0, f.format, f.type, nullptr);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
}

// Whether texture `tex`, last allocated as `have`, must be made (again) as `want`.
bool stale(GLuint tex, const Intermediate& have, const Intermediate& want) {
    return tex == 0 || have.width != want.width || have.height != want.height || have.format != want.format;
}

bool output_stale(const ssao_context& ctx, const FramePlan& plan) {
    return plan.owned_output && (ctx.output == 0 || ctx.output_width != plan.output_width ||
                                 ctx.output_height != plan.output_height || ctx.output_format != plan.output_format);
}

const char* const kIntermediateLabels[kMaxIntermediates] = {"ssao: intermediate 0", "ssao: intermediate 1",
                                                            "ssao: intermediate 2", "ssao: intermediate 3"};
const char* const kMaskLabels[kMaxMasks] = {"ssao: sky mask 0", "ssao: sky mask 1"};

// Whether update_resources will (re)allocate anything for `plan`.
bool resources_stale(const ssao_context& ctx, const FramePlan& plan) {
    for (int i = 0; i < plan.intermediate_count; ++i)
        if (stale(ctx.intermediates[i], ctx.intermediate_specs[i], plan.intermediates[i])) return true;
    for (int i = 0; i < plan.mask_count; ++i)
        if (stale(ctx.masks[i], ctx.mask_specs[i], plan.masks[i])) return true;
    return output_stale(ctx, plan);
}

// Forgets an output texture the host deleted (owned_output_alive false), so
// it is made again; the name is not deleted, it is not the library's any more.
void forget_deleted_output(ssao_context& ctx) {
    if (ctx.output == 0 || owned_output_alive(ctx)) return;
    ctx.output = 0;
    ctx.output_width = ctx.output_height = 0;
}

// Default unpack state for the library's uploads (the guard restores the host's).
void reset_unpack(const GladGLContext& gl) {
    gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    gl.PixelStorei(GL_UNPACK_SWAP_BYTES, 0);
    gl.PixelStorei(GL_UNPACK_LSB_FIRST, 0);
    gl.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    gl.PixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    gl.PixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    gl.PixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    gl.PixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
}

// The plan's intermediates and owned output at the size and format it asks
// for. Returns whether the owned output was (re)made.
bool allocate_stale(ssao_context& ctx, const FramePlan& plan, GlStateGuard& guard) {
    if (!resources_stale(ctx, plan)) return false;
    const GladGLContext& gl = ctx.gl;
    use_default_unpack(gl, guard);
    gl.ActiveTexture(GL_TEXTURE0 + SSAO_UNIT_AO);
    for (int i = 0; i < plan.intermediate_count; ++i) {
        const Intermediate& want = plan.intermediates[i];
        if (!stale(ctx.intermediates[i], ctx.intermediate_specs[i], want)) continue;
        allocate(ctx, ctx.intermediates[i], want.format, want.width, want.height, kIntermediateLabels[i]);
        ctx.intermediate_specs[i] = want;
    }
    for (int i = 0; i < plan.mask_count; ++i) {
        const Intermediate& want = plan.masks[i];
        if (!stale(ctx.masks[i], ctx.mask_specs[i], want)) continue;
        allocate(ctx, ctx.masks[i], want.format, want.width, want.height, kMaskLabels[i]);
        ctx.mask_specs[i] = want;
    }
    if (!output_stale(ctx, plan)) return false;
    allocate(ctx, ctx.output, plan.output_format, plan.output_width, plan.output_height, ctx.output_label.c_str());
    ctx.output_width = plan.output_width;
    ctx.output_height = plan.output_height;
    ctx.output_format = plan.output_format;
    return true;
}

}  // namespace

TargetFramebuffer::TargetFramebuffer(ssao_context& ctx) : gl_(ctx.gl) {
    gl_.BindFramebuffer(GL_FRAMEBUFFER, ctx.fbo);
    // A framebuffer exists only after its first bind: labelled then, once.
    if (!ctx.debug.objects_labelled) {
        label_object(ctx, GL_FRAMEBUFFER, ctx.fbo, kLabelFramebuffer);
        ctx.debug.objects_labelled = true;
    }
}

TargetFramebuffer::~TargetFramebuffer() { attach(0, 0, 0); }

void TargetFramebuffer::attach(GLuint colour0, GLuint colour1, GLuint depth) {
    static const GLenum one[1] = {GL_COLOR_ATTACHMENT0};
    static const GLenum two[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour0, 0);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, colour1, 0);
    gl_.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    // The draw-buffer list is the library's framebuffer's own state, not the host's.
    gl_.DrawBuffers(colour1 != 0 ? 2 : 1, colour1 != 0 ? two : one);
}

bool TargetFramebuffer::complete() const {
    return gl_.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
}

GLuint PlanTextures::resolve(const TexRef& ref) const {
    switch (ref.source) {
        case TexRef::Source::none: return 0;
        case TexRef::Source::depth: return depth;
        case TexRef::Source::normal: return normal;
        case TexRef::Source::noise: return noise;
        case TexRef::Source::intermediate: return intermediates[ref.index];
        case TexRef::Source::mask: return masks[ref.index];
        case TexRef::Source::output: return output;
    }
    return 0;
}

GLenum PlanTextures::target_of(const TexRef& ref) const {
    const bool host_input = ref.source == TexRef::Source::depth || ref.source == TexRef::Source::normal;
    return host_input ? input_target : GLenum(GL_TEXTURE_2D);
}

bool owned_output_alive(const ssao_context& ctx) {
    return ctx.output != 0 && ctx.gl.IsTexture(ctx.output) &&
           has_label(ctx, GL_TEXTURE, ctx.output, ctx.output_label.c_str());
}

ssao_status check_host_output(const ssao_context& ctx, const AnalysedInputs& in, TargetFramebuffer& framebuffer) {
    if (in.output_texture == 0) return SSAO_OK;
    framebuffer.attach(in.output_texture);
    if (!framebuffer.complete())
        return ctx.fail(SSAO_ERROR_UNSUPPORTED_FORMAT, "inputs.output_texture is not colour-renderable");
    return SSAO_OK;
}

ssao_status update_resources(ssao_context& ctx, const FramePlan& plan, const AnalysedInputs& in, GlStateGuard& guard,
                             TargetFramebuffer& framebuffer, PlanTextures& out) {
    if (plan.owned_output) forget_deleted_output(ctx);
    const bool new_output = allocate_stale(ctx, plan, guard);

    out.depth = in.depth_texture;
    out.normal = in.normal_texture;
    out.input_target = in.multisample ? GLenum(GL_TEXTURE_2D_MULTISAMPLE) : GLenum(GL_TEXTURE_2D);
    out.noise = ctx.noise_texture;
    out.output = plan.owned_output ? ctx.output : in.output_texture;
    for (int i = 0; i < kMaxIntermediates; ++i) out.intermediates[i] = ctx.intermediates[i];
    for (int i = 0; i < kMaxMasks; ++i) out.masks[i] = ctx.masks[i];

    if (new_output) {
        framebuffer.attach(out.output);
        if (!framebuffer.complete())
            return ctx.fail(SSAO_ERROR_FRAMEBUFFER, "the library's output framebuffer is incomplete");
    }
    return SSAO_OK;
}

void use_default_unpack(const GladGLContext& gl, GlStateGuard& guard) {
    guard.save_unpack_state();
    reset_unpack(gl);
}

}  // namespace ssao_impl
