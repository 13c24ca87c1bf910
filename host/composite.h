// composite.h - the host's lighting pass: a fullscreen triangle that
// reconstructs the view-space position from the depth buffer (no position
// buffer) and applies LearnOpenGL's Blinn-Phong with the AO multiplying the
// ambient term: ambient = 0.3 * diffuse * AO, one point light with
// attenuation, specular with shininess 8.
#pragma once

#include "gbuffer.h"

#include <glad/gl.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace composite {

struct Lighting {
    glm::vec3 light_view{0.0f};                 // light position, view space
    glm::vec3 light_color{0.2f, 0.2f, 0.7f};    // the chapter's bluish light
    float linear = 0.09f, quadratic = 0.032f;   // the chapter's attenuation
    float distance_scale = 1.0f;                // distances are multiplied by this before attenuation
    float albedo = 0.95f;                       // the chapter's diffuse colour (grey)
    glm::vec3 sky{0.0f};                        // empty pixels
};

// The light the host uses for a scene: above the scene's bounding box, in
// front and to the right, with attenuation distances measured in units of
// one tenth of the bounding-box diagonal (so a scene in millimetres is lit
// like one in metres).
Lighting default_lighting(const glm::vec3& bounds_min, const glm::vec3& bounds_max, const glm::mat4& view);

class Compositor {
public:
    Compositor(GladGLContext& gl, int width, int height);   // throws gl_util::Error
    ~Compositor();
    Compositor(const Compositor&) = delete;
    Compositor& operator=(const Compositor&) = delete;

    // Lights the G-buffer. ao_texture 0 = no AO (AO = 1). Returns RGB8 pixels,
    // top row first.
    std::vector<uint8_t> render(const gbuffer::GBuffer& g, const glm::mat4& view, const glm::mat4& projection,
                                GLuint ao_texture, glm::ivec2 ao_origin, const Lighting& lighting);
    // The same lighting, left in framebuffer() (RGBA8, width x height) for a
    // window to blit instead of read back.
    void draw(const gbuffer::GBuffer& g, const glm::mat4& view, const glm::mat4& projection,
              GLuint ao_texture, glm::ivec2 ao_origin, const Lighting& lighting);
    GLuint framebuffer() const { return fbo_; }
    // The texture behind framebuffer() (RGBA8), e.g. for the plugin's
    // multiply output mode, and its pixels as render() returns them.
    GLuint texture() const { return target_; }
    std::vector<uint8_t> read() const;

private:
    void release();
    GladGLContext& gl_;
    int width_, height_;
    GLuint program_ = 0, vao_ = 0, fbo_ = 0, target_ = 0, sampler_ = 0;
};

}  // namespace composite
