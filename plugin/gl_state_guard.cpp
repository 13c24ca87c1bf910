#include "gl_state_guard.h"

#include <algorithm>

namespace ssao_impl {

namespace {

const GLenum kUnpackParams[8] = {GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH,
                                 GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS,
                                 GL_UNPACK_SKIP_IMAGES, GL_UNPACK_ALIGNMENT};

// No polygon mode has this value: marks a slot glGetIntegerv left alone.
constexpr GLint kUnwrittenPolygonMode = -1;

void set_enabled(const GladGLContext& gl, GLenum cap, GLboolean on) {
    if (on) gl.Enable(cap); else gl.Disable(cap);
}

}  // namespace

GlStateGuard::GlStateGuard(const GladGLContext& gl, const GlCaps& caps, GLuint uniform_binding_a,
                           GLuint uniform_binding_b)
    : gl_(gl), caps_(caps) {
    gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_fbo_);
    gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_fbo_);
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &host_program_);
    program_ = host_program_;
    if (program_ != 0) {
        // Two current programs cannot be made current again once the passes
        // bind theirs: one the host flagged for deletion (GL deletes it then),
        // and one whose last re-link failed (GL keeps its old executable in
        // use but refuses glUseProgram on it).
        GLint flagged = GL_FALSE, linked = GL_TRUE;
        gl.GetProgramiv(static_cast<GLuint>(program_), GL_DELETE_STATUS, &flagged);
        if (!flagged) gl.GetProgramiv(static_cast<GLuint>(program_), GL_LINK_STATUS, &linked);
        if (flagged || !linked) program_ = 0;
    }
    gl.GetIntegerv(GL_VERTEX_ARRAY_BINDING, &vao_);
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
    for (int u = 0; u < kUnits; ++u) {
        gl.ActiveTexture(GL_TEXTURE0 + u);
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &texture_2d_[u]);
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &texture_2d_ms_[u]);
        gl.GetIntegerv(GL_SAMPLER_BINDING, &sampler_[u]);
    }
    gl.ActiveTexture(static_cast<GLenum>(active_texture_));
    gl.GetIntegerv(GL_ARRAY_BUFFER_BINDING, &array_buffer_);
    gl.GetIntegerv(GL_UNIFORM_BUFFER_BINDING, &uniform_buffer_);
    ubo_index_[0] = uniform_binding_a;
    ubo_index_[1] = uniform_binding_b;
    for (int i = 0; i < 2; ++i) {
        gl.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, ubo_index_[i], &ubo_binding_[i]);
        gl.GetInteger64i_v(GL_UNIFORM_BUFFER_START, ubo_index_[i], &ubo_start_[i]);
        gl.GetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, ubo_index_[i], &ubo_size_[i]);
    }
    gl.GetIntegerv(GL_VIEWPORT, viewport_);
    // With viewport arrays index 0 may hold a sub-pixel (float) viewport,
    // which the integer query rounds: it is saved and restored as floats too.
    if (caps.viewports > 1) gl.GetFloati_v(GL_VIEWPORT, 0, viewport_array_[0]);
    gl.GetIntegerv(GL_SCISSOR_BOX, scissor_);
    scissor_test_ = gl.IsEnabled(GL_SCISSOR_TEST);
    for (int i = 1; i < std::min(caps.viewports, kMaxViewports); ++i) {
        const GLuint v = static_cast<GLuint>(i);
        gl.GetFloati_v(GL_VIEWPORT, v, viewport_array_[i]);
        gl.GetIntegeri_v(GL_SCISSOR_BOX, v, scissor_array_[i]);
        scissor_test_array_[i] = gl.IsEnabledi(GL_SCISSOR_TEST, v);
    }
    depth_test_ = gl.IsEnabled(GL_DEPTH_TEST);
    stencil_test_ = gl.IsEnabled(GL_STENCIL_TEST);
    cull_face_ = gl.IsEnabled(GL_CULL_FACE);
    rasterizer_discard_ = gl.IsEnabled(GL_RASTERIZER_DISCARD);
    polygon_offset_fill_ = gl.IsEnabled(GL_POLYGON_OFFSET_FILL);
    color_logic_op_ = gl.IsEnabled(GL_COLOR_LOGIC_OP);
    sample_mask_ = gl.IsEnabled(GL_SAMPLE_MASK);
    dither_ = gl.IsEnabled(GL_DITHER);
    framebuffer_srgb_ = gl.IsEnabled(GL_FRAMEBUFFER_SRGB);
    multisample_ = gl.IsEnabled(GL_MULTISAMPLE);
    sample_alpha_to_coverage_ = gl.IsEnabled(GL_SAMPLE_ALPHA_TO_COVERAGE);
    const int buffers = std::min(caps.max_draw_buffers, kMaxBuffers);
    for (int i = 0; i < buffers; ++i) {
        blend_[i] = gl.IsEnabledi(GL_BLEND, static_cast<GLuint>(i));
        gl.GetBooleani_v(GL_COLOR_WRITEMASK, static_cast<GLuint>(i), color_mask_[i]);
    }
    for (int i = 0; i < std::min(caps.max_clip_distances, 8); ++i)
        clip_distance_[i] = gl.IsEnabled(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i));
    // A core profile's state table holds one polygon mode, and a driver may
    // write one value (NVIDIA's does); a compatibility profile writes front
    // and back. An unwritten back slot reads as the front mode.
    polygon_mode_[1] = kUnwrittenPolygonMode;
    gl.GetIntegerv(GL_POLYGON_MODE, polygon_mode_);
    if (polygon_mode_[1] == kUnwrittenPolygonMode) polygon_mode_[1] = polygon_mode_[0];
    gl.GetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask_);
    gl.GetIntegerv(GL_DEPTH_FUNC, &depth_func_);
    gl.GetDoublev(GL_DEPTH_RANGE, depth_range_[0]);
    for (int i = 1; i < std::min(caps.viewports, kMaxViewports); ++i)
        gl.GetDoublei_v(GL_DEPTH_RANGE, static_cast<GLuint>(i), depth_range_[i]);
    gl.GetIntegerv(GL_STENCIL_WRITEMASK, &stencil_mask_front_);
    gl.GetIntegerv(GL_STENCIL_BACK_WRITEMASK, &stencil_mask_back_);
    if (caps.clip_control) {
        gl.GetIntegerv(GL_CLIP_ORIGIN, &clip_origin_);
        gl.GetIntegerv(GL_CLIP_DEPTH_MODE, &clip_depth_mode_);
    }
}

void GlStateGuard::save_unpack_state() {
    if (unpack_saved_) return;
    unpack_saved_ = true;
    gl_.GetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack_buffer_);
    for (int i = 0; i < 8; ++i) gl_.GetIntegerv(kUnpackParams[i], &unpack_[i]);
}

void GlStateGuard::save_blend_function() {
    if (blend_function_saved_) return;
    blend_function_saved_ = true;
    const GladGLContext& gl = gl_;
    // Draw buffer 0's where blend state is per buffer, else the one global state.
    const auto get = [&](GLenum pname, GLint* value) {
        if (caps_.indexed_blend) gl.GetIntegeri_v(pname, 0, value); else gl.GetIntegerv(pname, value);
    };
    get(GL_BLEND_SRC_RGB, &blend_src_rgb_);
    get(GL_BLEND_DST_RGB, &blend_dst_rgb_);
    get(GL_BLEND_SRC_ALPHA, &blend_src_alpha_);
    get(GL_BLEND_DST_ALPHA, &blend_dst_alpha_);
    get(GL_BLEND_EQUATION_RGB, &blend_equation_rgb_);
    get(GL_BLEND_EQUATION_ALPHA, &blend_equation_alpha_);
}

void GlStateGuard::save_depth_stencil_mode(GLuint texture, GLuint unit, GLenum target) {
    if (!caps_.depth_stencil_mode) return;
    ds_texture_ = texture;
    ds_unit_ = unit;
    ds_target_ = target;
    gl_.GetTexParameteriv(target, GL_DEPTH_STENCIL_TEXTURE_MODE, &ds_mode_);
}

GlStateGuard::~GlStateGuard() {
    const GladGLContext& gl = gl_;
    if (ds_texture_ != 0) {
        gl.ActiveTexture(GL_TEXTURE0 + ds_unit_);
        gl.BindTexture(ds_target_, ds_texture_);
        gl.TexParameteri(ds_target_, GL_DEPTH_STENCIL_TEXTURE_MODE, ds_mode_);
    }
    for (int u = 0; u < kUnits; ++u) {
        gl.ActiveTexture(GL_TEXTURE0 + u);
        gl.BindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture_2d_[u]));
        gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, static_cast<GLuint>(texture_2d_ms_[u]));
        gl.BindSampler(static_cast<GLuint>(u), static_cast<GLuint>(sampler_[u]));
    }
    gl.ActiveTexture(static_cast<GLenum>(active_texture_));
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_fbo_));
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_fbo_));
    // Only where a pass bound its own: a call that bound none (refused, or a
    // frame that only clears) leaves the host's program current, flagged for
    // deletion or not.
    GLint current = 0;
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &current);
    if (current != host_program_) gl.UseProgram(static_cast<GLuint>(program_));
    gl.BindVertexArray(static_cast<GLuint>(vao_));
    // Indexed uniform bindings first: glBindBufferRange/Base also set the
    // generic binding, which is restored after them.
    for (int i = 0; i < 2; ++i) {
        if (ubo_binding_[i] != 0 && ubo_size_[i] > 0)
            gl.BindBufferRange(GL_UNIFORM_BUFFER, ubo_index_[i], static_cast<GLuint>(ubo_binding_[i]),
                               static_cast<GLintptr>(ubo_start_[i]), static_cast<GLsizeiptr>(ubo_size_[i]));
        else
            gl.BindBufferBase(GL_UNIFORM_BUFFER, ubo_index_[i], static_cast<GLuint>(ubo_binding_[i]));
    }
    gl.BindBuffer(GL_UNIFORM_BUFFER, static_cast<GLuint>(uniform_buffer_));
    gl.BindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(array_buffer_));
    if (unpack_saved_) {
        gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack_buffer_));
        for (int i = 0; i < 8; ++i) gl.PixelStorei(kUnpackParams[i], unpack_[i]);
    }
    // Index 0 through the plain calls (which also set every other index),
    // then the other indices of a viewport array.
    gl.Viewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    gl.Scissor(scissor_[0], scissor_[1], scissor_[2], scissor_[3]);
    set_enabled(gl, GL_SCISSOR_TEST, scissor_test_);
    for (int i = 1; i < std::min(caps_.viewports, kMaxViewports); ++i) {
        const GLuint v = static_cast<GLuint>(i);
        gl.ViewportIndexedfv(v, viewport_array_[i]);
        gl.ScissorIndexedv(v, scissor_array_[i]);
        if (scissor_test_array_[i]) gl.Enablei(GL_SCISSOR_TEST, v); else gl.Disablei(GL_SCISSOR_TEST, v);
    }
    if (caps_.viewports > 1) gl.ViewportIndexedfv(0, viewport_array_[0]);
    set_enabled(gl, GL_DEPTH_TEST, depth_test_);
    set_enabled(gl, GL_STENCIL_TEST, stencil_test_);
    set_enabled(gl, GL_CULL_FACE, cull_face_);
    set_enabled(gl, GL_RASTERIZER_DISCARD, rasterizer_discard_);
    set_enabled(gl, GL_POLYGON_OFFSET_FILL, polygon_offset_fill_);
    set_enabled(gl, GL_COLOR_LOGIC_OP, color_logic_op_);
    set_enabled(gl, GL_SAMPLE_MASK, sample_mask_);
    set_enabled(gl, GL_DITHER, dither_);
    set_enabled(gl, GL_FRAMEBUFFER_SRGB, framebuffer_srgb_);
    set_enabled(gl, GL_MULTISAMPLE, multisample_);
    set_enabled(gl, GL_SAMPLE_ALPHA_TO_COVERAGE, sample_alpha_to_coverage_);
    const int buffers = std::min(caps_.max_draw_buffers, kMaxBuffers);
    for (int i = 0; i < buffers; ++i) {
        const GLuint b = static_cast<GLuint>(i);
        if (blend_[i]) gl.Enablei(GL_BLEND, b); else gl.Disablei(GL_BLEND, b);
        gl.ColorMaski(b, color_mask_[i][0], color_mask_[i][1], color_mask_[i][2], color_mask_[i][3]);
    }
    const auto e = [](GLint v) { return static_cast<GLenum>(v); };
    if (blend_function_saved_) {
        if (caps_.indexed_blend) {
            gl.BlendFuncSeparatei(0, e(blend_src_rgb_), e(blend_dst_rgb_), e(blend_src_alpha_), e(blend_dst_alpha_));
            gl.BlendEquationSeparatei(0, e(blend_equation_rgb_), e(blend_equation_alpha_));
        } else {
            gl.BlendFuncSeparate(e(blend_src_rgb_), e(blend_dst_rgb_), e(blend_src_alpha_), e(blend_dst_alpha_));
            gl.BlendEquationSeparate(e(blend_equation_rgb_), e(blend_equation_alpha_));
        }
    }
    for (int i = 0; i < std::min(caps_.max_clip_distances, 8); ++i)
        set_enabled(gl, GL_CLIP_DISTANCE0 + static_cast<GLenum>(i), clip_distance_[i]);
    // A core profile accepts only GL_FRONT_AND_BACK (NVIDIA's refuses GL_FRONT
    // with GL_INVALID_ENUM); only a compatibility profile holds two modes.
    if (polygon_mode_[0] == polygon_mode_[1]) {
        gl.PolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygon_mode_[0]));
    } else {
        gl.PolygonMode(GL_FRONT, static_cast<GLenum>(polygon_mode_[0]));
        gl.PolygonMode(GL_BACK, static_cast<GLenum>(polygon_mode_[1]));
    }
    gl.DepthMask(depth_mask_);
    gl.DepthFunc(static_cast<GLenum>(depth_func_));
    gl.DepthRange(depth_range_[0][0], depth_range_[0][1]);
    for (int i = 1; i < std::min(caps_.viewports, kMaxViewports); ++i)
        gl.DepthRangeIndexed(static_cast<GLuint>(i), depth_range_[i][0], depth_range_[i][1]);
    gl.StencilMaskSeparate(GL_FRONT, static_cast<GLuint>(stencil_mask_front_));
    gl.StencilMaskSeparate(GL_BACK, static_cast<GLuint>(stencil_mask_back_));
    if (caps_.clip_control)
        gl.ClipControl(static_cast<GLenum>(clip_origin_), static_cast<GLenum>(clip_depth_mode_));
}

QueryBufferUnbound::QueryBufferUnbound(const GladGLContext& gl, const GlCaps& caps) : gl_(gl) {
    if (!caps.query_buffer) return;
    gl.GetIntegerv(GL_QUERY_BUFFER_BINDING, &saved_);
    if (saved_ != 0) gl.BindBuffer(GL_QUERY_BUFFER, 0);
}

QueryBufferUnbound::~QueryBufferUnbound() {
    if (saved_ != 0) gl_.BindBuffer(GL_QUERY_BUFFER, static_cast<GLuint>(saved_));
}

void set_pass_state(const GladGLContext& gl, const GlCaps& caps) {
    gl.Disable(GL_SCISSOR_TEST);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_STENCIL_TEST);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_RASTERIZER_DISCARD);
    gl.Disable(GL_POLYGON_OFFSET_FILL);
    gl.Disable(GL_COLOR_LOGIC_OP);
    gl.Disable(GL_SAMPLE_MASK);
    gl.Disable(GL_DITHER);
    gl.Disable(GL_FRAMEBUFFER_SRGB);
    gl.Disable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    gl.Disable(GL_BLEND);  // every draw buffer
    for (int i = 0; i < std::min(caps.max_clip_distances, 8); ++i) gl.Disable(GL_CLIP_DISTANCE0 + static_cast<GLenum>(i));
    // Both draw buffers a pass may write (the grid pass writes two): the
    // colour mask is context state per draw buffer index, so the host's mask
    // on buffer 1 would otherwise hold back channels of the grid's normals.
    for (GLuint b = 0; b < 2; ++b) gl.ColorMaski(b, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    if (caps.clip_control) gl.ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

void begin_multiply_blend(const GladGLContext& gl, const GlCaps& caps) {
    // rgb = src * 0 + dst * src.rgb; alpha = src * 0 + dst * 1 (kept). Only
    // draw buffer 0 where blend state is per buffer (GL 4.0): the library's
    // framebuffer has one colour attachment, and a host's per-buffer
    // functions for the others are left alone.
    if (caps.indexed_blend) {
        gl.BlendFuncSeparatei(0, GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE);
        gl.BlendEquationSeparatei(0, GL_FUNC_ADD, GL_FUNC_ADD);
    } else {
        gl.BlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ZERO, GL_ONE);
        gl.BlendEquationSeparate(GL_FUNC_ADD, GL_FUNC_ADD);
    }
    gl.Enablei(GL_BLEND, 0);
    // An sRGB lit image is multiplied in linear space (decoded, multiplied,
    // encoded); for any other format this enable changes nothing.
    gl.Enable(GL_FRAMEBUFFER_SRGB);
}

void end_multiply_blend(const GladGLContext& gl) {
    gl.Disablei(GL_BLEND, 0);
    gl.Disable(GL_FRAMEBUFFER_SRGB);
}

}  // namespace ssao_impl
