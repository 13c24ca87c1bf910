#include "textbook_ssao.h"

#include "gl_util.h"

#include <glm/gtc/type_ptr.hpp>

#include <random>
#include <string>

namespace textbook {

namespace {

const char* kGeometryVs = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_view;
uniform mat4 u_projection;
out vec3 v_view_pos;
void main() {
    vec4 p = u_view * vec4(a_position, 1.0);
    v_view_pos = p.xyz;
    gl_Position = u_projection * p;
})";
const char* kGeometryFs = R"(#version 330 core
in vec3 v_view_pos;
layout(location = 0) out vec4 g_position;
void main() { g_position = vec4(v_view_pos, 1.0); })";

const char* kQuadVs = R"(#version 330 core
out vec2 TexCoords;
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    TexCoords = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
})";

// The chapter's fragment shader, with noiseScale from the actual size.
const char* kSsaoFs = R"(#version 330 core
out float FragColor;
in vec2 TexCoords;
uniform sampler2D gPosition;
uniform sampler2D gNormal;
uniform sampler2D texNoise;
uniform vec3 samples[64];
uniform int kernelSize;
uniform float radius;
uniform float bias;
uniform vec2 noiseScale;
uniform mat4 projection;
void main() {
    vec4 g = texture(gPosition, TexCoords);
    if (g.w == 0.0) { FragColor = 1.0; return; }  // background
    vec3 fragPos = g.xyz;
    vec3 normal = normalize(texture(gNormal, TexCoords).rgb);
    vec3 randomVec = normalize(texture(texNoise, TexCoords * noiseScale).xyz);
    vec3 tangent = normalize(randomVec - normal * dot(randomVec, normal));
    vec3 bitangent = cross(normal, tangent);
    mat3 TBN = mat3(tangent, bitangent, normal);
    float occlusion = 0.0;
    for (int i = 0; i < kernelSize; ++i) {
        vec3 samplePos = TBN * samples[i];
        samplePos = fragPos + samplePos * radius;
        vec4 offset = vec4(samplePos, 1.0);
        offset = projection * offset;
        offset.xyz /= offset.w;
        offset.xyz = offset.xyz * 0.5 + 0.5;
        vec4 s = texture(gPosition, offset.xy);
        float sampleDepth = s.w == 0.0 ? -1e30 : s.z;  // background: far away
        float rangeCheck = smoothstep(0.0, 1.0, radius / abs(fragPos.z - sampleDepth));
        occlusion += (sampleDepth >= samplePos.z + bias ? 1.0 : 0.0) * rangeCheck;
    }
    FragColor = 1.0 - (occlusion / kernelSize);
})";

const char* kBlurFs = R"(#version 330 core
out float FragColor;
in vec2 TexCoords;
uniform sampler2D ssaoInput;
void main() {
    vec2 texelSize = 1.0 / vec2(textureSize(ssaoInput, 0));
    float result = 0.0;
    for (int x = -2; x < 2; ++x)
        for (int y = -2; y < 2; ++y) {
            vec2 offset = vec2(float(x), float(y)) * texelSize;
            result += texture(ssaoInput, TexCoords + offset).r;
        }
    FragColor = result / (4.0 * 4.0);
})";

GLuint texture(GladGLContext& gl, GLenum internal, GLenum format, int w, int h, GLenum filter, const void* data) {
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D, t);
    gl.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), w, h, 0, format, GL_FLOAT, data);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

GLuint framebuffer(GladGLContext& gl, GLuint color) {
    GLuint f = 0;
    gl.GenFramebuffers(1, &f);
    gl.BindFramebuffer(GL_FRAMEBUFFER, f);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    return f;
}

float lerp(float a, float b, float f) { return a + f * (b - a); }

}  // namespace

Pass::Pass(GladGLContext& gl, const scene::Mesh& mesh, int width, int height, float radius)
    : gl_(gl), width_(width), height_(height), radius_(radius) {
    gl.GenVertexArrays(1, &vao_);
    gl.GenVertexArrays(1, &empty_vao_);
    gl.BindVertexArray(vao_);
    gl.GenBuffers(2, buffers_);
    gl.BindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.positions.size() * sizeof(glm::vec3)),
                  mesh.positions.data(), GL_STATIC_DRAW);
    gl.EnableVertexAttribArray(0);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
    gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(uint32_t)),
                  mesh.indices.data(), GL_STATIC_DRAW);
    index_count_ = static_cast<GLuint>(mesh.indices.size());
    gl.BindVertexArray(0);

    position_tex_ = texture(gl, GL_RGBA32F, GL_RGBA, width, height, GL_NEAREST, nullptr);
    gbuffer_fbo_ = framebuffer(gl, position_tex_);
    gl.GenRenderbuffers(1, &depth_rb_);
    gl.BindRenderbuffer(GL_RENDERBUFFER, depth_rb_);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT32F, width, height);
    gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_rb_);
    ssao_tex_ = texture(gl, GL_R16F, GL_RED, width, height, GL_NEAREST, nullptr);
    ssao_fbo_ = framebuffer(gl, ssao_tex_);
    blur_tex_ = texture(gl, GL_R16F, GL_RED, width, height, GL_NEAREST, nullptr);
    blur_fbo_ = framebuffer(gl, blur_tex_);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);

    // The chapter's kernel and noise, with its generator.
    std::uniform_real_distribution<float> random(0.0f, 1.0f);
    std::default_random_engine generator;
    for (int i = 0; i < 64; ++i) {
        glm::vec3 s(random(generator) * 2.0f - 1.0f, random(generator) * 2.0f - 1.0f, random(generator));
        s = glm::normalize(s);
        s *= random(generator);
        float scale = static_cast<float>(i) / 64.0f;
        scale = lerp(0.1f, 1.0f, scale * scale);
        kernel_.push_back(s * scale);
    }
    std::vector<glm::vec3> noise;
    for (int i = 0; i < 16; ++i)
        noise.emplace_back(random(generator) * 2.0f - 1.0f, random(generator) * 2.0f - 1.0f, 0.0f);
    noise_tex_ = texture(gl, GL_RGB32F, GL_RGB, 4, 4, GL_NEAREST, noise.data());
    gl.BindTexture(GL_TEXTURE_2D, noise_tex_);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);

    geometry_program_ = gl_util::make_program(gl, "textbook geometry", kGeometryVs, kGeometryFs);
    ssao_program_ = gl_util::make_program(gl, "textbook SSAO", kQuadVs, kSsaoFs);
    blur_program_ = gl_util::make_program(gl, "textbook blur", kQuadVs, kBlurFs);
    gl.UseProgram(ssao_program_);
    gl.Uniform1i(gl.GetUniformLocation(ssao_program_, "gPosition"), 0);
    gl.Uniform1i(gl.GetUniformLocation(ssao_program_, "gNormal"), 1);
    gl.Uniform1i(gl.GetUniformLocation(ssao_program_, "texNoise"), 2);
    // The chapter uploads 64 uniforms by name every frame; once is enough here.
    for (int i = 0; i < 64; ++i)
        gl.Uniform3fv(gl.GetUniformLocation(ssao_program_, ("samples[" + std::to_string(i) + "]").c_str()), 1,
                      glm::value_ptr(kernel_[static_cast<size_t>(i)]));
    gl.Uniform1i(gl.GetUniformLocation(ssao_program_, "kernelSize"), 64);
    gl.Uniform1f(gl.GetUniformLocation(ssao_program_, "radius"), radius_);
    gl.Uniform1f(gl.GetUniformLocation(ssao_program_, "bias"), 0.025f);
    gl.Uniform2f(gl.GetUniformLocation(ssao_program_, "noiseScale"), width / 4.0f, height / 4.0f);
    gl.UseProgram(blur_program_);
    gl.Uniform1i(gl.GetUniformLocation(blur_program_, "ssaoInput"), 0);
    gl.UseProgram(0);
    gl.GenQueries(2, queries_);
}

Pass::~Pass() {
    gl_.DeleteQueries(2, queries_);
    gl_.DeleteProgram(geometry_program_);
    gl_.DeleteProgram(ssao_program_);
    gl_.DeleteProgram(blur_program_);
    const GLuint textures[] = {position_tex_, ssao_tex_, blur_tex_, noise_tex_};
    gl_.DeleteTextures(4, textures);
    const GLuint fbos[] = {gbuffer_fbo_, ssao_fbo_, blur_fbo_};
    gl_.DeleteFramebuffers(3, fbos);
    gl_.DeleteRenderbuffers(1, &depth_rb_);
    gl_.DeleteBuffers(2, buffers_);
    gl_.DeleteVertexArrays(1, &vao_);
    gl_.DeleteVertexArrays(1, &empty_vao_);
}

void Pass::render_positions(const glm::mat4& view, const glm::mat4& projection) {
    GladGLContext& gl = gl_;
    gl.BindFramebuffer(GL_FRAMEBUFFER, gbuffer_fbo_);
    gl.Viewport(0, 0, width_, height_);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    gl.ClearColor(0, 0, 0, 0);
    gl.ClearDepth(1.0);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.UseProgram(geometry_program_);
    gl.UniformMatrix4fv(gl.GetUniformLocation(geometry_program_, "u_view"), 1, GL_FALSE, glm::value_ptr(view));
    gl.UniformMatrix4fv(gl.GetUniformLocation(geometry_program_, "u_projection"), 1, GL_FALSE,
                        glm::value_ptr(projection));
    gl.BindVertexArray(vao_);
    gl.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(index_count_), GL_UNSIGNED_INT, nullptr);
    gl.Disable(GL_DEPTH_TEST);
}

void Pass::run(GLuint normal_texture, const glm::mat4& projection) {
    GladGLContext& gl = gl_;
    gl.QueryCounter(queries_[0], GL_TIMESTAMP);
    gl.BindFramebuffer(GL_FRAMEBUFFER, ssao_fbo_);
    gl.Viewport(0, 0, width_, height_);
    gl.UseProgram(ssao_program_);
    gl.UniformMatrix4fv(gl.GetUniformLocation(ssao_program_, "projection"), 1, GL_FALSE, glm::value_ptr(projection));
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, position_tex_);
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, normal_texture);
    gl.ActiveTexture(GL_TEXTURE2);
    gl.BindTexture(GL_TEXTURE_2D, noise_tex_);
    gl.BindVertexArray(empty_vao_);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.BindFramebuffer(GL_FRAMEBUFFER, blur_fbo_);
    gl.UseProgram(blur_program_);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, ssao_tex_);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.QueryCounter(queries_[1], GL_TIMESTAMP);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
}

double Pass::last_ms() {
    GLuint64 t0 = 0, t1 = 0;
    gl_.GetQueryObjectui64v(queries_[0], GL_QUERY_RESULT, &t0);
    gl_.GetQueryObjectui64v(queries_[1], GL_QUERY_RESULT, &t1);
    return static_cast<double>(t1 - t0) * 1e-6;
}

std::vector<float> Pass::read_ao() {
    std::vector<float> out(static_cast<size_t>(width_) * height_);
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, blur_fbo_);
    gl_.PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl_.ReadPixels(0, 0, width_, height_, GL_RED, GL_FLOAT, out.data());
    gl_.BindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return out;
}

}  // namespace textbook
