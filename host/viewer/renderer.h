// renderer.h - one frame of the viewer: the host's G-buffer pass, the SSAO
// plugin (through its C ABI), the host's lighting pass, and the AO-only view,
// into the window's framebuffer. resize() reallocates everything sized to the
// window; the plugin resizes its own targets from the inputs' viewport.
#pragma once

#include "composite.h"
#include "controls.h"
#include "gbuffer.h"
#include "scene.h"

#include <ssao/ssao.h>

#include <glad/gl.h>

#include <memory>

namespace viewer {

class Renderer {
public:
    // The GL context must be current; `get_proc` is handed to the plugin.
    // Throws std::runtime_error with the plugin's or GL's reason.
    Renderer(GladGLContext& gl, const ssao_api& api, ssao_get_proc_address_fn get_proc,
             const scene::Scene& scene, const ssao_settings& settings, int width, int height);
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    void resize(int width, int height);
    int width() const { return width_; }
    int height() const { return height_; }

    // Renders the scene from `camera` as `state` asks into framebuffer 0.
    void render(const camera::Camera& camera, const State& state);

    // GPU times of the newest finished plugin frame (available = 0 before one).
    ssao_timings timings() const;

private:
    void release_display();
    GladGLContext& gl_;
    const ssao_api& api_;
    const scene::Scene& scene_;
    ssao_context* ctx_ = nullptr;
    ssao_settings applied_{};
    int width_ = 0, height_ = 0;
    std::unique_ptr<gbuffer::GBuffer> gbuffer_;
    std::unique_ptr<composite::Compositor> compositor_;
    GLuint ao_program_ = 0, vao_ = 0, sampler_ = 0;   // the AO-only view
};

}  // namespace viewer
