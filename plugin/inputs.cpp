// inputs.cpp - validation and analysis of ssao_inputs: every refusal of the
// inputs happens here, before anything of the library's changes, so a
// refused call leaves the library's own output as it was.
#include "inputs.h"

#include "context.h"
#include "raw_enum.h"
#include "resources.h"

#include <cmath>
#include <string>

namespace ssao_impl {

namespace {

// What a texture name is, as far as can be told without binding it.
enum class TexKind {
    not_texture,  // 0 or no texture object
    tex_2d,       // GL_TEXTURE_2D
    tex_2d_ms,    // GL_TEXTURE_2D_MULTISAMPLE
    other,        // another target (GL 4.5 query)
    unknown,      // a texture; below GL 4.5 its target is found by binding it
};

// Without GL 4.5's GL_TEXTURE_TARGET query only "is a texture" can be checked
// without raising a GL error.
TexKind texture_kind(ssao_context& ctx, GLuint name) {
    if (name == 0 || !ctx.gl.IsTexture(name)) return TexKind::not_texture;
    if (!ctx.caps.texture_target_query) return TexKind::unknown;
    // A buffer texture has no GL_TEXTURE_TARGET to query (asking raises
    // GL_INVALID_OPERATION) but answers its level-0 buffer query: it has a
    // data store, which a GL_TEXTURE_2D(_MULTISAMPLE) never has.
    GLint store = 0;
    ctx.gl.GetTextureLevelParameteriv(name, 0, GL_TEXTURE_BUFFER_DATA_STORE_BINDING, &store);
    if (store != 0) return TexKind::other;
    GLint target = 0;
    ctx.gl.GetTextureParameteriv(name, GL_TEXTURE_TARGET, &target);
    if (target == GL_TEXTURE_2D) return TexKind::tex_2d;
    if (target == GL_TEXTURE_2D_MULTISAMPLE) return TexKind::tex_2d_ms;
    return TexKind::other;
}

// Binds `name` to `target` on `unit` and says whether it took: below GL 4.5
// a name of another target cannot be recognised beforehand, the bind then
// fails (raising GL_INVALID_OPERATION) and leaves the previous binding.
bool bind_on(const GladGLContext& gl, GLuint unit, GLenum target, GLuint name) {
    gl.ActiveTexture(GL_TEXTURE0 + unit);
    gl.BindTexture(target, name);
    GLint bound = 0;
    gl.GetIntegerv(target == GL_TEXTURE_2D ? GL_TEXTURE_BINDING_2D : GL_TEXTURE_BINDING_2D_MULTISAMPLE, &bound);
    return static_cast<GLuint>(bound) == name;
}

bool bind_2d(const GladGLContext& gl, GLuint unit, GLuint name) { return bind_on(gl, unit, GL_TEXTURE_2D, name); }

// Binds an input (depth or normal) on its target: GL_TEXTURE_2D or
// GL_TEXTURE_2D_MULTISAMPLE. Returns the target, or 0 when it is neither.
// With GL 4.5 the target is known; below, `likely` is tried first and each
// failed try raises GL_INVALID_OPERATION.
GLenum bind_input(ssao_context& ctx, GLuint unit, GLuint name, GLenum likely) {
    const TexKind kind = texture_kind(ctx, name);
    GLenum order[2] = {likely, likely == GL_TEXTURE_2D ? GLenum(GL_TEXTURE_2D_MULTISAMPLE) : GLenum(GL_TEXTURE_2D)};
    if (kind == TexKind::tex_2d) order[0] = order[1] = GL_TEXTURE_2D;
    if (kind == TexKind::tex_2d_ms) order[0] = order[1] = GL_TEXTURE_2D_MULTISAMPLE;
    if (bind_on(ctx.gl, unit, order[0], name)) return order[0];
    if (order[1] != order[0] && bind_on(ctx.gl, unit, order[1], name)) return order[1];
    return 0;
}

const char* target_name(GLenum target) {
    return target == GL_TEXTURE_2D_MULTISAMPLE ? "GL_TEXTURE_2D_MULTISAMPLE" : "GL_TEXTURE_2D";
}

// Is level 0 of the texture bound to `target` (on the active unit) of an
// integer format (GL_INT or GL_UNSIGNED_INT components)?
bool has_integer_format(const GladGLContext& gl, GLenum target = GL_TEXTURE_2D) {
    GLint red_type = 0;
    gl.GetTexLevelParameteriv(target, 0, GL_TEXTURE_RED_TYPE, &red_type);
    return red_type == GL_INT || red_type == GL_UNSIGNED_INT;
}

void level0_size(const GladGLContext& gl, int& w, int& h, GLenum target = GL_TEXTURE_2D) {
    gl.GetTexLevelParameteriv(target, 0, GL_TEXTURE_WIDTH, &w);
    gl.GetTexLevelParameteriv(target, 0, GL_TEXTURE_HEIGHT, &h);
}

// Sample count of the texture bound to `target` (0 for a single-sample one).
int sample_count(const GladGLContext& gl, GLenum target) {
    if (target != GL_TEXTURE_2D_MULTISAMPLE) return 0;
    GLint samples = 0;
    gl.GetTexLevelParameteriv(target, 0, GL_TEXTURE_SAMPLES, &samples);
    return samples;
}

// Every check of the normal texture, in one place: bound on SSAO_UNIT_NORMAL
// on the depth texture's target, with the depth texture's size and sample
// count, three non-integer channels.
ssao_status inspect_normal(ssao_context& ctx, GLuint name, GLenum depth_target, int dw, int dh, int depth_samples) {
    const GladGLContext& gl = ctx.gl;
    const GLenum target = bind_input(ctx, SSAO_UNIT_NORMAL, name, depth_target);
    if (target == 0)
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE,
                        "inputs.normal_texture is not a GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE (it did not bind)");
    if (target != depth_target)
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE,
                        std::string("inputs.depth_texture is a ") + target_name(depth_target) +
                            " but inputs.normal_texture is a " + target_name(target) +
                            ": both must be multisampled (with the same sample count) or both single-sample");
    const int samples = sample_count(gl, target);
    if (samples != depth_samples)
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.normal_texture has " + std::to_string(samples) +
                                                        " samples but the depth texture has " +
                                                        std::to_string(depth_samples) + "; they must match");
    int nw = 0, nh = 0;
    level0_size(gl, nw, nh, target);
    GLint red_bits = 0, blue_bits = 0;
    gl.GetTexLevelParameteriv(target, 0, GL_TEXTURE_RED_SIZE, &red_bits);
    gl.GetTexLevelParameteriv(target, 0, GL_TEXTURE_BLUE_SIZE, &blue_bits);
    if (nw != dw || nh != dh)
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.normal_texture is " + std::to_string(nw) + "x" +
                                                        std::to_string(nh) + " but the depth texture is " +
                                                        std::to_string(dw) + "x" + std::to_string(dh));
    if (red_bits <= 0 || blue_bits <= 0)
        return ctx.fail(SSAO_ERROR_UNSUPPORTED_FORMAT, "inputs.normal_texture needs three colour channels (x, y, z)");
    if (has_integer_format(gl, target))
        return ctx.fail(SSAO_ERROR_UNSUPPORTED_FORMAT,
                        "inputs.normal_texture has an integer format; a float, unorm or snorm one is needed");
    return SSAO_OK;
}

}  // namespace

ssao_status check_inputs(ssao_context& ctx, const ssao_inputs& in, AnalysedInputs& out) {
    // No normal texture: normals are rebuilt from depth, and what
    // describes the normal texture (space, packing, view matrix) is ignored.
    const bool from_depth = in.normal_texture == 0;
    // Raw bits first (raw_enum.h): a caller may store any 32-bit value.
    if (!from_depth && !raw_enum_at_most(in.normal_space, SSAO_NORMAL_SPACE_WORLD))
        return ctx.fail(SSAO_ERROR_INVALID_ENUM, "inputs.normal_space is not an ssao_normal_space");
    if (!from_depth && !raw_enum_at_most(in.normal_packing, SSAO_NORMAL_PACKING_SIGNED))
        return ctx.fail(SSAO_ERROR_INVALID_ENUM, "inputs.normal_packing is not an ssao_normal_packing");
    if (!raw_enum_at_most(in.clip_range, SSAO_CLIP_ZERO_TO_ONE))
        return ctx.fail(SSAO_ERROR_INVALID_ENUM, "inputs.clip_range is not an ssao_clip_range");
    if (!raw_enum_at_most(in.output_mode, SSAO_OUTPUT_MODE_MULTIPLY))
        return ctx.fail(SSAO_ERROR_INVALID_ENUM, "inputs.output_mode is not an ssao_output_mode");
    if (in.output_mode == SSAO_OUTPUT_MODE_MULTIPLY && in.output_texture == 0)
        return ctx.fail(SSAO_ERROR_INVALID_VALUE,
                        "inputs.output_mode is MULTIPLY but output_texture is 0 (multiply needs the host's lit image)");
    const bool world_normals = !from_depth && in.normal_space == SSAO_NORMAL_SPACE_WORLD;
    if (world_normals) {
        for (float v : in.view_matrix)
            if (!std::isfinite(v)) return ctx.fail(SSAO_ERROR_INVALID_VALUE, "inputs.view_matrix is not finite");
    }
    ProjectionInfo proj;
    std::string why;
    const ssao_status pst = analyse_projection(in.projection, in.clip_range, proj, why);
    if (pst != SSAO_OK) return ctx.fail(pst, "inputs.projection: " + why);
    if (in.depth_texture == 0) return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.depth_texture is 0");
    // Inputs: GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE; below GL 4.5
    // the target is found by binding (inspect_textures), which also checks
    // that depth and normal agree.
    const auto is_input_kind = [](TexKind k) {
        return k == TexKind::tex_2d || k == TexKind::tex_2d_ms || k == TexKind::unknown;
    };
    if (!is_input_kind(texture_kind(ctx, in.depth_texture)))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE,
                        "inputs.depth_texture is not the name of a GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE");
    if (!from_depth && !is_input_kind(texture_kind(ctx, in.normal_texture)))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE,
                        "inputs.normal_texture is not the name of a GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE");
    if (in.output_texture != 0) {
        const TexKind out_kind = texture_kind(ctx, in.output_texture);
        if (out_kind == TexKind::tex_2d_ms)
            return ctx.fail(SSAO_ERROR_INVALID_TEXTURE,
                            "inputs.output_texture is a GL_TEXTURE_2D_MULTISAMPLE; the output must be a GL_TEXTURE_2D");
        if (out_kind != TexKind::tex_2d && out_kind != TexKind::unknown)
            return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.output_texture is not the name of a GL_TEXTURE_2D");
    }
    if (in.output_texture != 0 && (in.output_texture == in.depth_texture || in.output_texture == in.normal_texture))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.output_texture is also an input (a feedback loop)");
    // With no output_texture the library writes (and may reallocate) its own.
    if (in.output_texture == 0 && ctx.output != 0 &&
        (ctx.output == in.depth_texture || (!from_depth && ctx.output == in.normal_texture)) && owned_output_alive(ctx))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE,
                        std::string(ctx.output == in.depth_texture ? "inputs.depth_texture" : "inputs.normal_texture") +
                            " is the library's own output texture, which this execute writes (a feedback loop)");

    out.proj = proj;
    out.world_normals = world_normals;
    out.normal_to_view = glm::dmat4(1.0);
    if (world_normals) {
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) out.normal_to_view[c][r] = in.view_matrix[c * 4 + r];
    }
    out.signed_normals = !from_depth && in.normal_packing == SSAO_NORMAL_PACKING_SIGNED;
    out.normals_from_depth = from_depth;
    out.frame_index = in.frame_index;  // any value is valid
    out.multiply_output = in.output_mode == SSAO_OUTPUT_MODE_MULTIPLY;
    return SSAO_OK;
}

ssao_status inspect_textures(ssao_context& ctx, const ssao_inputs& in, GlStateGuard& guard, AnalysedInputs& out) {
    const GladGLContext& gl = ctx.gl;
    // The last successful execute's target first: execute keeps it only when
    // the frame succeeds, so a refused call does not change which comes first.
    const GLenum target = bind_input(ctx, SSAO_UNIT_DEPTH, in.depth_texture, ctx.last_input_target);
    if (target == 0)
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE,
                        "inputs.depth_texture is not a GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE (it did not bind)");
    int dw = 0, dh = 0;
    level0_size(gl, dw, dh, target);
    const int samples = sample_count(gl, target);
    DepthFormat fmt;
    GLint depth_bits = 0, depth_type = 0, stencil_bits = 0;
    gl.GetTexLevelParameteriv(target, 0, GL_TEXTURE_DEPTH_SIZE, &depth_bits);
    gl.GetTexLevelParameteriv(target, 0, GL_TEXTURE_DEPTH_TYPE, &depth_type);
    gl.GetTexLevelParameteriv(target, 0, GL_TEXTURE_STENCIL_SIZE, &stencil_bits);
    fmt.bits = depth_bits;
    fmt.is_float = depth_type == GL_FLOAT;
    fmt.has_stencil = stencil_bits > 0;
    const bool supported = (fmt.bits == 16 && !fmt.is_float) || (fmt.bits == 24 && !fmt.is_float) ||
                           (fmt.bits == 32 && fmt.is_float);
    if (!supported)
        return ctx.fail(SSAO_ERROR_UNSUPPORTED_FORMAT,
                        "inputs.depth_texture has " + std::to_string(fmt.bits) + (fmt.is_float ? "-bit float" : "-bit") +
                            " depth; D16, D24, D24S8, D32F or D32FS8 is required");
    if (fmt.has_stencil) {
        guard.save_depth_stencil_mode(in.depth_texture, SSAO_UNIT_DEPTH, target);
        if (ctx.caps.depth_stencil_mode) gl.TexParameteri(target, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    }
    // Multisampled inputs: the sample read at every pixel must exist.
    if (samples > 0 && in.sample_index >= static_cast<uint32_t>(samples))
        return ctx.fail(SSAO_ERROR_INVALID_VALUE, "inputs.sample_index is " + std::to_string(in.sample_index) +
                                                      " but the inputs have " + std::to_string(samples) +
                                                      " samples (0.." + std::to_string(samples - 1) + ")");
    if (in.normal_texture != 0) {
        const ssao_status normal_status = inspect_normal(ctx, in.normal_texture, target, dw, dh, samples);
        if (normal_status != SSAO_OK) return normal_status;
    }

    int vx = in.viewport[0], vy = in.viewport[1], vw = in.viewport[2], vh = in.viewport[3];
    if (vx == 0 && vy == 0 && vw == 0 && vh == 0) { vw = dw; vh = dh; }
    if (vw <= 0 || vh <= 0 || vw > SSAO_MAX_DIMENSION || vh > SSAO_MAX_DIMENSION)
        return ctx.fail(SSAO_ERROR_INVALID_SIZE, "the viewport is " + std::to_string(vw) + "x" + std::to_string(vh) +
                                                     "; each side must be 1.." + std::to_string(SSAO_MAX_DIMENSION));
    if (vx < 0 || vy < 0 || static_cast<int64_t>(vx) + vw > dw || static_cast<int64_t>(vy) + vh > dh)
        return ctx.fail(SSAO_ERROR_INVALID_SIZE, "the viewport does not lie inside the " + std::to_string(dw) + "x" +
                                                     std::to_string(dh) + " input textures");

    if (in.output_texture != 0) {
        if (!bind_2d(gl, SSAO_UNIT_AO, in.output_texture))
            return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.output_texture is not a GL_TEXTURE_2D (it did not bind)");
        int ow = 0, oh = 0;
        level0_size(gl, ow, oh);
        if (ow < vx + vw || oh < vy + vh)
            return ctx.fail(SSAO_ERROR_INVALID_SIZE, "inputs.output_texture (" + std::to_string(ow) + "x" +
                                                         std::to_string(oh) + ") does not contain the viewport");
        // AO is a float written through a float output: an integer texture
        // (R32UI, RGBA8UI) would be complete but receive float bit patterns.
        if (has_integer_format(gl))
            return ctx.fail(SSAO_ERROR_UNSUPPORTED_FORMAT,
                            "inputs.output_texture has an integer format; a float, unorm or snorm one is needed");
        GLint blue_bits = 0;
        gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_BLUE_SIZE, &blue_bits);
        out.output_rgb = blue_bits > 0;
    }

    out.depth = fmt;
    out.texture_width = dw;
    out.texture_height = dh;
    out.viewport[0] = vx;
    out.viewport[1] = vy;
    out.viewport[2] = vw;
    out.viewport[3] = vh;
    out.depth_texture = in.depth_texture;
    out.normal_texture = in.normal_texture;
    out.output_texture = in.output_texture;
    out.multisample = samples > 0;
    out.samples = samples;
    out.sample_index = samples > 0 ? static_cast<int>(in.sample_index) : 0;
    return SSAO_OK;
}

}  // namespace ssao_impl
