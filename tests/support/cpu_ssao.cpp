#include "cpu_ssao.h"

#include "kernel.h"
#include "projection.h"

#include <algorithm>
#include <cmath>

namespace cpu {

namespace {

double smoothstep01(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

}  // namespace

float ao(const Input& in, const ssao_settings& s, int x, int y) {
    const analytic::GBuffer& g = *in.gbuffer;
    ssao_impl::ProjectionInfo p;
    std::string why;
    if (ssao_impl::analyse_projection(in.projection, in.clip, p, why) != SSAO_OK) return -1.0f;
    const double sky = p.sky_depth;
    auto depth = [&](int px, int py) { return static_cast<double>(g.depth[static_cast<size_t>(py) * g.width + px]); };
    auto ndc = [&](int px, int py) {
        return glm::dvec2((px + 0.5) / g.width * 2.0 - 1.0, (py + 0.5) / g.height * 2.0 - 1.0);
    };
    auto position = [&](int px, int py, double d) {
        const glm::dvec2 n = ndc(px, py);
        return ssao_impl::view_position(p, n.x, n.y, d);
    };
    auto step = [&](int px, int py, double d) {
        // |dz/dd| * ulp(d), by the analytic derivative of the reconstruction.
        const glm::dvec2 n = ndc(px, py);
        const double ndc_z = p.ndc_per_depth == 2.0 ? d * 2.0 - 1.0 : d;
        const glm::dvec4 v = p.inverse * glm::dvec4(n, ndc_z, 1.0);
        const double dz = (p.inverse[2][2] * v.w - v.z * p.inverse[2][3]) / (v.w * v.w);
        double ulp = in.depth_step > 0 ? in.depth_step : std::max(std::abs(d) * 1.1920929e-7, 1.1754944e-38);
        if (in.depth_step == 0 && p.ndc_per_depth == 2.0) ulp = std::max(ulp, std::abs(d * 2.0 - 1.0) * 0.5 * 1.1920929e-7);
        return std::abs(dz) * p.ndc_per_depth * ulp;
    };

    const double d = depth(x, y);
    if (d == sky) return 1.0f;
    const glm::dvec3 P = position(x, y, d);
    const glm::dvec3 to_eye = p.orthographic ? glm::dvec3(0, 0, 1) : glm::normalize(-P);
    glm::dvec3 n = glm::dvec3(g.normal[static_cast<size_t>(y) * g.width + x]);
    const double m = std::max(std::abs(n.x), std::max(std::abs(n.y), std::abs(n.z)));
    const double sum = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);  // NaN-propagating, unlike max
    n = (m > 1e-30 && m < 3.0e38 && sum < 3.0e38) ? glm::normalize(n / m) : to_eye;
    const double away = glm::dot(n, to_eye);
    if (away < 0.0) n = glm::normalize(n - to_eye * (away * 1.01));

    // Basis (Duff et al.) and the rotation.
    const double sg = n.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (sg + n.z), b = n.x * n.y * a;
    const glm::dvec3 b1(1.0 + sg * n.x * n.x * a, sg * b, -sg * n.x), b2(b, sg + n.y * n.y * a, -n.y);
    glm::dvec2 r(1.0, 0.0);
    if (s.rotation == SSAO_ROTATION_NOISE_4X4) {
        const auto noise = ssao_impl::make_noise(s.seed);
        r = glm::dvec2(noise[static_cast<size_t>((y & 3) * 4 + (x & 3))]);
    } else if (s.rotation == SSAO_ROTATION_HASH) {
        const double angle = ssao_impl::pixel_hash(static_cast<uint32_t>(x), static_cast<uint32_t>(y), s.seed) * 6.28318530718;
        r = glm::dvec2(std::cos(angle), std::sin(angle));
    }
    const glm::dvec3 T = r.x * b1 + r.y * b2, B = glm::cross(n, T);

    const auto kernel = ssao_impl::make_kernel(s);
    const double radius = s.radius;
    const double step_p = step(x, y, d);
    double occlusion = 0.0, valid = 0.0;
    for (const glm::vec3& k : kernel) {
        const glm::dvec3 sp = P + (T * double(k.x) + B * double(k.y) + n * double(k.z)) * radius;
        const glm::dvec4 c = p.proj * glm::dvec4(sp, 1.0);
        if (!(c.w > 0.0)) continue;
        const double fx = (c.x / c.w * 0.5 + 0.5) * g.width, fy = (c.y / c.w * 0.5 + 0.5) * g.height;
        if (fx < 0.0 || fy < 0.0 || fx >= g.width || fy >= g.height) continue;
        const int sx = static_cast<int>(fx), sy = static_cast<int>(fy);
        valid += 1.0;
        const double sd = depth(sx, sy);
        if (sd == sky) continue;
        const glm::dvec3 Q = position(sx, sy, sd);
        const double plane = glm::dot(sp, n);
        glm::dvec3 sn = sp;
        if (p.orthographic) {
            if (std::abs(n.z) > 1e-3) sn = glm::dvec3(Q.x, Q.y, (plane - n.x * Q.x - n.y * Q.y) / n.z);
        } else {
            const double qn = glm::dot(Q, n);
            if (std::abs(qn) > 1e-3 * glm::length(Q)) sn = Q * (plane / qn);
        }
        if (in.legacy_snap_guard && glm::distance(sn, sp) > 0.5 * radius) sn = sp;
        const double bias = s.bias + s.depth_step_bias * (step_p + step(sx, sy, sd));
        const double range = smoothstep01(radius / std::abs(P.z - Q.z));
        occlusion += (Q.z >= sn.z + bias ? 1.0 : 0.0) * range;
    }
    const double o = valid > 0.0 ? occlusion / valid : 0.0;
    const double strength = s.strength == SSAO_STRENGTH_OFF ? 0.0 : s.strength;
    return static_cast<float>(std::pow(std::clamp(1.0 - strength * o, 0.0, 1.0), double(s.power)));
}

}  // namespace cpu
