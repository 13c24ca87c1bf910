// passes.cpp - execute: validate the inputs, derive the frame constants, and
// run only the passes the settings call for (clear | AO [-> blur x -> blur y]),
// all inside one GL state guard.
#include "context.h"
#include "kernel.h"
#include "raw_enum.h"
#include "settings.h"
#include "uniforms.h"

#include <cmath>
#include <cstring>
#include <vector>

static_assert(SSAO_MAX_KERNEL == SSAO_MAX_SAMPLES, "shader and ABI sample limits differ");
static_assert(SSAO_BLUR_MAX_TAPS == SSAO_MAX_BLUR_RADIUS, "shader and ABI blur limits differ");
static_assert(SSAO_UNITS_USED == SSAO_TEXTURE_UNITS_USED, "shader and ABI texture units differ");
static_assert(SSAO_SHADER_KERNEL_SEPARABLE == SSAO_KERNEL_SEPARABLE && SSAO_SHADER_KERNEL_SPHERE == SSAO_KERNEL_SPHERE,
              "kernel enums differ");
static_assert(SSAO_SHADER_ROTATION_NOISE == SSAO_ROTATION_NOISE_4X4 && SSAO_SHADER_ROTATION_HASH == SSAO_ROTATION_HASH &&
                  SSAO_SHADER_ROTATION_NONE == SSAO_ROTATION_NONE, "rotation enums differ");
static_assert(SSAO_SHADER_NORMAL_WORLD == SSAO_NORMAL_SPACE_WORLD && SSAO_SHADER_PACKING_UNORM == SSAO_NORMAL_PACKING_UNORM,
              "normal enums differ");
static_assert(SSAO_SHADER_BLUR_DEPTH_AWARE == SSAO_BLUR_DEPTH_AWARE && SSAO_SHADER_BLUR_BOX == SSAO_BLUR_BOX_4X4 &&
                  SSAO_SHADER_BLUR_GAUSSIAN == SSAO_BLUR_GAUSSIAN, "blur enums differ");

namespace ssao_impl {

namespace {

struct DepthFormat {
    int bits = 0;      // 16, 24, 32
    bool is_float = false;
    bool has_stencil = false;
};

// Is `name` a GL_TEXTURE_2D? Without GL 4.5's GL_TEXTURE_TARGET query only
// "is a texture" can be checked without raising a GL error.
bool is_texture_2d(ssao_context& ctx, GLuint name) {
    if (name == 0 || !ctx.gl.IsTexture(name)) return false;
    if (ctx.caps.texture_target_query) {
        GLint target = 0;
        ctx.gl.GetTextureParameteriv(name, GL_TEXTURE_TARGET, &target);
        return target == GL_TEXTURE_2D;
    }
    return true;
}

// Binds `name` to GL_TEXTURE_2D on `unit` and says whether it took: below GL
// 4.5 a name of another target cannot be recognised beforehand, the bind then
// fails (raising GL_INVALID_OPERATION) and leaves the previous binding.
bool bind_2d(const GladGLContext& gl, GLuint unit, GLuint name) {
    gl.ActiveTexture(GL_TEXTURE0 + unit);
    gl.BindTexture(GL_TEXTURE_2D, name);
    GLint bound = 0;
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    return static_cast<GLuint>(bound) == name;
}

// Leaves the plugin's framebuffer without an attachment on every way out of
// execute, so it never keeps a host texture alive (declared after the state
// guard, so it runs first, while the plugin's framebuffer is still bound).
struct DetachOnExit {
    const GladGLContext& gl;
    GLuint fbo;
    ~DetachOnExit() {
        gl.BindFramebuffer(GL_FRAMEBUFFER, fbo);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
    }
};

// Is level 0 of the texture bound to GL_TEXTURE_2D (on the active unit) of
// an integer format (GL_INT or GL_UNSIGNED_INT components)?
bool has_integer_format(const GladGLContext& gl) {
    GLint red_type = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_TYPE, &red_type);
    return red_type == GL_INT || red_type == GL_UNSIGNED_INT;
}

void level0_size(const GladGLContext& gl, int& w, int& h) {
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
}

void allocate(const GladGLContext& gl, GLuint& tex, GLenum internal, GLenum format, GLenum type, int w, int h) {
    if (tex == 0) gl.GenTextures(1, &tex);
    gl.BindTexture(GL_TEXTURE_2D, tex);
    // Re-specifying level 0 reallocates in place: no new name, nothing leaks.
    gl.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), w, h, 0, format, type, nullptr);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
}

void set_mat4(ssao_std140::mat4& dst, const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) dst.m[c * 4 + r] = static_cast<float>(m[c][r]);
}

void upload_kernel(ssao_context& ctx) {
    const GladGLContext& gl = ctx.gl;
    SsaoKernel block{};
    const std::vector<glm::vec3> kernel = make_kernel(ctx.settings);
    for (size_t i = 0; i < kernel.size(); ++i) {
        block.u_kernel[i] = {{kernel[i].x, kernel[i].y, kernel[i].z, 0.0f}};
    }
    gl.BindBuffer(GL_UNIFORM_BUFFER, ctx.ubo_kernel);
    gl.BufferData(GL_UNIFORM_BUFFER, sizeof block, &block, GL_STATIC_DRAW);

    const std::vector<glm::vec2> noise = make_noise(ctx.settings.seed);
    gl.ActiveTexture(GL_TEXTURE0 + SSAO_UNIT_NOISE);
    gl.BindTexture(GL_TEXTURE_2D, ctx.noise_texture);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, SSAO_NOISE_SIZE, SSAO_NOISE_SIZE, 0, GL_RG, GL_FLOAT, noise.data());
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    ctx.kernel_dirty = false;
}

// Default unpack state for our uploads (the guard restores the host's).
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

struct Target {
    GLuint texture = 0;
    int origin_x = 0, origin_y = 0;
    bool intermediate = false;  // RG32F (ao, view z) for the next pass
};

void draw(ssao_context& ctx, GLuint program, const ssao_context::PassUniforms& u, const Target& t, int w, int h) {
    const GladGLContext& gl = ctx.gl;
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, t.texture, 0);
    gl.Viewport(t.origin_x, t.origin_y, w, h);
    gl.UseProgram(program);
    gl.Uniform2i(u.target_origin, t.origin_x, t.origin_y);
    gl.Uniform1i(u.pack_depth, t.intermediate ? 1 : 0);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

void stamp(ssao_context& ctx, int slot, int index) {
    if (slot >= 0) ctx.gl.QueryCounter(ctx.queries[slot][index], GL_TIMESTAMP);
}

}  // namespace

void collect_timings(ssao_context& ctx) {
    if (!ctx.timers) return;
    const GladGLContext& gl = ctx.gl;
    // Oldest first, so the newest completed frame wins.
    for (;;) {
        int oldest = -1;
        for (int s = 0; s < ssao_context::kFrames; ++s)
            if (ctx.query_frame[s] != 0 && (oldest < 0 || ctx.query_frame[s] < ctx.query_frame[oldest])) oldest = s;
        if (oldest < 0) return;
        GLuint available = 0;
        gl.GetQueryObjectuiv(ctx.queries[oldest][ssao_context::kStamps - 1], GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) return;  // never wait: later frames cannot be done either
        GLuint64 t[ssao_context::kStamps] = {};
        for (int i = 0; i < ssao_context::kStamps; ++i)
            gl.GetQueryObjectui64v(ctx.queries[oldest][i], GL_QUERY_RESULT, &t[i]);
        ctx.timings.available = 1;
        ctx.timings.frame = ctx.query_frame[oldest];
        ctx.timings.ao_ms = static_cast<double>(t[1] - t[0]) * 1e-6;
        ctx.timings.blur_ms = static_cast<double>(t[2] - t[1]) * 1e-6;
        ctx.timings.total_ms = static_cast<double>(t[2] - t[0]) * 1e-6;
        ctx.query_frame[oldest] = 0;
    }
}

ssao_status execute(ssao_context& ctx, const ssao_inputs& in, ssao_output* out) {
    const GladGLContext& gl = ctx.gl;
    const ssao_settings& s = ctx.settings;

    // ---- checks that need no GL state change
    // Raw bits first (raw_enum.h): a caller may store any 32-bit value.
    if (!raw_enum_at_most(in.normal_space, SSAO_NORMAL_SPACE_WORLD))
        return ctx.fail(SSAO_ERROR_INVALID_ENUM, "inputs.normal_space is not an ssao_normal_space");
    if (!raw_enum_at_most(in.normal_packing, SSAO_NORMAL_PACKING_SIGNED))
        return ctx.fail(SSAO_ERROR_INVALID_ENUM, "inputs.normal_packing is not an ssao_normal_packing");
    if (!raw_enum_at_most(in.clip_range, SSAO_CLIP_ZERO_TO_ONE))
        return ctx.fail(SSAO_ERROR_INVALID_ENUM, "inputs.clip_range is not an ssao_clip_range");
    const bool world_normals = in.normal_space == SSAO_NORMAL_SPACE_WORLD;
    if (world_normals) {
        for (float v : in.view_matrix)
            if (!std::isfinite(v)) return ctx.fail(SSAO_ERROR_INVALID_VALUE, "inputs.view_matrix is not finite");
    }
    ProjectionInfo proj;
    std::string why;
    const ssao_status pst = analyse_projection(in.projection, in.clip_range, proj, why);
    if (pst != SSAO_OK) return ctx.fail(pst, "inputs.projection: " + why);
    if (in.depth_texture == 0) return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.depth_texture is 0");
    if (in.normal_texture == 0) return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.normal_texture is 0");
    if (!is_texture_2d(ctx, in.depth_texture))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.depth_texture is not the name of a GL_TEXTURE_2D");
    if (!is_texture_2d(ctx, in.normal_texture))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.normal_texture is not the name of a GL_TEXTURE_2D");
    if (in.output_texture != 0 && !is_texture_2d(ctx, in.output_texture))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.output_texture is not the name of a GL_TEXTURE_2D");
    if (in.output_texture != 0 && (in.output_texture == in.depth_texture || in.output_texture == in.normal_texture))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.output_texture is also an input (a feedback loop)");

    GlStateGuard guard(gl, ctx.caps, SSAO_UBO_FRAME, SSAO_UBO_KERNEL);
    const DetachOnExit detach{gl, ctx.fbo};

    // ---- inspect the textures (binds them: from here on the guard restores)
    if (!bind_2d(gl, SSAO_UNIT_DEPTH, in.depth_texture))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.depth_texture is not a GL_TEXTURE_2D (it did not bind)");
    int dw = 0, dh = 0;
    level0_size(gl, dw, dh);
    DepthFormat fmt;
    GLint depth_bits = 0, depth_type = 0, stencil_bits = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &depth_bits);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_TYPE, &depth_type);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &stencil_bits);
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
        guard.save_depth_stencil_mode(in.depth_texture, SSAO_UNIT_DEPTH);
        if (ctx.caps.depth_stencil_mode)
            gl.TexParameteri(GL_TEXTURE_2D, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_DEPTH_COMPONENT);
    }
    if (!bind_2d(gl, SSAO_UNIT_NORMAL, in.normal_texture))
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.normal_texture is not a GL_TEXTURE_2D (it did not bind)");
    int nw = 0, nh = 0;
    level0_size(gl, nw, nh);
    GLint red_bits = 0, blue_bits = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &red_bits);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_BLUE_SIZE, &blue_bits);
    if (nw != dw || nh != dh)
        return ctx.fail(SSAO_ERROR_INVALID_TEXTURE, "inputs.normal_texture is " + std::to_string(nw) + "x" +
                                                        std::to_string(nh) + " but the depth texture is " +
                                                        std::to_string(dw) + "x" + std::to_string(dh));
    if (red_bits <= 0 || blue_bits <= 0)
        return ctx.fail(SSAO_ERROR_UNSUPPORTED_FORMAT, "inputs.normal_texture needs three colour channels (x, y, z)");
    if (has_integer_format(gl))
        return ctx.fail(SSAO_ERROR_UNSUPPORTED_FORMAT,
                        "inputs.normal_texture has an integer format; a float, unorm or snorm one is needed");

    int vx = in.viewport[0], vy = in.viewport[1], vw = in.viewport[2], vh = in.viewport[3];
    if (vx == 0 && vy == 0 && vw == 0 && vh == 0) { vw = dw; vh = dh; }
    if (vw <= 0 || vh <= 0 || vw > SSAO_MAX_DIMENSION || vh > SSAO_MAX_DIMENSION)
        return ctx.fail(SSAO_ERROR_INVALID_SIZE, "the viewport is " + std::to_string(vw) + "x" + std::to_string(vh) +
                                                     "; each side must be 1.." + std::to_string(SSAO_MAX_DIMENSION));
    if (vx < 0 || vy < 0 || static_cast<int64_t>(vx) + vw > dw || static_cast<int64_t>(vy) + vh > dh)
        return ctx.fail(SSAO_ERROR_INVALID_SIZE, "the viewport does not lie inside the " + std::to_string(dw) + "x" +
                                                     std::to_string(dh) + " input textures");

    Target final_target;
    gl.BindFramebuffer(GL_FRAMEBUFFER, ctx.fbo);
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
        // Checked before anything of the library's changes: a refused call
        // leaves the library's own output as it was.
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, in.output_texture, 0);
        if (gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            return ctx.fail(SSAO_ERROR_UNSUPPORTED_FORMAT, "inputs.output_texture is not colour-renderable");
        final_target = {in.output_texture, vx, vy};
    }

    // ---- resources: (re)allocate only on change; only then are the unpack
    // state and our framebuffer's completeness looked at
    const bool strength_off = s.strength == SSAO_STRENGTH_OFF;
    const bool blur = !strength_off && s.blur != SSAO_BLUR_NONE;
    const bool separable_blur = blur && s.blur != SSAO_BLUR_BOX_4X4;
    const bool temp_stale = blur && (ctx.temp_width != vw || ctx.temp_height != vh || ctx.temp[0] == 0);
    const bool output_stale = in.output_texture == 0 && (ctx.output == 0 || ctx.output_width != vw ||
                                                         ctx.output_height != vh || ctx.output_format != s.output_format);
    if (temp_stale || output_stale || ctx.kernel_dirty) {
        guard.save_unpack_state();
        reset_unpack(gl);
    }
    gl.ActiveTexture(GL_TEXTURE0 + SSAO_UNIT_AO);
    if (temp_stale) {
        allocate(gl, ctx.temp[0], GL_RG32F, GL_RG, GL_FLOAT, vw, vh);
        allocate(gl, ctx.temp[1], GL_RG32F, GL_RG, GL_FLOAT, vw, vh);
        ctx.temp_width = vw;
        ctx.temp_height = vh;
    }
    if (output_stale) {
        if (s.output_format == SSAO_OUTPUT_R16F)
            allocate(gl, ctx.output, GL_R16F, GL_RED, GL_FLOAT, vw, vh);
        else
            allocate(gl, ctx.output, GL_R8, GL_RED, GL_UNSIGNED_BYTE, vw, vh);
        ctx.output_width = vw;
        ctx.output_height = vh;
        ctx.output_format = s.output_format;
    }
    if (in.output_texture == 0) final_target = {ctx.output, 0, 0};
    if (ctx.kernel_dirty) upload_kernel(ctx);

    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, final_target.texture, 0);
    if (output_stale && gl.CheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return ctx.fail(SSAO_ERROR_FRAMEBUFFER, "the library's output framebuffer is incomplete");

    // ---- frame constants
    SsaoFrame frame{};
    set_mat4(frame.u_proj, proj.proj);
    set_mat4(frame.u_inv_proj, proj.inverse);
    glm::dmat4 normal_to_view(1.0);
    if (world_normals) {
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) normal_to_view[c][r] = in.view_matrix[c * 4 + r];
    }
    set_mat4(frame.u_normal_to_view, normal_to_view);
    frame.u_viewport = {{vx, vy, vw, vh}};
    frame.u_modes = {{static_cast<int32_t>(s.kernel_shape), static_cast<int32_t>(s.rotation),
                      world_normals ? 2 : 1, in.normal_packing == SSAO_NORMAL_PACKING_SIGNED ? 2 : 1}};
    frame.u_counts = {{static_cast<int32_t>(s.sample_count), static_cast<int32_t>(s.seed),
                       static_cast<int32_t>(s.blur_radius), static_cast<int32_t>(s.blur)}};
    frame.u_ao = {{s.radius, s.bias, s.depth_step_bias, effective_strength(s)}};
    frame.u_ao2 = {{s.power, s.blur_sigma, s.blur_depth_tolerance, static_cast<float>(proj.ndc_per_depth)}};
    const float unorm_step = fmt.is_float ? 0.0f : static_cast<float>(1.0 / (std::ldexp(1.0, fmt.bits) - 1.0));
    frame.u_depth = {{proj.sky_depth, unorm_step, proj.reverse_z ? 1.0f : 0.0f, proj.orthographic ? 1.0f : 0.0f}};
    // A static camera and settings upload nothing: the block changes only
    // when the projection, viewport, inputs' encoding or settings do.
    if (!ctx.frame_uploaded || std::memcmp(&frame, &ctx.last_frame, sizeof frame) != 0) {
        gl.BindBuffer(GL_UNIFORM_BUFFER, ctx.ubo_frame);
        gl.BufferData(GL_UNIFORM_BUFFER, sizeof frame, &frame, GL_DYNAMIC_DRAW);
        ctx.last_frame = frame;
        ctx.frame_uploaded = true;
    }
    gl.BindBufferBase(GL_UNIFORM_BUFFER, SSAO_UBO_FRAME, ctx.ubo_frame);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, SSAO_UBO_KERNEL, ctx.ubo_kernel);

    // ---- bindings and fixed-function state for the passes
    gl.ActiveTexture(GL_TEXTURE0 + SSAO_UNIT_NOISE);
    gl.BindTexture(GL_TEXTURE_2D, ctx.noise_texture);
    for (GLuint u = 0; u < SSAO_UNITS_USED; ++u) gl.BindSampler(u, ctx.sampler);
    set_pass_state(gl, ctx.caps);
    gl.BindVertexArray(ctx.vao);

    // ---- timers: reuse a slot only once its results were read (never stall)
    collect_timings(ctx);
    ++ctx.frame;
    int slot = -1;
    if (ctx.timers) {
        const int candidate = static_cast<int>(ctx.frame % ssao_context::kFrames);
        if (ctx.query_frame[candidate] == 0) slot = candidate;
    }
    stamp(ctx, slot, 0);

    uint32_t passes = 0;
    if (strength_off) {
        // Strength 0: no sampling at all, the output is exactly 1.
        gl.Enable(GL_SCISSOR_TEST);
        gl.Scissor(final_target.origin_x, final_target.origin_y, vw, vh);
        const GLfloat one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
        gl.ClearBufferfv(GL_COLOR, 0, one);
        gl.Disable(GL_SCISSOR_TEST);
        passes |= SSAO_PASS_CLEAR;
        stamp(ctx, slot, 1);
    } else {
        gl.ActiveTexture(GL_TEXTURE0 + SSAO_UNIT_AO);
        gl.BindTexture(GL_TEXTURE_2D, 0);  // never sample what we render into
        const Target temp0{ctx.temp[0], 0, 0, true}, temp1{ctx.temp[1], 0, 0, true};
        draw(ctx, ctx.program_ao, ctx.ao_uniforms, blur ? temp0 : final_target, vw, vh);
        passes |= SSAO_PASS_AO;
        stamp(ctx, slot, 1);
        if (blur) {
            gl.BindTexture(GL_TEXTURE_2D, ctx.temp[0]);
            gl.UseProgram(ctx.program_blur);  // for u_blur_dir; draw() binds it too
            gl.Uniform2i(ctx.blur_dir_location, 1, 0);
            draw(ctx, ctx.program_blur, ctx.blur_uniforms, separable_blur ? temp1 : final_target, vw, vh);
            passes |= SSAO_PASS_BLUR_X;
            if (separable_blur) {
                gl.BindTexture(GL_TEXTURE_2D, ctx.temp[1]);
                gl.Uniform2i(ctx.blur_dir_location, 0, 1);
                draw(ctx, ctx.program_blur, ctx.blur_uniforms, final_target, vw, vh);
                passes |= SSAO_PASS_BLUR_Y;
            }
        }
    }
    stamp(ctx, slot, 2);
    if (slot >= 0) ctx.query_frame[slot] = ctx.frame;

    ctx.info.size = sizeof(ssao_frame_info);
    ctx.info.orthographic = proj.orthographic;
    ctx.info.reverse_z = proj.reverse_z;
    ctx.info.infinite_far = proj.infinite_far;
    ctx.info.depth_bits = static_cast<uint32_t>(fmt.bits);
    ctx.info.near_distance = static_cast<float>(proj.near_distance);
    ctx.info.far_distance = static_cast<float>(proj.far_distance);
    if (out) {
        out->texture = final_target.texture;
        out->origin[0] = final_target.origin_x;
        out->origin[1] = final_target.origin_y;
        out->passes_run = passes;
    }
    ctx.last_error.clear();
    return SSAO_OK;
}

}  // namespace ssao_impl
