// gbuffer.h - the host's geometry pass: a framebuffer with exactly a depth
// attachment and a normal attachment (no position buffer), the SSAO plugin's
// two inputs.
#pragma once

#include "cli.h"
#include "scene.h"

#include <glad/gl.h>
#include <glm/glm.hpp>

namespace gbuffer {

struct Desc {
    int width = 0, height = 0;
    cli::DepthFormat depth = cli::DepthFormat::D32F;
    cli::NormalSpace space = cli::NormalSpace::View;
    cli::NormalFormat format = cli::NormalFormat::RGBA16F;
    bool reverse_z = false;     // clear depth 0, GL_GREATER
    bool zero_to_one = false;   // glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) while drawing
    int samples = 0;            // > 1: GL_TEXTURE_2D_MULTISAMPLE textures of that many samples (--msaa)
};

class GBuffer {
public:
    // Makes the textures, the framebuffer, the program and uploads the mesh.
    // Throws gl_util::Error.
    GBuffer(GladGLContext& gl, const Desc& desc, const scene::Mesh& mesh);
    ~GBuffer();
    GBuffer(const GBuffer&) = delete;
    GBuffer& operator=(const GBuffer&) = delete;

    // Draws the mesh. Normals are written in the chosen space (world, or view
    // through view's rotation) and packing (signed, or n * 0.5 + 0.5 for rgba8),
    // facing the viewer on back faces.
    void render(const glm::mat4& view, const glm::mat4& projection);

    // GL_TEXTURE_2D, or GL_TEXTURE_2D_MULTISAMPLE when desc.samples > 1.
    GLuint depth_texture() const { return depth_; }
    GLuint normal_texture() const { return normal_; }
    const Desc& desc() const { return desc_; }
    // Depth value of empty pixels (the clear value).
    float clear_depth() const { return desc_.reverse_z ? 0.0f : 1.0f; }

private:
    void release();
    GladGLContext& gl_;
    Desc desc_;
    GLuint depth_ = 0, normal_ = 0, fbo_ = 0, program_ = 0;
    GLuint vao_ = 0, buffers_[3] = {0, 0, 0};
    GLsizei index_count_ = 0;
};

}  // namespace gbuffer
