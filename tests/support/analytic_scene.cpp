#include "analytic_scene.h"

#include <cmath>
#include <limits>

namespace analytic {

void Scene::add_box(glm::dvec3 lo, glm::dvec3 hi) {
    const glm::dvec3 dx(hi.x - lo.x, 0, 0), dy(0, hi.y - lo.y, 0), dz(0, 0, hi.z - lo.z);
    add_quad(lo, dx, dy);
    add_quad(lo + dz, dx, dy);
    add_quad(lo, dx, dz);
    add_quad(lo + dy, dx, dz);
    add_quad(lo, dy, dz);
    add_quad(lo + dx, dy, dz);
}

namespace {

// Ray-parallelogram intersection; returns t or +inf.
double intersect(const Quad& q, const glm::dvec3& o, const glm::dvec3& d, glm::dvec3& n_out) {
    const glm::dvec3 n = glm::cross(q.u, q.v);
    const double denom = glm::dot(n, d);
    if (std::abs(denom) < 1e-300) return std::numeric_limits<double>::infinity();
    const double t = glm::dot(n, q.origin - o) / denom;
    if (!(t > 0.0)) return std::numeric_limits<double>::infinity();
    const glm::dvec3 p = o + d * t - q.origin;
    // Solve p = a u + b v in the plane (least squares via the Gram matrix).
    const double uu = glm::dot(q.u, q.u), uv = glm::dot(q.u, q.v), vv = glm::dot(q.v, q.v);
    const double pu = glm::dot(p, q.u), pv = glm::dot(p, q.v);
    const double det = uu * vv - uv * uv;
    const double a = (pu * vv - pv * uv) / det, b = (pv * uu - pu * uv) / det;
    if (a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0) return std::numeric_limits<double>::infinity();
    n_out = glm::normalize(n);
    if (glm::dot(n_out, d) > 0.0) n_out = -n_out;
    return t;
}

}  // namespace

GBuffer render(const Scene& scene, const glm::dmat4& proj, ssao_clip_range clip, int width, int height) {
    GBuffer g;
    g.width = width;
    g.height = height;
    const size_t count = static_cast<size_t>(width) * height;
    g.depth.assign(count, 0.0f);
    g.normal.assign(count, glm::vec3(0.0f));
    g.position.assign(count, glm::dvec3(std::nan("")));
    const glm::dmat4 inv = glm::inverse(proj);
    const bool zo = clip == SSAO_CLIP_ZERO_TO_ONE;
    // The far value: which end of [0,1] lies farther away (reverse-Z or not).
    auto depth_of = [&](const glm::dvec3& p) {
        const glm::dvec4 c = proj * glm::dvec4(p, 1.0);
        const double z = c.z / c.w;
        return zo ? z : z * 0.5 + 0.5;
    };
    const double d_near = depth_of(glm::dvec3(0, 0, -1e-3)), d_far = depth_of(glm::dvec3(0, 0, -1e3));
    const bool reversed = d_far < d_near;
    const float sky = reversed ? 0.0f : 1.0f;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const double nx = (x + 0.5) / width * 2.0 - 1.0, ny = (y + 0.5) / height * 2.0 - 1.0;
            // Two points on the pixel's ray: at NDC depths inside any convention.
            const double z0 = zo ? 0.5 : 0.0;
            glm::dvec4 a = inv * glm::dvec4(nx, ny, z0, 1.0);
            glm::dvec4 b = inv * glm::dvec4(nx, ny, zo ? 0.25 : -0.5, 1.0);
            const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
            glm::dvec3 dir = glm::normalize(pa - pb);
            if (dir.z > 0) dir = -dir;  // towards -z, away from the eye
            // Ray origin: for perspective the eye; for orthographic a point far behind.
            const bool ortho = proj[2][3] == 0.0;
            glm::dvec3 origin(0.0);
            if (ortho) {  // start on the near plane, where the rasteriser clips
                const double ndc_near = reversed ? 1.0 : (zo ? 0.0 : -1.0);
                const glm::dvec4 o = inv * glm::dvec4(nx, ny, ndc_near, 1.0);
                origin = glm::dvec3(o) / o.w;
            }
            double best = std::numeric_limits<double>::infinity();
            glm::dvec3 best_n(0.0);
            for (const Quad& q : scene.quads) {
                glm::dvec3 n(0.0);
                const double t = intersect(q, origin, dir, n);
                if (t < best) { best = t; best_n = n; }
            }
            const size_t i = static_cast<size_t>(y) * width + x;
            if (std::isinf(best)) { g.depth[i] = sky; continue; }
            const glm::dvec3 p = origin + dir * best;
            const double d = depth_of(p);
            if (!(d >= 0.0 && d <= 1.0)) { g.depth[i] = sky; continue; }  // clipped by near/far
            g.depth[i] = static_cast<float>(d);
            g.normal[i] = glm::vec3(best_n);
            g.position[i] = p;
        }
    }
    return g;
}

glm::dmat4 perspective(double fovy, double aspect, double n, double f) {
    const double t = 1.0 / std::tan(fovy / 2.0);
    glm::dmat4 m(0.0);
    m[0][0] = t / aspect; m[1][1] = t;
    m[2][2] = -(f + n) / (f - n); m[2][3] = -1.0; m[3][2] = -2.0 * f * n / (f - n);
    return m;
}
glm::dmat4 perspective_zo(double fovy, double aspect, double n, double f) {
    glm::dmat4 m = perspective(fovy, aspect, n, f);
    m[2][2] = -f / (f - n); m[3][2] = -f * n / (f - n);
    return m;
}
glm::dmat4 reverse_z(double fovy, double aspect, double n, double f) {
    glm::dmat4 m = perspective(fovy, aspect, n, f);
    m[2][2] = n / (f - n); m[3][2] = f * n / (f - n);
    return m;
}
glm::dmat4 reverse_z_infinite(double fovy, double aspect, double n) {
    glm::dmat4 m = perspective(fovy, aspect, n, 1.0);
    m[2][2] = 0.0; m[3][2] = n;
    return m;
}
glm::dmat4 infinite(double fovy, double aspect, double n) {
    glm::dmat4 m = perspective(fovy, aspect, n, 1.0);
    m[2][2] = -1.0; m[3][2] = -2.0 * n;
    return m;
}
glm::dmat4 orthographic(double half_w, double half_h, double n, double f) {
    glm::dmat4 m(1.0);
    m[0][0] = 1.0 / half_w; m[1][1] = 1.0 / half_h;
    m[2][2] = -2.0 / (f - n); m[3][2] = -(f + n) / (f - n);
    return m;
}

void to_floats(const glm::dmat4& m, float out[16]) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) out[c * 4 + r] = static_cast<float>(m[c][r]);
}

}  // namespace analytic
