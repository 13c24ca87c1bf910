#include "gbuffer.h"

#include "gl_util.h"

#include <glm/gtc/type_ptr.hpp>

#include <limits>

namespace gbuffer {

namespace {

const char* kVertex = R"glsl(#version 330 core
layout(location = 0) in vec3 a_position;   // world space
layout(location = 1) in vec3 a_normal;     // world space
uniform mat4 u_view;
uniform mat4 u_projection;
out vec3 v_normal_world;
void main() {
    v_normal_world = a_normal;
    gl_Position = u_projection * (u_view * vec4(a_position, 1.0));
}
)glsl";

const char* kFragment = R"glsl(#version 330 core
in vec3 v_normal_world;
uniform mat3 u_view_rotation;   // world -> view
uniform int u_world_space;      // 1: store world-space normals
uniform int u_unorm;            // 1: store n * 0.5 + 0.5
layout(location = 0) out vec4 o_normal;
void main() {
    vec3 n = v_normal_world;
    float len2 = dot(n, n);
    // A degenerate normal must not become NaN: face the viewer instead.
    n = (len2 > 1e-20 && !isnan(len2) && !isinf(len2)) ? n * inversesqrt(len2)
                                                      : transpose(u_view_rotation) * vec3(0.0, 0.0, 1.0);
    if (!gl_FrontFacing) n = -n;
    if (u_world_space == 0) n = normalize(u_view_rotation * n);
    o_normal = vec4(u_unorm == 1 ? n * 0.5 + 0.5 : n, 1.0);
}
)glsl";

GLenum depth_internal_format(cli::DepthFormat f) {
    switch (f) {
        case cli::DepthFormat::D16: return GL_DEPTH_COMPONENT16;
        case cli::DepthFormat::D24: return GL_DEPTH_COMPONENT24;
        case cli::DepthFormat::D32F: return GL_DEPTH_COMPONENT32F;
    }
    return GL_DEPTH_COMPONENT32F;
}

// A multisampled texture of `samples` samples (fixed sample locations).
GLuint make_multisample_texture(GladGLContext& gl, GLenum internal_format, int samples, int width, int height) {
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, t);
    gl.TexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, internal_format, width, height, GL_TRUE);
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    return t;
}

}  // namespace

GBuffer::GBuffer(GladGLContext& gl, const Desc& desc, const scene::Mesh& mesh) : gl_(gl), desc_(desc) {
    if (mesh.indices.size() > static_cast<size_t>(std::numeric_limits<GLsizei>::max()))
        throw gl_util::Error("the scene has too many triangles for one draw call");
    try {
        const GLenum depth_format = depth_internal_format(desc.depth);
        const GLenum normal_format = desc.format == cli::NormalFormat::RGBA8 ? GL_RGBA8 : GL_RGBA16F;
        const bool ms = desc.samples > 1;
        if (ms) {
            depth_ = make_multisample_texture(gl, depth_format, desc.samples, desc.width, desc.height);
            normal_ = make_multisample_texture(gl, normal_format, desc.samples, desc.width, desc.height);
        } else {
            depth_ = gl_util::make_texture(gl, depth_format, desc.width, desc.height);
            normal_ = gl_util::make_texture(gl, normal_format, desc.width, desc.height);
        }
        const GLenum target = ms ? GL_TEXTURE_2D_MULTISAMPLE : GL_TEXTURE_2D;
        gl.GenFramebuffers(1, &fbo_);
        gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, target, depth_, 0);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, normal_, 0);
        const GLenum draw_buffer = GL_COLOR_ATTACHMENT0;
        gl.DrawBuffers(1, &draw_buffer);
        gl_util::check_framebuffer(gl, "G-buffer");
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);

        program_ = gl_util::make_program(gl, "G-buffer", kVertex, kFragment);

        gl.GenVertexArrays(1, &vao_);
        gl.GenBuffers(3, buffers_);
        gl.BindVertexArray(vao_);
        gl.BindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
        gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.positions.size() * sizeof(glm::vec3)),
                      mesh.positions.data(), GL_STATIC_DRAW);
        gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
        gl.EnableVertexAttribArray(0);
        gl.BindBuffer(GL_ARRAY_BUFFER, buffers_[1]);
        if (mesh.normals.size() == mesh.positions.size()) {
            gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.normals.size() * sizeof(glm::vec3)),
                          mesh.normals.data(), GL_STATIC_DRAW);
            gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
            gl.EnableVertexAttribArray(1);
        } else {
            gl.VertexAttrib3f(1, 0.0f, 0.0f, 0.0f);  // degenerate: the shader faces the viewer
        }
        gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[2]);
        gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                      mesh.indices.data(), GL_STATIC_DRAW);
        gl.BindVertexArray(0);
        gl.BindBuffer(GL_ARRAY_BUFFER, 0);
        index_count_ = static_cast<GLsizei>(mesh.indices.size());
        gl_util::check(gl, "G-buffer setup");
    } catch (...) {
        release();
        throw;
    }
}

GBuffer::~GBuffer() { release(); }

void GBuffer::release() {
    if (vao_) gl_.DeleteVertexArrays(1, &vao_);
    if (buffers_[0]) gl_.DeleteBuffers(3, buffers_);
    if (program_) gl_.DeleteProgram(program_);
    if (fbo_) gl_.DeleteFramebuffers(1, &fbo_);
    if (normal_) gl_.DeleteTextures(1, &normal_);
    if (depth_) gl_.DeleteTextures(1, &depth_);
    vao_ = program_ = fbo_ = normal_ = depth_ = 0;
    buffers_[0] = buffers_[1] = buffers_[2] = 0;
}

void GBuffer::render(const glm::mat4& view, const glm::mat4& projection) {
    auto& gl = gl_;
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    gl.Viewport(0, 0, desc_.width, desc_.height);
    if (desc_.zero_to_one) gl.ClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthMask(GL_TRUE);
    gl.DepthFunc(desc_.reverse_z ? GL_GREATER : GL_LESS);
    gl.Disable(GL_CULL_FACE);
    gl.Disable(GL_BLEND);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float clear_depth = this->clear_depth();
    gl.ClearBufferfv(GL_COLOR, 0, zero);
    gl.ClearBufferfv(GL_DEPTH, 0, &clear_depth);

    gl.UseProgram(program_);
    gl.UniformMatrix4fv(gl.GetUniformLocation(program_, "u_view"), 1, GL_FALSE, glm::value_ptr(view));
    gl.UniformMatrix4fv(gl.GetUniformLocation(program_, "u_projection"), 1, GL_FALSE, glm::value_ptr(projection));
    const glm::mat3 rotation(view);
    gl.UniformMatrix3fv(gl.GetUniformLocation(program_, "u_view_rotation"), 1, GL_FALSE, glm::value_ptr(rotation));
    gl.Uniform1i(gl.GetUniformLocation(program_, "u_world_space"), desc_.space == cli::NormalSpace::World ? 1 : 0);
    gl.Uniform1i(gl.GetUniformLocation(program_, "u_unorm"), desc_.format == cli::NormalFormat::RGBA8 ? 1 : 0);
    gl.BindVertexArray(vao_);
    gl.DrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
    gl.BindVertexArray(0);
    gl.UseProgram(0);

    gl.Disable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    if (desc_.zero_to_one) gl.ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_util::check(gl, "the G-buffer pass");
}

}  // namespace gbuffer
