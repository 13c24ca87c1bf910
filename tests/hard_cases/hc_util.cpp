#include "hc_util.h"

#include "uniforms.h"  // SSAO_PLANE_TOLERANCE (shaders/ssao_constants.h)
#include "test_scenes.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

namespace hc {

Out run(testgl::Fixture& fx, const analytic::GBuffer& g, const glm::dmat4& proj, ssao_clip_range clip,
        const RunOptions& o) {
    Out r;
    const int W = g.width + o.pad_x + o.pad_right, H = g.height + o.pad_y + o.pad_top;
    analytic::GBuffer shown = g;
    if (o.normals) shown.normal = *o.normals;
    if (o.normal_space == SSAO_NORMAL_SPACE_WORLD) shown = with_world_normals(std::move(shown), o.view_matrix);
    const testgl::Textures t = inset_textures(fx, shown, o.pad_x, o.pad_y, W, H, o.depth_format, o.normal_format);
    ssao_inputs in = fx.inputs(t.depth, t.normal, proj, clip);
    in.normal_space = o.normal_space;
    in.normal_packing = testgl::packing_of(o.normal_format);
    if (o.normal_space == SSAO_NORMAL_SPACE_WORLD) analytic::to_floats(o.view_matrix, in.view_matrix);
    if (o.depth_only) in.normal_texture = 0;
    if (W != g.width || H != g.height) testgl::set_viewport(in, o.pad_x, o.pad_y, g.width, g.height);
    r.output.size = sizeof r.output;
    fx.gl().Finish();
    const auto t0 = std::chrono::steady_clock::now();
    r.status = fx.api().execute(fx.ctx(), &in, &r.output);
    fx.gl().Finish();
    r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (r.status == SSAO_OK) r.ao = fx.read_red(r.output.texture, g.width, g.height);
    return r;
}

testgl::Textures inset_textures(testgl::Fixture& fx, const analytic::GBuffer& g, int x, int y, int tw, int th,
                                GLenum depth_format, GLenum normal_format) {
    std::vector<float> depth(static_cast<size_t>(tw) * th, 0.37f);
    std::vector<glm::vec3> normal(depth.size(), glm::vec3(0.6f, -0.8f, 0.0f));
    for (int gy = 0; gy < g.height; ++gy)
        for (int gx = 0; gx < g.width; ++gx) {
            depth[at(gx + x, gy + y, tw)] = g.depth[at(gx, gy, g.width)];
            normal[at(gx + x, gy + y, tw)] = g.normal[at(gx, gy, g.width)];
        }
    testgl::Textures t;
    t.depth = fx.make_depth(depth_format, tw, th, depth);
    t.normal = fx.make_normals(normal_format, tw, th, normal);
    return t;
}

GLuint sentinel_texture(GladGLContext& gl, int tw, int th, float value) {
    const std::vector<float> texels(static_cast<size_t>(tw) * th, value);
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D, t);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R32F, tw, th, 0, GL_RED, GL_FLOAT, texels.data());
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    return t;
}

analytic::GBuffer with_world_normals(analytic::GBuffer g, const glm::dmat4& view) {
    const glm::dmat3 to_world = glm::transpose(glm::dmat3(view));
    for (glm::vec3& n : g.normal) n = glm::vec3(to_world * glm::dvec3(n));
    return g;
}

int check_unit_finite(const std::vector<float>& ao, const char* what) {
    int bad = 0;
    for (float v : ao)
        if (!(std::isfinite(v) && v >= 0.0f && v <= 1.0f)) ++bad;
    INFO(what << ": " << bad << " of " << ao.size() << " pixels are not finite or outside [0,1]");
    CHECK(bad == 0);
    CHECK(!ao.empty());
    return bad;
}

ssao_settings make(uint32_t samples, ssao_blur blur, ssao_rotation rotation, float radius, ssao_method method) {
    ssao_settings s = testscenes::make(samples, blur, rotation);
    s.method = method;
    s.radius = radius;
    s.output_format = SSAO_OUTPUT_R16F;
    return s;
}

glm::dmat4 ortho_zo(double half_w, double half_h, double n, double f) {
    glm::dmat4 m(1.0);
    m[0][0] = 1.0 / half_w;
    m[1][1] = 1.0 / half_h;
    m[2][2] = -1.0 / (f - n);
    m[3][2] = -n / (f - n);
    return m;
}

glm::dmat4 ortho_reverse(double half_w, double half_h, double n, double f) {
    glm::dmat4 m(1.0);
    m[0][0] = 1.0 / half_w;
    m[1][1] = 1.0 / half_h;
    m[2][2] = 1.0 / (f - n);
    m[3][2] = f / (f - n);
    return m;
}

glm::dmat4 reverse_z_gl(double fovy, double aspect, double n, double f) {
    glm::dmat4 m = analytic::perspective(fovy, aspect, n, f);
    m[2][2] = (f + n) / (f - n);
    m[3][2] = 2.0 * f * n / (f - n);
    return m;
}

glm::dmat4 frustum(double l, double r, double b, double t, double n, double f) {
    glm::dmat4 m(0.0);
    m[0][0] = 2 * n / (r - l);
    m[1][1] = 2 * n / (t - b);
    m[2][0] = (r + l) / (r - l);
    m[2][1] = (t + b) / (t - b);
    m[2][2] = -(f + n) / (f - n);
    m[2][3] = -1.0;
    m[3][2] = -2 * f * n / (f - n);
    return m;
}

glm::dmat4 pixel_shift(const glm::dmat4& proj, double px, double py, int w, int h) {
    glm::dmat4 shift(1.0);
    shift[3][0] = 2.0 * px / w;
    shift[3][1] = 2.0 * py / h;
    return shift * proj;
}

double tangent_plane_z(const analytic::GBuffer& g, const glm::dmat4& proj, int x0, int y0, int x, int y) {
    const size_t c = static_cast<size_t>(y0) * g.width + x0;
    const glm::dvec3 P0 = g.position[c];
    const glm::dvec3 n = glm::dvec3(g.normal[c]);
    // Two points of the pixel's ray: its NDC point on the near and the far
    // clip planes, back through the projection (any convention, any camera).
    const glm::dmat4 inv = glm::inverse(proj);
    const double nx = (x + 0.5) / g.width * 2.0 - 1.0, ny = (y + 0.5) / g.height * 2.0 - 1.0;
    auto unproject = [&](double nz) {
        const glm::dvec4 h = inv * glm::dvec4(nx, ny, nz, 1.0);
        return glm::dvec3(h) / h.w;
    };
    const glm::dvec3 A = unproject(-0.5), B = unproject(0.5);
    const double along = glm::dot(n, B - A);
    if (along == 0.0) return P0.z;
    return (A + (B - A) * (glm::dot(n, P0 - A) / along)).z;
}

double blur_depth_weight(const analytic::GBuffer& g, const glm::dmat4& proj, double relative_tolerance, int x0, int y0,
                         int x, int y) {
    // A pixel has a tangent plane for the blur where its normal is not along the view axis.
    auto has_plane = [&g](size_t i) { return g.normal[i].x != 0.0f || g.normal[i].y != 0.0f; };
    const size_t c = static_cast<size_t>(y0) * g.width + x0;
    const size_t t = static_cast<size_t>(y) * g.width + x;
    const double z0 = g.position[c].z;
    const bool plane = has_plane(c);
    const double tolerance = std::max(relative_tolerance * std::abs(z0) * (plane ? SSAO_PLANE_TOLERANCE : 1.0), 1e-30);
    const double expected = plane ? tangent_plane_z(g, proj, x0, y0, x, y) : z0;
    double dz = std::abs(g.position[t].z - expected);
    if (plane && has_plane(t)) dz += std::abs(tangent_plane_z(g, proj, x, y, x0, y0) - z0);  // both ways
    return std::clamp(1.0 - dz / tolerance, 0.0, 1.0);
}

double depth_at(const glm::dmat4& proj, ssao_clip_range clip, double t) {
    const glm::dvec4 c = proj * glm::dvec4(0, 0, -t, 1);
    const double z = c.z / c.w;
    return clip == SSAO_CLIP_ZERO_TO_ONE ? z : z * 0.5 + 0.5;
}

int format_bits(GLenum f) {
    switch (f) {
        case GL_DEPTH_COMPONENT16: return 16;
        case GL_DEPTH_COMPONENT24:
        case GL_DEPTH24_STENCIL8: return 24;
        default: return 32;
    }
}

namespace {
double distance_of(const glm::dmat4& proj, ssao_clip_range clip, double d) {
    const double ndc = clip == SSAO_CLIP_ZERO_TO_ONE ? d : d * 2 - 1;
    const glm::dvec4 v = glm::inverse(proj) * glm::dvec4(0, 0, ndc, 1);
    return -v.z / v.w;
}
}  // namespace

double depth_step(const glm::dmat4& proj, ssao_clip_range clip, GLenum fmt, double t) {
    const double d = depth_at(proj, clip, t);
    const int bits = format_bits(fmt);
    double step;
    if (bits == 32) {
        const float fd = static_cast<float>(d);
        step = static_cast<double>(std::nextafter(fd, 2.0f)) - fd;
        // With GL's [-1,1] clip range the rasteriser holds NDC z in float
        // before depth = ndc * 0.5 + 0.5: the stored value cannot be finer
        // than half an ulp of NDC z (this is why reverse-Z needs [0,1]).
        if (clip != SSAO_CLIP_ZERO_TO_ONE) {
            const float ndc = static_cast<float>(d * 2.0 - 1.0);
            step = std::max(step, 0.5 * (static_cast<double>(std::nextafter(ndc, 2.0f)) - ndc));
        }
    } else {
        step = 1.0 / (std::ldexp(1.0, bits) - 1.0);
    }
    return std::abs(distance_of(proj, clip, d + step) - distance_of(proj, clip, d));
}

double design_step(GLenum fmt, bool reverse_zo, double n, double t) {
    const int bits = format_bits(fmt);
    if (bits == 16) return 1.5e-5 * t * t / n;
    if (bits == 32 && reverse_zo) return 1.2e-7 * t;
    return 6e-8 * t * t / n;
}

double quantise(double d, GLenum fmt) {
    const int bits = format_bits(fmt);
    if (bits == 32) return static_cast<float>(d);
    const double m = std::ldexp(1.0, bits) - 1.0;
    return std::round(d * m) / m;
}

glm::vec3 shader_view_position(const glm::dmat4& proj, ssao_clip_range clip, int px, int py, int w, int h,
                               float depth) {
    const glm::mat4 inv(glm::inverse(glm::dmat4(glm::mat4(proj))));  // float matrix in, double inverse, float out
    const glm::vec2 ndc = (glm::vec2(static_cast<float>(px), static_cast<float>(py)) + 0.5f) /
                              glm::vec2(static_cast<float>(w), static_cast<float>(h)) * 2.0f -
                          1.0f;
    const float z = clip == SSAO_CLIP_ZERO_TO_ONE ? depth : depth * 2.0f - 1.0f;
    const glm::vec4 v = inv * glm::vec4(ndc, z, 1.0f);
    return glm::vec3(v) / v.w;
}

void gl_window_depth(analytic::GBuffer& g, ssao_clip_range clip, GLenum depth_format) {
    if (clip == SSAO_CLIP_ZERO_TO_ONE || format_bits(depth_format) != 32) return;
    for (size_t i = 0; i < g.depth.size(); ++i) {
        if (std::isnan(g.position[i].x)) continue;  // sky: the clear value, exact
        const float ndc = static_cast<float>(static_cast<double>(g.depth[i]) * 2.0 - 1.0);
        g.depth[i] = ndc * 0.5f + 0.5f;
    }
}

double mean(const std::vector<float>& v, const std::function<bool(size_t)>& mask) {
    double s = 0;
    size_t n = 0;
    for (size_t i = 0; i < v.size(); ++i)
        if (!mask || mask(i)) {
            s += v[i];
            ++n;
        }
    return n ? s / static_cast<double>(n) : std::nan("");
}

}  // namespace hc

namespace hc {

glm::dmat4 crease_view(double scale, glm::dvec3 eye_offset) {
    glm::dmat4 rot(1.0);
    const double a = 0.436, c = std::cos(a), s = std::sin(a);
    rot[1][1] = c; rot[1][2] = s; rot[2][1] = -s; rot[2][2] = c;  // rotate about x by a
    glm::dmat4 tr(1.0);
    tr[3] = glm::dvec4(-eye_offset - glm::dvec3(0, 2 * scale, 0), 1.0);
    return rot * tr;
}

analytic::Scene crease_world(double k, bool boxes, glm::dvec3 o) {
    analytic::Scene s;
    s.add_quad(o + k * glm::dvec3(-50, 0, 50), k * glm::dvec3(100, 0, 0), k * glm::dvec3(0, 0, -56));
    s.add_quad(o + k * glm::dvec3(-50, 0, -6), k * glm::dvec3(100, 0, 0), k * glm::dvec3(0, 50, 0));
    if (boxes) {
        s.add_box(o + k * glm::dvec3(-2.0, 0, -4.5), o + k * glm::dvec3(-0.8, 1.2, -3.3));
        s.add_box(o + k * glm::dvec3(0.9, 0, -5.4), o + k * glm::dvec3(1.7, 2.0, -4.6));
    }
    return s;
}

analytic::Scene to_view(const analytic::Scene& world, const glm::dmat4& view) {
    analytic::Scene s;
    for (const auto& q : world.quads)
        s.add_quad(glm::dvec3(view * glm::dvec4(q.origin, 1.0)), glm::dvec3(view * glm::dvec4(q.u, 0.0)),
                   glm::dvec3(view * glm::dvec4(q.v, 0.0)));
    return s;
}

Diff diff(const std::vector<float>& a, const std::vector<float>& b, const std::function<bool(size_t)>& mask,
          double one_sample) {
    // Two images of one size: an empty or short one (a failed run) must not pass as "no difference".
    CHECK(a.size() == b.size());
    CHECK(!a.empty());
    Diff d;
    double sum = 0;
    for (size_t i = 0; i < a.size() && i < b.size(); ++i) {
        if (mask && !mask(i)) continue;
        const double e = std::abs(static_cast<double>(a[i]) - b[i]);
        ++d.compared;
        sum += e;
        if (e > 1e-3) ++d.over_1e3;
        if (e > one_sample + 2e-3) ++d.over_one_sample;
        d.worst = std::max(d.worst, e);
    }
    d.mean_abs = d.compared ? sum / static_cast<double>(d.compared) : 0;
    return d;
}

analytic::Scene crease_scene(double scale, bool boxes) {
    return to_view(crease_world(scale, boxes), crease_view(scale));
}

analytic::Scene sky_scene() {
    analytic::Scene s;
    s.add_quad({-2, -2, -6}, {3, 0, 0}, {0, 3, 0});
    s.add_box({0.5, -1.0, -5.0}, {1.5, 0.5, -4.0});
    s.add_quad({-3, 0.5, -7}, {2, 0, 0}, {0, 0, 2});
    return s;
}

analytic::GBuffer crease_gbuffer(const glm::dmat4& proj, ssao_clip_range clip, int w, int h) {
    return analytic::render(crease_scene(), proj, clip, w, h);
}

CreaseSetup::CreaseSetup(int w, int h, const glm::dmat4& projection, ssao_clip_range clip)
    : W(w), H(h), proj(projection), g(crease_gbuffer(projection, clip, w, h)) {}

CreaseReverseZ::CreaseReverseZ()
    : CreaseSetup(64, 48, analytic::reverse_z(kFov, 64.0 / 48.0, 0.1, 100.0), SSAO_CLIP_ZERO_TO_ONE) {}

CreaseGl::CreaseGl()
    : CreaseSetup(64, 48, analytic::perspective(kFov, 64.0 / 48.0, 0.1, 100.0), SSAO_CLIP_NEGATIVE_ONE_TO_ONE) {}

}  // namespace hc
