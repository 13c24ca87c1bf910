#include "renderer.h"

#include "debug_view_text.h"
#include "gl_util.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace viewer {

namespace {

// The AO texture as grey, pixel for pixel (white without one: mode E), or a
// normal debug view's RGB.
const char* kAoFragment = R"glsl(#version 330 core
uniform sampler2D u_ao;
uniform int u_use_ao;
uniform int u_rgb;
uniform ivec2 u_ao_origin;
out vec4 o_color;
void main() {
    vec3 c = u_use_ao == 1 ? texelFetch(u_ao, ivec2(gl_FragCoord.xy) + u_ao_origin, 0).rgb : vec3(1.0);
    o_color = vec4(u_rgb == 1 ? c : vec3(c.r), 1.0);
}
)glsl";

}  // namespace

Renderer::Renderer(GladGLContext& gl, const ssao_api& api, ssao_get_proc_address_fn get_proc,
                   const scene::Scene& scene, const ssao_settings& settings, int width, int height)
    : gl_(gl), api_(api), scene_(scene) {
    ssao_context_desc desc{};
    desc.size = sizeof desc;
    desc.get_proc_address = get_proc;
    desc.settings = &settings;
    const ssao_status st = api_.create_context(&desc, &ctx_);
    if (st != SSAO_OK) throw std::runtime_error(std::string("the SSAO plugin could not start: ") + api_.status_string(st));
    applied_ = settings;
    try {
        ao_program_ = gl_util::make_program(gl_, "AO view", gl_util::fullscreen_vertex_shader().c_str(), kAoFragment);
        gl_.GenVertexArrays(1, &vao_);
        // texelFetch needs a complete texture whatever the plugin's filters.
        gl_.GenSamplers(1, &sampler_);
        gl_.SamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl_.SamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        resize(width, height);
    } catch (...) {
        release_display();
        api_.destroy_context(ctx_);
        throw;
    }
}

Renderer::~Renderer() {
    gbuffer_.reset();
    compositor_.reset();
    release_display();
    api_.destroy_context(ctx_);
}

void Renderer::release_display() {
    if (sampler_) gl_.DeleteSamplers(1, &sampler_);
    if (vao_) gl_.DeleteVertexArrays(1, &vao_);
    if (ao_program_) gl_.DeleteProgram(ao_program_);
    sampler_ = vao_ = ao_program_ = 0;
}

void Renderer::resize(int width, int height) {
    if (width == width_ && height == height_ && gbuffer_) return;
    // The old targets go first, so a resize never holds two sets.
    gbuffer_.reset();
    compositor_.reset();
    width_ = width;
    height_ = height;
    gbuffer::Desc d;   // ssao-host's defaults: D32F depth, view-space RGBA16F normals
    d.width = width;
    d.height = height;
    gbuffer_ = std::make_unique<gbuffer::GBuffer>(gl_, d, scene_.mesh);
    compositor_ = std::make_unique<composite::Compositor>(gl_, width, height);
}

void Renderer::render(const camera::Camera& camera, const State& state) {
    const float aspect = static_cast<float>(width_) / static_cast<float>(height_);
    const glm::mat4 view = camera::view_matrix(camera);
    const glm::mat4 projection = camera::projection_matrix(camera, aspect);
    gbuffer_->render(view, projection);

    GLuint ao_texture = 0;
    glm::ivec2 ao_origin(0);
    if (state.ssao) {
        if (std::memcmp(&applied_, &state.settings, sizeof applied_) != 0) {
            const ssao_status st = api_.set_settings(ctx_, &state.settings);
            if (st != SSAO_OK)
                throw std::runtime_error(std::string("the SSAO plugin refused the settings: ") + api_.status_string(st) +
                                         ": " + api_.last_error(ctx_));
            applied_ = state.settings;
        }
        ssao_inputs in{};
        in.size = sizeof in;
        in.depth_texture = gbuffer_->depth_texture();
        in.normal_texture = gbuffer_->normal_texture();
        in.normal_space = SSAO_NORMAL_SPACE_VIEW;
        in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
        std::copy_n(glm::value_ptr(projection), 16, in.projection);
        std::copy_n(glm::value_ptr(view), 16, in.view_matrix);
        in.clip_range = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
        ssao_output out{};
        out.size = sizeof out;
        const ssao_status st = api_.execute(ctx_, &in, &out);
        if (st != SSAO_OK)
            throw std::runtime_error(std::string("the SSAO plugin failed: ") + api_.status_string(st) + ": " +
                                     api_.last_error(ctx_));
        ao_texture = out.texture;
        ao_origin = glm::ivec2(out.origin[0], out.origin[1]);
    }

    auto& gl = gl_;
    if (state.view == View::Lit && !debug_view_shown(state)) {
        const composite::Lighting lighting = composite::default_lighting(scene_.bounds_min, scene_.bounds_max, view);
        compositor_->draw(*gbuffer_, view, projection, ao_texture, ao_origin, lighting);
        gl.BindFramebuffer(GL_READ_FRAMEBUFFER, compositor_->framebuffer());
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        gl.BlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    } else {
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        gl.Viewport(0, 0, width_, height_);
        gl.Disable(GL_DEPTH_TEST);
        gl.Disable(GL_BLEND);
        gl.UseProgram(ao_program_);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_2D, ao_texture);
        gl.BindSampler(0, sampler_);
        gl.Uniform1i(gl.GetUniformLocation(ao_program_, "u_ao"), 0);
        gl.Uniform1i(gl.GetUniformLocation(ao_program_, "u_use_ao"), ao_texture != 0 ? 1 : 0);
        const bool rgb = debug_view_shown(state) && debug_view_text::is_rgb(state.settings.debug_view);
        gl.Uniform1i(gl.GetUniformLocation(ao_program_, "u_rgb"), rgb ? 1 : 0);
        gl.Uniform2i(gl.GetUniformLocation(ao_program_, "u_ao_origin"), ao_origin.x, ao_origin.y);
        gl.BindVertexArray(vao_);
        gl.DrawArrays(GL_TRIANGLES, 0, 3);
        gl.BindVertexArray(0);
        gl.BindSampler(0, 0);
        gl.BindTexture(GL_TEXTURE_2D, 0);
        gl.UseProgram(0);
    }
    gl_util::check(gl, "the viewer's frame");
}

ssao_timings Renderer::timings() const {
    ssao_timings t{};
    t.size = sizeof t;
    api_.get_timings(ctx_, &t);
    return t;
}

}  // namespace viewer
