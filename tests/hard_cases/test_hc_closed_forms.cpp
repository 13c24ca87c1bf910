// Against the closed forms of V_R (docs/reference.md, "Ground truth"): the wall and the wedge. Hemisphere
// SSAO converges to its own limit, not to V_R; the limit is computed here by
// an independent numerical integral of the estimator's definition over the
// kernel's continuous distribution (uniform directions on the hemisphere,
// length u * lerp(0.1, 1, t^2) with u, t uniform), with exact ray casts
// against the analytic scene (no pixels, no snapping). The GPU, averaged over
// several seeds (kernels) and many pixels (rotations), must land within its
// own noise of that limit. The gap from the limit to V_R (the bias) is
// reported, not asserted.
#include <doctest/doctest.h>

#include "hc_util.h"
#include "kernel.h"
#include "uniforms.h"  // SSAO_MARCH_STRETCH (shaders/ssao_constants.h)

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

using analytic::GBuffer;
using analytic::Scene;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Nearest hit of the ray o + t d (t > 0) with the scene's quads.
double first_hit(const Scene& scene, const glm::dvec3& o, const glm::dvec3& d) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& q : scene.quads) {
        const glm::dvec3 n = glm::cross(q.u, q.v);
        const double denom = glm::dot(n, d);
        if (std::abs(denom) < 1e-300) continue;
        const double t = glm::dot(n, q.origin - o) / denom;
        if (!(t > 0.0) || t >= best) continue;
        const glm::dvec3 p = o + d * t - q.origin;
        const double uu = glm::dot(q.u, q.u), uv = glm::dot(q.u, q.v), vv = glm::dot(q.v, q.v);
        const double pu = glm::dot(p, q.u), pv = glm::dot(p, q.v), det = uu * vv - uv * uv;
        const double a = (pu * vv - pv * uv) / det, b = (pv * uu - pu * uv) / det;
        if (a < 0.0 || a > 1.0 || b < 0.0 || b > 1.0) continue;
        best = t;
    }
    return best;
}

double smoothstep01(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

// The estimator's converged AO at view-space point P with normal n: the mean
// over the continuous kernel distribution of [the camera ray through the
// sample s hits a surface Q in front of s by more than the bias] *
// smoothstep(R / |P.z - Q.z|).
double converged_limit(const Scene& view_scene, const glm::dvec3& P, const glm::dvec3& n, double R, double bias,
                       int samples, uint64_t seed) {
    const double sg = n.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (sg + n.z), b = n.x * n.y * a;
    const glm::dvec3 b1(1.0 + sg * n.x * n.x * a, sg * b, -sg * n.x), b2(b, sg + n.y * n.y * a, -n.y);
    ssao_impl::Random rng(seed);
    double occlusion = 0;
    for (int i = 0; i < samples; ++i) {
        glm::dvec3 v;
        for (;;) {
            // Sequenced draws (z, y, x), as plugin/kernel.cpp: argument order is unspecified.
            const double z = rng.next_float(), y = rng.next_float() * 2.0 - 1.0;
            v = glm::dvec3(rng.next_float() * 2.0 - 1.0, y, z);
            const double len = glm::length(v);
            if (len > 1e-3 && len <= 1.0) { v /= len; break; }
        }
        const double t = rng.next_float(), u = rng.next_float();
        const double length = u * (0.1 + 0.9 * t * t);
        const glm::dvec3 s = P + (b1 * v.x + b2 * v.y + n * v.z) * (R * length);
        const double hit = first_hit(view_scene, glm::dvec3(0.0), s);  // s at parameter 1
        if (!(hit < 1.0 - 1e-12)) continue;
        const glm::dvec3 Q = s * hit;
        if (Q.z >= s.z + bias) occlusion += smoothstep01(R / std::abs(P.z - Q.z));
    }
    return 1.0 - occlusion / samples;
}

struct Bin {
    double lo, hi;           // distance from the crease line, world units
    std::vector<size_t> px;  // pixel indices in the bin
};

struct Measured {
    double gpu = 0, gpu_se = 0, limit = 0, closed = 0;
    size_t pixels = 0;
};

// Floor y = 0 and a second plane through the line z = -6, y = 0 at interior
// angle alpha from the floor (90 degrees = the wall) and `height` high.
Scene wedge_world(double alpha_deg, double height = 60.0) {
    const double a = alpha_deg * kPi / 180.0;
    Scene s;
    s.add_quad({-50, 0, 50}, {100, 0, 0}, {0, 0, -56});
    s.add_quad({-50, 0, -6}, {100, 0, 0}, glm::dvec3(0, std::sin(a), std::cos(a)) * height);
    return s;
}

// The reference value `measure` compares a bin with, at view-space point P
// with normal n (pixel index i, for seeding).
using Reference = std::function<double(const Scene& view_scene, const glm::dvec3& P, const glm::dvec3& n, size_t i)>;

// V_R itself by exact ray casts: cosine-weighted directions (stratified),
// occluded when the first hit is within R.
double exact_visibility(const Scene& view_scene, const glm::dvec3& P, const glm::dvec3& n, double R, int samples,
                        uint64_t seed) {
    const double sg = n.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (sg + n.z), b = n.x * n.y * a;
    const glm::dvec3 b1(1.0 + sg * n.x * n.x * a, sg * b, -sg * n.x), b2(b, sg + n.y * n.y * a, -n.y);
    ssao_impl::Random rng(seed);
    const glm::dvec3 origin = P + n * 1e-9;
    int open = 0;
    for (int i = 0; i < samples; ++i) {
        const double u = (i + rng.next_float()) / samples, phi = 2.0 * kPi * rng.next_float();
        const double r = std::sqrt(u);
        const glm::dvec3 d = b1 * (r * std::cos(phi)) + b2 * (r * std::sin(phi)) + n * std::sqrt(1.0 - u);
        if (!(first_hit(view_scene, origin, d) <= R)) ++open;
    }
    return static_cast<double>(open) / samples;
}

// The kernel estimator's reference: its own converged limit.
Reference kernel_limit(double R, double bias) {
    return [R, bias](const Scene& scene, const glm::dvec3& P, const glm::dvec3& n, size_t i) {
        return converged_limit(scene, P, n, R, bias, 4000, 1000 + i);
    };
}

std::vector<Measured> measure(testgl::Fixture& fx, const Scene& world, std::vector<Bin> bins,
                              const std::function<double(double)>& closed_form, const ssao_settings& base,
                              const Reference& reference, double camera_distance = 2.5) {
    const int W = 128, H = 96;
    // Camera 2.5 above the floor, 2.5 in front of the crease, looking 45
    // degrees down at it: floor rows ~0.05 units apart near the crease.
    glm::dmat4 rot(1.0), tr(1.0);
    const double pitch = kPi / 4;
    rot[1][1] = std::cos(pitch); rot[1][2] = std::sin(pitch); rot[2][1] = -std::sin(pitch); rot[2][2] = std::cos(pitch);
    tr[3] = glm::dvec4(0.0, -camera_distance, 6.0 - camera_distance, 1.0);
    const glm::dmat4 view = rot * tr;
    const Scene view_scene = hc::to_view(world, view);
    const auto proj = analytic::reverse_z(hc::kFov, double(W) / H, 0.1, 200.0);
    const GBuffer g = analytic::render(view_scene, proj, SSAO_CLIP_ZERO_TO_ONE, W, H);
    const glm::dmat4 inv_view = glm::inverse(view);
    // Floor pixels 16 px from the edges (samples stay on screen), by distance
    // to the crease line.
    for (int y = 16; y < H - 16; ++y)
        for (int x = 16; x < W - 16; ++x) {
            if (g.sky(x, y)) continue;
            const glm::dvec3 w = glm::dvec3(inv_view * glm::dvec4(g.position[hc::at(x, y, W)], 1.0));
            if (std::abs(w.y) > 1e-6) continue;
            const double d = w.z + 6.0;
            for (Bin& b : bins)
                if (d >= b.lo && d < b.hi) b.px.push_back(hc::at(x, y, W));
        }
    const int seeds = 8;
    std::vector<std::vector<double>> per_seed(bins.size());
    for (int seed = 1; seed <= seeds; ++seed) {
        ssao_settings s = base;
        s.seed = static_cast<uint32_t>(seed);
        fx.settings(s);
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "closed form");
        for (size_t b = 0; b < bins.size(); ++b) {
            double sum = 0;
            for (size_t i : bins[b].px) sum += r.ao[i];
            per_seed[b].push_back(sum / static_cast<double>(bins[b].px.size()));
        }
    }
    std::vector<Measured> out;
    for (size_t b = 0; b < bins.size(); ++b) {
        Measured m;
        m.pixels = bins[b].px.size();
        REQUIRE(m.pixels >= 20);
        for (double v : per_seed[b]) m.gpu += v / seeds;
        double var = 0;
        for (double v : per_seed[b]) var += (v - m.gpu) * (v - m.gpu) / (seeds - 1);
        m.gpu_se = std::sqrt(var / seeds);
        double lim = 0, closed = 0;
        const int take = static_cast<int>(std::min<size_t>(m.pixels, 24));
        for (int k = 0; k < take; ++k) {
            const size_t i = bins[b].px[k * m.pixels / take];
            const glm::dvec3 P = g.position[i];
            const glm::dvec3 n = glm::dvec3(g.normal[i]);
            lim += reference(view_scene, P, n, i) / take;
            const glm::dvec3 w = glm::dvec3(inv_view * glm::dvec4(P, 1.0));
            closed += closed_form(w.z + 6.0) / take;
        }
        m.limit = lim;
        m.closed = closed;
        out.push_back(m);
    }
    return out;
}

// The kernel estimator as these tests have measured it since the start: 64
// accelerating samples, hash rotation, no blur.
ssao_settings kernel_settings(double R) {
    ssao_settings s = hc::make(64, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(R), SSAO_METHOD_KERNEL);
    s.distribution = SSAO_DISTRIBUTION_ACCELERATING;
    return s;
}

// The visibility estimator, converged: 64 directions x 32 steps.
ssao_settings visibility_settings(double R) {
    ssao_settings s = hc::make(64, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(R), SSAO_METHOD_VISIBILITY);
    s.step_count = 32;
    return s;
}

double wall_closed_form(double d, double R) {
    const double a = std::min(d / R, 1.0);
    return 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / kPi;
}

// Each estimator against its own converged limit: the kernel's is computed
// above (converged_limit); the visibility estimator's is the depth-only
// limit, which here, where the depth buffer sees every occluder, is V_R
// itself (exact ray casts).
ssao_settings settings_for(ssao_method method, double R) {
    return method == SSAO_METHOD_VISIBILITY ? visibility_settings(R) : kernel_settings(R);
}
// How far the camera stands from the crease. The kernel leaves samples that
// fall off screen out of its count; the visibility march (like the
// depth-only limit) counts a direction that leaves the screen as open, so it
// equals V_R only where every march of length R stays on screen: from 2.5
// units a radius of 1.5 spans ~35 px of the 128 x 96 image and the marches
// of the bins near the screen's edge leave it (measured: GPU above V_R by up
// to 0.023); from 4 units they stay on.
double camera_for(ssao_method method) { return method == SSAO_METHOD_VISIBILITY ? 4.0 : 2.5; }
Reference limit_for(ssao_method method, double R) {
    if (method == SSAO_METHOD_KERNEL) return kernel_limit(R, 0.025 * R);  // the default bias (D32F reverse-Z: the step part is ~1e-7 z)
    return [R](const Scene& scene, const glm::dvec3& P, const glm::dvec3& n, size_t i) {
        return exact_visibility(scene, P, n, R, 4000, 7000 + i);
    };
}

}  // namespace

TEST_CASE("closed forms: the visibility estimator converges to V_R on the wall and the wedge (the kernel cannot)") {
    // Where the depth buffer sees every occluder (a floor and a wall or
    // wedge, seen from the open side), the depth-only limit is V_R itself,
    // and the visibility estimator must land on it: within 0.01 + noise.
    testgl::Fixture fx;
    const double R = 1.5;
    for (double alpha : {90.0, 60.0, 120.0}) {
        CAPTURE(alpha);
        std::vector<Bin> bins;
        for (double c : {0.05, 0.2, 0.4, 0.6, 0.8}) bins.push_back({c * R - 0.04 * R, c * R + 0.04 * R, {}});
        const Reference exact = [R](const Scene& scene, const glm::dvec3& P, const glm::dvec3& n, size_t i) {
            return exact_visibility(scene, P, n, R, 4000, 7000 + i);
        };
        const auto m = measure(fx, wedge_world(alpha), bins, [R](double d) { return wall_closed_form(d, R); },
                               visibility_settings(R), exact, 4.0);
        double worst = 0.0;
        for (size_t b = 0; b < m.size(); ++b) {
            CAPTURE(b);
            const double d = 0.5 * (bins[b].lo + bins[b].hi) / R;
            MESSAGE("visibility, interior angle " << alpha << " deg, d/R " << d << " (" << m[b].pixels << " px): GPU "
                                                  << m[b].gpu << " +- " << m[b].gpu_se << ", V_R " << m[b].limit
                                                  << (alpha == 90.0 ? ", closed form " + std::to_string(m[b].closed) : std::string())
                                                  << "; GPU - V_R " << m[b].gpu - m[b].limit);
            // V_R here is an exact ray-cast integral (24 px x 4000
            // stratified rays, s.e. ~0.002); for the wall it equals the
            // closed form.
            if (alpha == 90.0) CHECK(std::abs(m[b].limit - m[b].closed) < 0.005);
            CHECK(std::abs(m[b].gpu - m[b].limit) <= 4 * m[b].gpu_se + 0.01);
            worst = std::max(worst, std::abs(m[b].gpu - m[b].limit));
        }
        // The kernel estimator, in the same bins, misses V_R by far more
        // than 0.01 (its bias, measured in the cases below): this test's
        // tolerance separates the two.
        const auto k = measure(fx, wedge_world(alpha), bins, [R](double d) { return wall_closed_form(d, R); },
                               kernel_settings(R), exact, 4.0);
        double kernel_worst = 0.0;
        for (const Measured& km : k) kernel_worst = std::max(kernel_worst, std::abs(km.gpu - km.limit));
        MESSAGE("interior angle " << alpha << ": worst |GPU - V_R| visibility " << worst << ", kernel " << kernel_worst);
        CHECK(kernel_worst > 0.05);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("closed forms: the wall - the GPU lands on the estimator's converged limit - the bias to V_R is reported") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const double R = 1.5;
    std::vector<Bin> bins;
    for (double c : {0.05, 0.2, 0.4, 0.6, 0.8, 0.95}) bins.push_back({c * R - 0.04 * R, c * R + 0.04 * R, {}});
    auto wall = [R](double d) { return wall_closed_form(d, R); };
    const auto m = measure(fx, wedge_world(90.0), bins, wall, settings_for(method, R), limit_for(method, R), camera_for(method));
    for (size_t b = 0; b < m.size(); ++b) {
        CAPTURE(b);
        const double d = 0.5 * (bins[b].lo + bins[b].hi) / R;
        MESSAGE("wall, d/R " << d << " (" << m[b].pixels << " px): GPU " << m[b].gpu << " +- " << m[b].gpu_se
                             << ", converged limit " << m[b].limit << ", V_R " << m[b].closed
                             << "; GPU - limit " << m[b].gpu - m[b].limit << ", limit - V_R (bias) " << m[b].limit - m[b].closed);
        // Noise: 4 standard errors of the seed-to-seed spread, the limit's
        // own Monte Carlo error (24 px x 4000 samples), and 0.01 for what the
        // continuum limit leaves out (texel snapping, half-float storage).
        CHECK(std::abs(m[b].gpu - m[b].limit) <= 4 * m[b].gpu_se + 0.01);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("closed forms: the wedge - the GPU lands on the estimator's converged limit - the bias to (1 - cos a) / 2 is reported") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const double R = 1.5;
    for (double alpha : {60.0, 120.0}) {
        CAPTURE(alpha);
        std::vector<Bin> bins;
        for (double c : {0.05, 0.15, 0.3}) bins.push_back({c * R - 0.04 * R, c * R + 0.04 * R, {}});
        const double v_inf = (1.0 - std::cos(alpha * kPi / 180.0)) / 2.0;
        const auto m = measure(fx, wedge_world(alpha), bins, [v_inf](double) { return v_inf; }, settings_for(method, R),
                               limit_for(method, R), camera_for(method));
        for (size_t b = 0; b < m.size(); ++b) {
            CAPTURE(b);
            const double d = 0.5 * (bins[b].lo + bins[b].hi) / R;
            MESSAGE("wedge " << alpha << " deg, d/R " << d << " (" << m[b].pixels << " px): GPU " << m[b].gpu << " +- "
                             << m[b].gpu_se << ", converged limit " << m[b].limit << ", V(R inf) " << v_inf
                             << "; GPU - limit " << m[b].gpu - m[b].limit << ", limit - V (bias) " << m[b].limit - v_inf);
            CHECK(std::abs(m[b].gpu - m[b].limit) <= 4 * m[b].gpu_se + 0.01);
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("closed forms: a coarse march blocks where its segment crosses the wall, however far behind the step lands") {
    // Four steps and a thickness of R/10 against the wall seen 45 degrees
    // down: most steps that pass the wall land further behind it (in view
    // depth) than the thickness, so a point test alone would call them open.
    // The crossing test blocks them, so every direction whose segment meets
    // the wall before the last step is blocked: with no rotation the jitter
    // is 0.5 and the last step stands at (4 - 0.5) / (4 - 0.5 stretch) R for
    // every pixel (SSAO_MARCH_STRETCH), and the GPU must land on V within
    // that distance (exact ray casts), as the converged march lands on V_R
    // above.
    testgl::Fixture fx;
    const double R = 1.5, last = 3.5 / (4.0 - 0.5 * SSAO_MARCH_STRETCH) * R;
    ssao_settings s = hc::make(64, SSAO_BLUR_NONE, SSAO_ROTATION_NONE, static_cast<float>(R), SSAO_METHOD_VISIBILITY);
    s.step_count = 4;
    s.thickness = static_cast<float>(0.1 * R);
    std::vector<Bin> bins;
    for (double c : {0.05, 0.2, 0.4, 0.6}) bins.push_back({c * R - 0.04 * R, c * R + 0.04 * R, {}});
    const Reference within_last = [last](const Scene& scene, const glm::dvec3& P, const glm::dvec3& n, size_t i) {
        return exact_visibility(scene, P, n, last, 4000, 7000 + i);
    };
    const auto m = measure(fx, wedge_world(90.0), bins, [last](double d) { return wall_closed_form(d, last); }, s, within_last,
                           camera_for(SSAO_METHOD_VISIBILITY));
    for (size_t b = 0; b < m.size(); ++b) {
        CAPTURE(b);
        const double d = 0.5 * (bins[b].lo + bins[b].hi) / R;
        MESSAGE("wall, 4 steps, thickness R/10, d/R " << d << " (" << m[b].pixels << " px): GPU " << m[b].gpu << " +- "
                                                      << m[b].gpu_se << ", V within the last step " << m[b].limit
                                                      << "; GPU - V " << m[b].gpu - m[b].limit);
        CHECK(std::abs(m[b].gpu - m[b].limit) <= 4 * m[b].gpu_se + 0.01);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("closed forms: a low wall that four steps pass over blocks once a step may span only a few texels") {
    // A wall R/10 high: a floor point's direction toward it is blocked where
    // it meets the wall below its top, and the march only sees that from a
    // step that lands inside the wall's shadow from the camera, at most R/10
    // behind it (the camera looks 45 degrees down). Four steps R/4 apart
    // mostly land beyond it, where the camera sees the floor under the step,
    // and call the direction open (max_step_texels off, the default). With
    // max_step_texels 1 a step spans at most one pixel: the ~22 px that R
    // spans here give ~22 steps R/22 apart, which land in the shadow. Where
    // the depth buffer sees every occluder the converged march is V_R (exact
    // ray casts, as above).
    testgl::Fixture fx;
    const double R = 1.5, height = 0.1 * R;
    std::vector<Bin> bins;
    for (double c : {0.1, 0.25, 0.4}) bins.push_back({c * R - 0.04 * R, c * R + 0.04 * R, {}});
    const Reference exact = [R](const Scene& scene, const glm::dvec3& P, const glm::dvec3& n, size_t i) {
        return exact_visibility(scene, P, n, R, 4000, 7000 + i);
    };
    auto run = [&](float max_step_texels) {
        ssao_settings s = hc::make(64, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(R), SSAO_METHOD_VISIBILITY);
        s.step_count = 4;
        s.thickness = static_cast<float>(0.5 * R);
        s.max_step_texels = max_step_texels;
        return measure(fx, wedge_world(90.0, height), bins, [](double) { return 0.0; }, s, exact,
                       camera_for(SSAO_METHOD_VISIBILITY));
    };
    const auto fixed = run(0.0f), adaptive = run(1.0f), four = run(4.0f);
    for (size_t b = 0; b < bins.size(); ++b) {
        CAPTURE(b);
        const double d = 0.5 * (bins[b].lo + bins[b].hi) / R;
        MESSAGE("low wall R/10, d/R " << d << " (" << fixed[b].pixels << " px): V_R " << fixed[b].limit
                                      << "; GPU - V_R: 4 steps fixed " << fixed[b].gpu - fixed[b].limit
                                      << ", max_step_texels 1 " << adaptive[b].gpu - adaptive[b].limit
                                      << ", max_step_texels 4 " << four[b].gpu - four[b].limit);
        CHECK(std::abs(adaptive[b].gpu - adaptive[b].limit) <= 4 * adaptive[b].gpu_se + 0.01);
        // Four fixed steps under-occlude (measured: by 0.116, 0.027 and
        // 0.012 from the nearest bin out); 4 texels (~6 steps) lie between.
        CHECK(fixed[b].gpu - fixed[b].limit > 3 * std::abs(adaptive[b].gpu - adaptive[b].limit) + 0.005);
        CHECK(four[b].gpu - four[b].limit < fixed[b].gpu - fixed[b].limit);
    }
    CHECK(fx.gl_errors().empty());
}
