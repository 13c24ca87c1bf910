#include "cpu_ssao.h"

#include "kernel.h"
#include "projection.h"
#include "settings.h"
#include "uniforms.h"  // SSAO_MARCH_STRETCH (shaders/ssao_constants.h)

#include <algorithm>
#include <cmath>
#include <optional>

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
    // The normal as the pass sees it: broken ones fall back to the eye
    // direction, back-facing ones lose the part pointing away.
    // The stored normal, unit length; false when zero, NaN or infinite.
    auto decode_normal = [&](int px, int py, glm::dvec3& v) {
        v = glm::dvec3(g.normal[static_cast<size_t>(py) * g.width + px]);
        const double m = std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
        const double sum = std::abs(v.x) + std::abs(v.y) + std::abs(v.z);  // NaN-propagating, unlike max
        if (!(m > 1e-30 && m < 3.0e38 && sum < 3.0e38)) return false;
        v = glm::normalize(v / m);
        return true;
    };
    auto normal_at = [&](int px, int py, const glm::dvec3& eye_dir) {
        glm::dvec3 v;
        if (!decode_normal(px, py, v)) v = eye_dir;
        const double away = glm::dot(v, eye_dir);
        if (away < 0.0) v = glm::normalize(v - eye_dir * (away * 1.01));
        return v;
    };
    const glm::dvec3 n = normal_at(x, y, to_eye);

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
    } else if (s.rotation == SSAO_ROTATION_GRADIENT_NOISE) {
        const double angle = ssao_impl::gradient_noise(static_cast<float>(x), static_cast<float>(y)) * 6.28318530718;
        r = glm::dvec2(std::cos(angle), std::sin(angle));
    }
    const glm::dvec3 T = r.x * b1 + r.y * b2, B = glm::cross(n, T);

    const double radius = s.radius;
    const double step_p = step(x, y, d);
    const double strength = ssao_impl::effective_strength(s);
    // Viewport pixel coordinates of clip coordinates c (in front of the eye: c.w > 0).
    auto pixel_of = [&](const glm::dvec4& c) {
        return glm::dvec2((c.x / c.w * 0.5 + 0.5) * g.width, (c.y / c.w * 0.5 + 0.5) * g.height);
    };
    // Where a view-space point lands: false behind the eye or off the image.
    auto project = [&](const glm::dvec3& sp, int& sx, int& sy) {
        const glm::dvec4 c = p.proj * glm::dvec4(sp, 1.0);
        if (!(c.w > 0.0)) return false;
        const glm::dvec2 f = pixel_of(c);
        if (f.x < 0.0 || f.y < 0.0 || f.x >= g.width || f.y >= g.height) return false;
        sx = static_cast<int>(f.x);
        sy = static_cast<int>(f.y);
        return true;
    };
    auto snap = [&](const glm::dvec3& sp, const glm::dvec3& Q) {
        const double plane = glm::dot(sp, n);
        if (p.orthographic)
            return std::abs(n.z) > 1e-3 ? glm::dvec3(Q.x, Q.y, (plane - n.x * Q.x - n.y * Q.y) / n.z) : sp;
        const double qn = glm::dot(Q, n);
        return std::abs(qn) > 1e-3 * glm::length(Q) ? Q * (plane / qn) : sp;
    };

    if (s.method == SSAO_METHOD_VISIBILITY) {
        // shaders/visibility.frag: a direction is blocked by its first step
        // that lies behind the depth buffer by [bias, thickness], or further
        // behind a surface that the segment from the previous point crossed.
        const auto dirs = ssao_impl::make_directions(s);
        // The bias as the pass takes it: depth-format steps at P and where the
        // format's step is largest among the surfaces that can block a step
        // (view z P.z - radius .. P.z + radius + thickness): the far end in
        // perspective, either end in orthographic projections.
        auto step_at_z = [&](double z) {
            const glm::dvec4 c = p.proj * glm::dvec4(P.x, P.y, z, 1.0);
            return step(x, y, p.ndc_per_depth == 2.0 ? c.z / c.w * 0.5 + 0.5 : c.z / c.w);
        };
        const double step_bound = std::max(step_at_z(P.z - radius),
                                           p.orthographic ? step_at_z(P.z + radius + s.thickness) : 0.0);
        const double bias = s.bias + s.depth_step_bias * (step_p + step_bound);
        const double jitter = ssao_impl::step_jitter(s.rotation, static_cast<uint32_t>(x), static_cast<uint32_t>(y), s.seed);
        // How far the plane through Q with normal nq lies in front of point sp
        // along sp's eye ray (orthographic: the view axis), in view z; nullopt
        // where that ray runs within 1e-3 of the plane.
        auto plane_in_front = [&](const glm::dvec3& sp, const glm::dvec3& Q, const glm::dvec3& nq) -> std::optional<double> {
            const double plane = glm::dot(Q, nq);
            if (p.orthographic) {
                if (std::abs(nq.z) > 1e-3) return (plane - nq.x * sp.x - nq.y * sp.y) / nq.z - sp.z;
            } else if (std::abs(glm::dot(sp, nq)) > 1e-3 * glm::length(sp)) {
                return sp.z * (plane / glm::dot(sp, nq)) - sp.z;
            }
            return std::nullopt;
        };
        // Steps along a direction: step_count, or (max_step_texels > 0) as many as keep each
        // within max_step_texels of the grid on screen, up to SSAO_MAX_STEPS;
        // the span is at most the viewport's diagonal (also where the end
        // lies behind the eye).
        const double grid_scale = ssao_impl::resolution_scale(s);
        const double diagonal = std::hypot(double(g.width), double(g.height));
        auto steps_along = [&](const glm::dvec3& dir) {
            if (!(s.max_step_texels > 0.0f)) return s.step_count;  // off
            const glm::dvec4 c0 = p.proj * glm::dvec4(P, 1.0), c1 = p.proj * glm::dvec4(P + dir * radius, 1.0);
            const double span = c1.w > 0.0 ? std::min(glm::length(pixel_of(c1) - pixel_of(c0)), diagonal) : diagonal;
            const double wanted = std::ceil(span / grid_scale / s.max_step_texels);
            return static_cast<uint32_t>(std::clamp(wanted, double(s.step_count), double(SSAO_MAX_STEPS)));
        };
        double open = 0.0;
        for (const glm::vec3& k : dirs) {
            const glm::dvec3 dir = T * double(k.x) + B * double(k.y) + n * double(k.z);
            const uint32_t steps = steps_along(dir);
            bool blocked = false;
            glm::dvec3 prev = P;
            for (uint32_t j = 0; j < steps && !blocked; ++j) {
                const glm::dvec3 sp = P + dir * (radius * (j + jitter) / (steps - SSAO_MARCH_STRETCH * (1.0 - jitter)));
                const glm::dvec3 before = prev;
                prev = sp;
                int sx = 0, sy = 0;
                if (!project(sp, sx, sy)) continue;
                const double sd = depth(sx, sy);
                if (sd == sky) continue;
                const glm::dvec3 Q = position(sx, sy, sd);
                // The surface under the step: the plane through Q with the
                // texel's normal, met by the eye ray through the step; the
                // snap where that normal is broken or faces away.
                glm::dvec3 nq;
                const glm::dvec3 to_eye_q = p.orthographic ? glm::dvec3(0, 0, 1) : glm::normalize(-Q);
                const bool trusted = decode_normal(sx, sy, nq) && glm::dot(nq, to_eye_q) > 0.0;
                const std::optional<double> through_plane = trusted ? plane_in_front(sp, Q, nq) : std::nullopt;
                const double in_front = through_plane ? *through_plane : Q.z - snap(sp, Q).z;
                // The crossing: the previous point lay in front of the same plane.
                const std::optional<double> before_in_front = through_plane ? plane_in_front(before, Q, nq) : std::nullopt;
                const bool crossed = before_in_front && *before_in_front < bias;
                blocked = in_front >= bias && (in_front <= s.thickness || crossed);
            }
            if (!blocked) open += 1.0;
        }
        const double occlusion = 1.0 - open / static_cast<double>(dirs.size());
        return static_cast<float>(std::pow(std::clamp(1.0 - strength * occlusion, 0.0, 1.0), double(s.power)));
    }

    const auto kernel = ssao_impl::make_kernel(s);
    double occlusion = 0.0, valid = 0.0;
    for (const glm::vec3& k : kernel) {
        const glm::dvec3 sp = P + (T * double(k.x) + B * double(k.y) + n * double(k.z)) * radius;
        int sx = 0, sy = 0;
        if (!project(sp, sx, sy)) continue;
        valid += 1.0;
        const double sd = depth(sx, sy);
        if (sd == sky) continue;
        const glm::dvec3 Q = position(sx, sy, sd);
        glm::dvec3 sn = snap(sp, Q);
        if (in.legacy_snap_guard && glm::distance(sn, sp) > 0.5 * radius) sn = sp;
        const double bias = s.bias + s.depth_step_bias * (step_p + step(sx, sy, sd));
        const double range = smoothstep01(radius / std::abs(P.z - Q.z));
        occlusion += (Q.z >= sn.z + bias ? 1.0 : 0.0) * range;
    }
    const double o = valid > 0.0 ? occlusion / valid : 0.0;
    return static_cast<float>(std::pow(std::clamp(1.0 - strength * o, 0.0, 1.0), double(s.power)));
}

}  // namespace cpu
