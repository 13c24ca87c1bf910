#include "composite.h"

#include "gl_util.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace composite {

namespace {

const char* kFragment = R"glsl(#version 330 core
uniform sampler2D u_depth;
uniform sampler2D u_normal;
uniform sampler2D u_ao;
uniform mat4 u_inv_projection;   // clip -> view
uniform int u_zero_to_one;       // depth = ndc_z (else ndc_z * 0.5 + 0.5)
uniform float u_clear_depth;     // empty pixels
uniform vec2 u_size;
uniform int u_orthographic;
uniform mat3 u_view_rotation;    // world -> view, for world-space normals
uniform int u_world_space;
uniform int u_unorm;
uniform int u_use_ao;
uniform ivec2 u_ao_origin;
uniform vec3 u_light_position;   // view space
uniform vec3 u_light_color;
uniform float u_linear;
uniform float u_quadratic;
uniform float u_distance_scale;
uniform float u_albedo;
uniform vec3 u_sky;
out vec4 o_color;

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    float depth = texelFetch(u_depth, pixel, 0).r;
    if (depth == u_clear_depth) {
        o_color = vec4(u_sky, 1.0);
        return;
    }
    // View-space position from depth: no position buffer.
    vec2 ndc_xy = (vec2(pixel) + 0.5) / u_size * 2.0 - 1.0;
    float ndc_z = u_zero_to_one == 1 ? depth : depth * 2.0 - 1.0;
    vec4 h = u_inv_projection * vec4(ndc_xy, ndc_z, 1.0);
    vec3 frag_pos = h.xyz / h.w;

    vec3 normal = texelFetch(u_normal, pixel, 0).xyz;
    if (u_unorm == 1) normal = normal * 2.0 - 1.0;
    if (u_world_space == 1) normal = u_view_rotation * normal;
    normal = normalize(normal);
    float ambient_occlusion = u_use_ao == 1 ? texelFetch(u_ao, pixel + u_ao_origin, 0).r : 1.0;
    vec3 diffuse_color = vec3(u_albedo);

    // Blinn-Phong in view space, as in the chapter's lighting pass.
    vec3 ambient = vec3(0.3 * diffuse_color * ambient_occlusion);
    vec3 lighting = ambient;
    vec3 view_dir = u_orthographic == 1 ? vec3(0.0, 0.0, 1.0) : normalize(-frag_pos);
    vec3 light_dir = normalize(u_light_position - frag_pos);
    vec3 diffuse = max(dot(normal, light_dir), 0.0) * diffuse_color * u_light_color;
    vec3 halfway_dir = normalize(light_dir + view_dir);
    float spec = pow(max(dot(normal, halfway_dir), 0.0), 8.0);
    vec3 specular = u_light_color * spec;
    float dist = length(u_light_position - frag_pos) * u_distance_scale;
    float attenuation = 1.0 / (1.0 + u_linear * dist + u_quadratic * dist * dist);
    diffuse *= attenuation;
    specular *= attenuation;
    lighting += diffuse + specular;
    o_color = vec4(lighting, 1.0);
}
)glsl";

bool is_orthographic(const glm::mat4& p) { return p[3][3] == 1.0f && p[2][3] == 0.0f; }

// RGBA float pixels, bottom row first, as RGB8 top row first.
std::vector<uint8_t> to_rgb8_top_down(const std::vector<float>& rgba, int width, int height) {
    std::vector<uint8_t> rgb(static_cast<size_t>(width) * static_cast<size_t>(height) * 3);
    for (int y = 0; y < height; ++y) {
        const size_t src_row = static_cast<size_t>(height - 1 - y) * static_cast<size_t>(width);
        const size_t dst_row = static_cast<size_t>(y) * static_cast<size_t>(width);
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                const float v = std::clamp(rgba[(src_row + static_cast<size_t>(x)) * 4 + static_cast<size_t>(c)], 0.0f, 1.0f);
                rgb[(dst_row + static_cast<size_t>(x)) * 3 + static_cast<size_t>(c)] =
                    static_cast<uint8_t>(std::lround(v * 255.0f));
            }
    }
    return rgb;
}

}  // namespace

Lighting default_lighting(const glm::vec3& bounds_min, const glm::vec3& bounds_max, const glm::mat4& view) {
    Lighting l;
    const glm::vec3 centre = 0.5f * (bounds_min + bounds_max);
    float diagonal = glm::length(bounds_max - bounds_min);
    if (!(diagonal > 0.0f) || !std::isfinite(diagonal)) diagonal = 1.0f;
    const glm::vec3 light_world = centre + diagonal * glm::vec3(0.15f, 0.35f, 0.2f);
    l.light_view = glm::vec3(view * glm::vec4(light_world, 1.0f));
    l.distance_scale = 10.0f / diagonal;
    return l;
}

Compositor::Compositor(GladGLContext& gl, int width, int height) : gl_(gl), width_(width), height_(height) {
    try {
        program_ = gl_util::make_program(gl, "composite", gl_util::fullscreen_vertex_shader().c_str(), kFragment);
        gl.GenVertexArrays(1, &vao_);
        target_ = gl_util::make_texture(gl, GL_RGBA8, width, height);
        gl.GenFramebuffers(1, &fbo_);
        gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target_, 0);
        const GLenum draw_buffer = GL_COLOR_ATTACHMENT0;
        gl.DrawBuffers(1, &draw_buffer);
        gl_util::check_framebuffer(gl, "composite");
        gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
        // texelFetch everywhere; the sampler only keeps the host's inputs
        // complete whatever their own filter parameters.
        gl.GenSamplers(1, &sampler_);
        gl.SamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl.SamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl.SamplerParameteri(sampler_, GL_TEXTURE_COMPARE_MODE, GL_NONE);
        gl_util::check(gl, "composite setup");
    } catch (...) {
        release();
        throw;
    }
}

Compositor::~Compositor() { release(); }

void Compositor::release() {
    if (sampler_) gl_.DeleteSamplers(1, &sampler_);
    if (fbo_) gl_.DeleteFramebuffers(1, &fbo_);
    if (target_) gl_.DeleteTextures(1, &target_);
    if (vao_) gl_.DeleteVertexArrays(1, &vao_);
    if (program_) gl_.DeleteProgram(program_);
    sampler_ = fbo_ = target_ = vao_ = program_ = 0;
}

std::vector<uint8_t> Compositor::render(const gbuffer::GBuffer& g, const glm::mat4& view,
                                        const glm::mat4& projection, GLuint ao_texture, glm::ivec2 ao_origin,
                                        const Lighting& l) {
    draw(g, view, projection, ao_texture, ao_origin, l);
    return read();
}

std::vector<uint8_t> Compositor::read() const {
    const std::vector<float> rgba = gl_util::read_texture(gl_, target_, 0, 0, width_, height_, 4);
    return to_rgb8_top_down(rgba, width_, height_);
}

void Compositor::draw(const gbuffer::GBuffer& g, const glm::mat4& view, const glm::mat4& projection,
                      GLuint ao_texture, glm::ivec2 ao_origin, const Lighting& l) {
    auto& gl = gl_;
    gl.BindFramebuffer(GL_FRAMEBUFFER, fbo_);
    gl.Viewport(0, 0, width_, height_);
    gl.Disable(GL_DEPTH_TEST);
    gl.Disable(GL_BLEND);
    gl.UseProgram(program_);
    const GLuint textures[3] = {g.depth_texture(), g.normal_texture(), ao_texture};
    const char* names[3] = {"u_depth", "u_normal", "u_ao"};
    for (int unit = 0; unit < 3; ++unit) {
        gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
        gl.BindTexture(GL_TEXTURE_2D, textures[unit]);
        gl.BindSampler(static_cast<GLuint>(unit), sampler_);
        gl.Uniform1i(gl.GetUniformLocation(program_, names[unit]), unit);
    }
    const glm::mat4 inv = glm::mat4(glm::inverse(glm::dmat4(projection)));
    auto loc = [&](const char* n) { return gl.GetUniformLocation(program_, n); };
    gl.UniformMatrix4fv(loc("u_inv_projection"), 1, GL_FALSE, glm::value_ptr(inv));
    gl.Uniform1i(loc("u_zero_to_one"), g.desc().zero_to_one ? 1 : 0);
    gl.Uniform1f(loc("u_clear_depth"), g.clear_depth());
    gl.Uniform2f(loc("u_size"), static_cast<float>(width_), static_cast<float>(height_));
    gl.Uniform1i(loc("u_orthographic"), is_orthographic(projection) ? 1 : 0);
    const glm::mat3 rotation(view);
    gl.UniformMatrix3fv(loc("u_view_rotation"), 1, GL_FALSE, glm::value_ptr(rotation));
    gl.Uniform1i(loc("u_world_space"), g.desc().space == cli::NormalSpace::World ? 1 : 0);
    gl.Uniform1i(loc("u_unorm"), g.desc().format == cli::NormalFormat::RGBA8 ? 1 : 0);
    gl.Uniform1i(loc("u_use_ao"), ao_texture != 0 ? 1 : 0);
    gl.Uniform2i(loc("u_ao_origin"), ao_origin.x, ao_origin.y);
    gl.Uniform3fv(loc("u_light_position"), 1, glm::value_ptr(l.light_view));
    gl.Uniform3fv(loc("u_light_color"), 1, glm::value_ptr(l.light_color));
    gl.Uniform1f(loc("u_linear"), l.linear);
    gl.Uniform1f(loc("u_quadratic"), l.quadratic);
    gl.Uniform1f(loc("u_distance_scale"), l.distance_scale);
    gl.Uniform1f(loc("u_albedo"), l.albedo);
    gl.Uniform3fv(loc("u_sky"), 1, glm::value_ptr(l.sky));
    gl.BindVertexArray(vao_);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    gl.BindVertexArray(0);
    gl.UseProgram(0);
    for (int unit = 2; unit >= 0; --unit) {
        gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
        gl.BindTexture(GL_TEXTURE_2D, 0);
        gl.BindSampler(static_cast<GLuint>(unit), 0);
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl_util::check(gl, "the composite pass");
}

}  // namespace composite
