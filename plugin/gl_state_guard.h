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
    int viewports = 1;                // GL 4.1 viewport arrays: how many indices to save (<= 16)
    int max_draw_buffers = 8;
    int max_clip_distances = 8;
};

class GlStateGuard {
public:
    GlStateGuard(const GladGLContext& gl, const GlCaps& caps, GLuint uniform_binding_a, GLuint uniform_binding_b);
    ~GlStateGuard();
    GlStateGuard(const GlStateGuard&) = delete;
    GlStateGuard& operator=(const GlStateGuard&) = delete;

    // Remember and later restore the depth-stencil texture mode of `texture`,
    // bound to GL_TEXTURE_2D on texture unit `unit` (the active one) when called.
    void save_depth_stencil_mode(GLuint texture, GLuint unit);

    // Save the pixel-unpack buffer binding and unpack pixel store, before an
    // upload or (re)allocation changes them: frames that upload nothing do
    // not query them at all.
    void save_unpack_state();

private:
    static constexpr int kUnits = 4;
    static constexpr int kMaxBuffers = 16;
    static constexpr int kMaxViewports = 16;
    const GladGLContext& gl_;
    const GlCaps& caps_;
    GLint draw_fbo_ = 0, read_fbo_ = 0, program_ = 0, vao_ = 0, active_texture_ = 0;
    GLint texture_2d_[kUnits] = {}, sampler_[kUnits] = {};
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
    GLboolean color_mask_[kMaxBuffers][4] = {};
    GLboolean clip_distance_[8] = {};
    GLint polygon_mode_[2] = {};  // front, back (they differ only in a compatibility profile)
    GLboolean depth_mask_ = 0;
    GLint stencil_mask_front_ = 0, stencil_mask_back_ = 0;
    GLint clip_origin_ = 0, clip_depth_mode_ = 0;
    GLint unpack_[8] = {};
    bool unpack_saved_ = false;
    GLuint ds_texture_ = 0, ds_unit_ = 0;
    GLint ds_mode_ = 0;
};

// Puts the pipeline into the state the passes assume (after the guard saved it).
void set_pass_state(const GladGLContext& gl, const GlCaps& caps);

}  // namespace ssao_impl
