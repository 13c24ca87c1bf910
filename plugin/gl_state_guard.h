// gl_state_guard.h - saves, in its constructor, every piece of GL state the
// plugin's passes change, and restores it in its destructor. One list, one
// scope: tests snapshot the same list before and after execute.
#pragma once

#include <glad/gl.h>

namespace ssao_impl {

struct GlCaps {
    int major = 3, minor = 3;
    bool clip_control = false;        // GL 4.5 or ARB_clip_control
    bool depth_stencil_mode = false;  // GL 4.3: GL_DEPTH_STENCIL_TEXTURE_MODE
    bool texture_target_query = false;// GL 4.5: GL_TEXTURE_TARGET
    bool indexed_blend = false;       // GL 4.0 or ARB_draw_buffers_blend: glBlendFuncSeparatei / glBlendEquationSeparatei
    bool query_buffer = false;        // GL 4.4 or ARB_query_buffer_object: GL_QUERY_BUFFER exists
    int viewports = 1;                // viewport arrays (GL 4.1 or ARB_viewport_array): indices to save (<= 16)
    int max_draw_buffers = 8;
    int max_clip_distances = 8;
    bool software_rasterizer = false; // GL_RENDERER names one (renderer.h): the plan's sky tests depend on it
};

class GlStateGuard {
public:
    GlStateGuard(const GladGLContext& gl, const GlCaps& caps, GLuint uniform_binding_a, GLuint uniform_binding_b);
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

    // Remember and later restore the depth-stencil texture mode of `texture`,
    // bound to `target` (GL_TEXTURE_2D or GL_TEXTURE_2D_MULTISAMPLE) on
    // texture unit `unit` (the active one) when called.
    void save_depth_stencil_mode(GLuint texture, GLuint unit, GLenum target);

    // Save the pixel-unpack buffer binding and unpack pixel store, before an
    // upload or (re)allocation changes them: frames that upload nothing do
    // not query them at all.
    void save_unpack_state();

    // Save draw buffer 0's blend function and equation (all buffers' below
    // GL 4.0), before the output's multiply blend changes them: a frame that
    // does not multiply leaves them alone, so a host's per-buffer functions
    // survive even where the library cannot set one buffer's.
    void save_blend_function();

private:
    static constexpr int kUnits = 4;
    static constexpr int kMaxBuffers = 16;
    static constexpr int kMaxViewports = 16;
    const GladGLContext& gl_;
    const GlCaps& caps_;
    GLint draw_fbo_ = 0, read_fbo_ = 0, vao_ = 0, active_texture_ = 0;
    GLint host_program_ = 0;  // current at construction
    GLint program_ = 0;       // made current again where a pass bound its own: 0 if the host's was flagged
                              // for deletion or its last re-link failed
    GLint texture_2d_[kUnits] = {}, texture_2d_ms_[kUnits] = {}, sampler_[kUnits] = {};
    GLint array_buffer_ = 0, uniform_buffer_ = 0, unpack_buffer_ = 0;
    GLuint ubo_index_[2] = {};
    GLint ubo_binding_[2] = {};
    GLint64 ubo_start_[2] = {}, ubo_size_[2] = {};
    GLint viewport_[4] = {}, scissor_[4] = {};
    // Viewport arrays (GL 4.1+): glViewport, glScissor and the scissor enable
    // set every index, so each one is saved.
    GLfloat viewport_array_[kMaxViewports][4] = {};
    GLint scissor_array_[kMaxViewports][4] = {};
    GLboolean scissor_test_array_[kMaxViewports] = {};
    GLboolean scissor_test_ = 0, depth_test_ = 0, stencil_test_ = 0, cull_face_ = 0, rasterizer_discard_ = 0,
              polygon_offset_fill_ = 0, color_logic_op_ = 0, sample_mask_ = 0, dither_ = 0, framebuffer_srgb_ = 0,
              multisample_ = 0, sample_alpha_to_coverage_ = 0;
    GLboolean blend_[kMaxBuffers] = {};
    // Blend function and equation of draw buffer 0 (the multiply output mode
    // sets them there; below GL 4.0 they are global).
    GLint blend_src_rgb_ = 0, blend_dst_rgb_ = 0, blend_src_alpha_ = 0, blend_dst_alpha_ = 0;
    GLint blend_equation_rgb_ = 0, blend_equation_alpha_ = 0;
    GLboolean color_mask_[kMaxBuffers][4] = {};
    GLboolean clip_distance_[8] = {};
    GLint polygon_mode_[2] = {};  // front, back (they differ only in a compatibility profile)
    GLboolean depth_mask_ = 0;
    GLint depth_func_ = 0;
    // Depth range of viewport index 0, and of every other index (glDepthRange
    // sets them all) where there are viewport arrays.
    GLdouble depth_range_[kMaxViewports][2] = {};
    GLint stencil_mask_front_ = 0, stencil_mask_back_ = 0;
    GLint clip_origin_ = 0, clip_depth_mode_ = 0;
    GLint unpack_[8] = {};
    bool unpack_saved_ = false;
    bool blend_function_saved_ = false;
    GLuint ds_texture_ = 0, ds_unit_ = 0;
    GLenum ds_target_ = GL_TEXTURE_2D;
    GLint ds_mode_ = 0;
};

// While it lives, no buffer is bound to GL_QUERY_BUFFER (where that target
// exists): with one bound, glGetQueryObject* writes the result into that
// buffer at the offset the pointer argument gives, instead of into memory.
// Restores the host's binding on destruction. Used around every read of the
// timer queries, inside execute and in get_timings (which has no state guard).
class QueryBufferUnbound {
public:
    QueryBufferUnbound(const GladGLContext& gl, const GlCaps& caps);
    ~QueryBufferUnbound();
    QueryBufferUnbound(const QueryBufferUnbound&) = delete;
    QueryBufferUnbound& operator=(const QueryBufferUnbound&) = delete;

private:
    const GladGLContext& gl_;
    GLint saved_ = 0;
};

// Puts the pipeline into the state the passes assume (after the guard saved it).
void set_pass_state(const GladGLContext& gl, const GlCaps& caps);

// Output mode MULTIPLY: blending on draw buffer 0 that multiplies the
// target's rgb by the fragment's rgb and keeps its alpha, and (for an sRGB
// target) in linear space; end_multiply_blend puts back set_pass_state's.
void begin_multiply_blend(const GladGLContext& gl, const GlCaps& caps);
void end_multiply_blend(const GladGLContext& gl);

}  // namespace ssao_impl
