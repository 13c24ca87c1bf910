// textbook_ssao.h - the LearnOpenGL chapter's SSAO, implemented here from its
// description as the benchmark's side-by-side anchor: a view-space position
// G-buffer, 64 hemisphere samples from std::default_random_engine with the
// lerp(0.1, 1, t^2) scale, a 4x4 tiled noise texture, the range check, bias
// 0.025, and the 4x4 box blur. It is deliberately not the plugin's code.
#pragma once

#include "scene.h"

#include <glad/gl.h>
#include <glm/glm.hpp>

#include <vector>

namespace textbook {

class Pass {
public:
    // Uploads the mesh and makes the position G-buffer, the SSAO and blur
    // targets (RED float) and programs. Throws gl_util::Error (a std::runtime_error).
    Pass(GladGLContext& gl, const scene::Mesh& mesh, int width, int height, float radius);
    ~Pass();
    Pass(const Pass&) = delete;
    Pass& operator=(const Pass&) = delete;

    // The chapter's own geometry pass writing view-space positions (its
    // required extra input; timed separately from the AO).
    void render_positions(const glm::mat4& view, const glm::mat4& projection);
    // SSAO + box blur, with GPU timestamps around them. `normal_texture` is the
    // host's view-space signed normal texture (what the chapter's gNormal holds).
    void run(GLuint normal_texture, const glm::mat4& projection);
    // The last run's GPU time in ms (SSAO + blur), waiting for the result.
    double last_ms();
    // The blurred AO, bottom row first.
    std::vector<float> read_ao();

private:
    GladGLContext& gl_;
    int width_, height_;
    float radius_;
    GLuint vao_ = 0, buffers_[2] = {}, index_count_ = 0;
    GLuint position_tex_ = 0, depth_rb_ = 0, gbuffer_fbo_ = 0;
    GLuint ssao_tex_ = 0, ssao_fbo_ = 0, blur_tex_ = 0, blur_fbo_ = 0, noise_tex_ = 0, empty_vao_ = 0;
    GLuint geometry_program_ = 0, ssao_program_ = 0, blur_program_ = 0;
    GLuint queries_[2] = {};
    std::vector<glm::vec3> kernel_;
};

}  // namespace textbook
