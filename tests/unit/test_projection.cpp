// test_projection.cpp - projection analysis and position reconstruction
// (plugin/projection.h) over many kinds of projection matrix.
#include "projection.h"

#include <doctest/doctest.h>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

using ssao_impl::analyse_projection;
using ssao_impl::depth_of;
using ssao_impl::ProjectionInfo;
using ssao_impl::view_position;

namespace {

constexpr double kInfD = std::numeric_limits<double>::infinity();

struct Case {
    std::string name;
    glm::mat4 m;
    ssao_clip_range clip;
    bool ortho;
    bool reverse;
    bool infinite;
    double near_d;  // expected near distance
    double far_d;   // expected far distance (inf when infinite)
};

// Reverse-Z for [0,1] depth: near -> 1, far -> 0.
glm::mat4 reverse_zo(float fovy, float aspect, float n, float f) {
    glm::mat4 m = glm::perspectiveRH_ZO(fovy, aspect, n, f);
    m[2][2] = n / (f - n);
    m[3][2] = f * n / (f - n);
    return m;
}

// Reverse-Z with an infinite far plane: [[f/a,0,0,0],[0,f,0,0],[0,0,0,-1],[0,0,n,0]] (columns).
glm::mat4 reverse_infinite(float fovy, float aspect, float n) {
    const float f = 1.0f / std::tan(fovy * 0.5f);
    glm::mat4 m(0.0f);
    m[0][0] = f / aspect;
    m[1][1] = f;
    m[2][3] = -1.0f;
    m[3][2] = n;
    return m;
}

// Half-pixel TAA jitter of a perspective (moves the image by half a pixel).
glm::mat4 jittered(glm::mat4 m, int width, int height) {
    m[2][0] += 0.5f * 2.0f / static_cast<float>(width);
    m[2][1] -= 0.5f * 2.0f / static_cast<float>(height);
    return m;
}

std::vector<Case> all_cases() {
    std::vector<Case> cases;
    const float fovs[] = {glm::radians(30.0f), glm::radians(60.0f), glm::radians(100.0f)};
    const float aspects[] = {1.0f, 16.0f / 9.0f, 0.5f};
    const double nears[] = {1e-4, 1e-2, 0.1, 1.0};
    const double ratios[] = {10.0, 1e3, 1e6};  // far / near
    int k = 0;
    for (double n : nears)
        for (double ratio : ratios) {
            const float fovy = fovs[k % 3];
            const float aspect = aspects[(k / 3) % 3];
            ++k;
            const float nf = static_cast<float>(n);
            const float ff = static_cast<float>(n * ratio);
            const double fd = static_cast<double>(ff);
            const std::string tag = " n=" + std::to_string(n) + " f/n=" + std::to_string(ratio);
            cases.push_back({"perspective GL" + tag, glm::perspective(fovy, aspect, nf, ff),
                             SSAO_CLIP_NEGATIVE_ONE_TO_ONE, false, false, false, n, fd});
            cases.push_back({"perspective ZO" + tag, glm::perspectiveRH_ZO(fovy, aspect, nf, ff), SSAO_CLIP_ZERO_TO_ONE,
                             false, false, false, n, fd});
            cases.push_back({"reverse-Z ZO" + tag, reverse_zo(fovy, aspect, nf, ff), SSAO_CLIP_ZERO_TO_ONE, false, true,
                             false, n, fd});
            // glm::perspective with near and far swapped: reverse-Z in GL's [-1,1].
            cases.push_back({"reverse-Z GL" + tag, glm::perspective(fovy, aspect, ff, nf),
                             SSAO_CLIP_NEGATIVE_ONE_TO_ONE, false, true, false, n, fd});
            cases.push_back({"jittered GL" + tag, jittered(glm::perspective(fovy, aspect, nf, ff), 1920, 1080),
                             SSAO_CLIP_NEGATIVE_ONE_TO_ONE, false, false, false, n, fd});
            cases.push_back({"jittered reverse-Z" + tag, jittered(reverse_zo(fovy, aspect, nf, ff), 37, 23),
                             SSAO_CLIP_ZERO_TO_ONE, false, true, false, n, fd});
            cases.push_back({"off-centre frustum" + tag,
                             glm::frustum(-0.3f * nf, 0.9f * nf, -0.2f * nf, 0.5f * nf, nf, ff),
                             SSAO_CLIP_NEGATIVE_ONE_TO_ONE, false, false, false, n, fd});
        }
    for (double n : nears) {
        const float nf = static_cast<float>(n);
        const std::string tag = " n=" + std::to_string(n);
        cases.push_back({"infinite GL" + tag, glm::infinitePerspective(glm::radians(70.0f), 1.5f, nf),
                         SSAO_CLIP_NEGATIVE_ONE_TO_ONE, false, false, true, n, kInfD});
        cases.push_back({"infinite reverse-Z ZO" + tag, reverse_infinite(glm::radians(70.0f), 1.5f, nf),
                         SSAO_CLIP_ZERO_TO_ONE, false, true, true, n, kInfD});
        cases.push_back({"jittered infinite reverse-Z" + tag,
                         jittered(reverse_infinite(glm::radians(50.0f), 0.75f, nf), 640, 480), SSAO_CLIP_ZERO_TO_ONE,
                         false, true, true, n, kInfD});
    }
    // A projection times a positive constant is the same projection.
    cases.push_back({"perspective GL scaled x2", 2.0f * glm::perspective(glm::radians(45.0f), 1.3f, 0.2f, 300.0f),
                     SSAO_CLIP_NEGATIVE_ONE_TO_ONE, false, false, false, 0.2, 300.0});
    cases.push_back({"reverse-Z ZO scaled x0.25", 0.25f * reverse_zo(glm::radians(45.0f), 1.3f, 0.2f, 300.0f),
                     SSAO_CLIP_ZERO_TO_ONE, false, true, false, 0.2, 300.0});
    cases.push_back({"ortho scaled x3", 3.0f * glm::ortho(-4.0f, 4.0f, -3.0f, 3.0f, 2.0f, 40.0f),
                     SSAO_CLIP_NEGATIVE_ONE_TO_ONE, true, false, false, 2.0, 40.0});
    struct O {
        float l, r, b, t, n, f;
    };
    const O orthos[] = {{-1, 1, -1, 1, 0.1f, 100}, {-10, 30, -5, 15, 1, 1000}, {0, 1920, 0, 1080, 0.5f, 2},
                        {-2, 5, -3, 1, 1e-4f, 1e2f}, {-100, 100, -50, 50, 1, 1e6f}};
    for (const O& o : orthos) {
        const std::string tag = " [" + std::to_string(o.l) + "," + std::to_string(o.r) + "] n=" + std::to_string(o.n) +
                                " f=" + std::to_string(o.f);
        cases.push_back({"ortho GL" + tag, glm::ortho(o.l, o.r, o.b, o.t, o.n, o.f), SSAO_CLIP_NEGATIVE_ONE_TO_ONE,
                         true, false, false, o.n, o.f});
        cases.push_back({"ortho ZO" + tag, glm::orthoRH_ZO(o.l, o.r, o.b, o.t, o.n, o.f), SSAO_CLIP_ZERO_TO_ONE, true,
                         false, false, o.n, o.f});
        // Near and far swapped: reverse-Z orthographic.
        cases.push_back({"ortho reverse-Z ZO" + tag, glm::orthoRH_ZO(o.l, o.r, o.b, o.t, o.f, o.n),
                         SSAO_CLIP_ZERO_TO_ONE, true, true, false, o.n, o.f});
        glm::mat4 jit = glm::ortho(o.l, o.r, o.b, o.t, o.n, o.f);
        jit[3][0] += 1.0f / 1920.0f;
        jit[3][1] += 1.0f / 1080.0f;
        cases.push_back({"ortho jittered" + tag, jit, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, true, false, false, o.n, o.f});
    }
    return cases;
}

ssao_status analyse(const glm::mat4& m, ssao_clip_range clip, ProjectionInfo& info, std::string& why) {
    return analyse_projection(glm::value_ptr(m), clip, info, why);
}

// The view-space point that projects to (ndc_x, ndc_y) at distance t (z = -t),
// solved from the matrix itself (x and y enter clip x and y only through
// m[0][0] and m[1][1]; the rest are offsets).
glm::dvec3 point_at(const glm::dmat4& m, double ndc_x, double ndc_y, double t) {
    const double z = -t;
    const double w = m[2][3] * z + m[3][3];
    const double x = (ndc_x * w - m[2][0] * z - m[3][0]) / m[0][0];
    const double y = (ndc_y * w - m[2][1] * z - m[3][1]) / m[1][1];
    return {x, y, z};
}

// How precisely a float matrix pins down its planes: the plane that comes from
// a difference of two terms near 1 (the far plane of a standard perspective,
// the near plane of a GL orthographic projection) carries a float rounding of
// ~6e-8 divided by ~near/far, so allow that (relative) on top of 1e-4.
double plane_tolerance(const Case& c) { return 1e-4 + 3e-7 * (c.far_d / c.near_d); }

}  // namespace

TEST_CASE("projection: analysis reports kind and reverse-Z and infinite far and near and far") {
    for (const Case& c : all_cases()) {
        CAPTURE(c.name);
        ProjectionInfo info;
        std::string why;
        const ssao_status st = analyse(c.m, c.clip, info, why);
        CAPTURE(why);
        REQUIRE(st == SSAO_OK);
        CHECK(info.orthographic == c.ortho);
        CHECK(info.reverse_z == c.reverse);
        CHECK(info.infinite_far == c.infinite);
        CHECK(info.near_distance == doctest::Approx(c.near_d).epsilon(c.ortho ? plane_tolerance(c) : 1e-4));
        if (c.infinite) {
            CHECK(std::isinf(info.far_distance));
            CHECK(info.far_distance > 0.0);
        } else {
            CHECK(std::isfinite(info.far_distance));
            CHECK(info.far_distance == doctest::Approx(c.far_d).epsilon(plane_tolerance(c)));
        }
        CHECK(info.sky_depth == (c.reverse ? 0.0f : 1.0f));
        CHECK(info.ndc_per_depth == (c.clip == SSAO_CLIP_ZERO_TO_ONE ? 1.0 : 2.0));
    }
}

TEST_CASE("projection: the near plane has the near depth and the far plane the sky depth") {
    for (const Case& c : all_cases()) {
        CAPTURE(c.name);
        ProjectionInfo info;
        std::string why;
        REQUIRE(analyse(c.m, c.clip, info, why) == SSAO_OK);
        const glm::dmat4 m(c.m);
        const double near_depth = c.reverse ? 1.0 : 0.0;
        CHECK(depth_of(info, point_at(m, 0.3, -0.2, c.near_d)) == doctest::Approx(near_depth).epsilon(1e-5).scale(1.0));
        const double far_t = c.infinite ? c.near_d * 1e9 : c.far_d;
        CHECK(depth_of(info, point_at(m, -0.5, 0.7, far_t)) ==
              doctest::Approx(info.sky_depth).epsilon(1e-5).scale(1.0));
        // Depth is monotonic with distance, in the documented direction.
        const double d1 = depth_of(info, point_at(m, 0.0, 0.0, c.near_d * 1.5));
        const double d2 = depth_of(info, point_at(m, 0.0, 0.0, c.near_d * 2.0));
        if (c.reverse)
            CHECK(d1 > d2);
        else
            CHECK(d1 < d2);
    }
}

TEST_CASE("projection: depth_of then view_position returns the view point") {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> ndc(-0.999, 0.999), unit(0.0, 1.0);
    for (const Case& c : all_cases()) {
        CAPTURE(c.name);
        ProjectionInfo info;
        std::string why;
        REQUIRE(analyse(c.m, c.clip, info, why) == SSAO_OK);
        const glm::dmat4 m(c.m);
        // The float matrix's own far plane may sit a little before c.far_d
        // (see plane_tolerance); stay inside it.
        const double t_max = c.infinite ? c.near_d * 1e6 : std::min(c.far_d, info.far_distance);
        const double t_min = std::max(c.near_d, info.near_distance);
        double worst = 0.0;
        for (int i = 0; i < 1000; ++i) {
            const double nx = ndc(rng), ny = ndc(rng);
            // Perspective: distances log-uniform over [near, far]; ortho: uniform.
            const double u = unit(rng);
            const double t = c.ortho ? t_min + (t_max - t_min) * u : t_min * std::pow(t_max / t_min, u);
            const glm::dvec3 p = point_at(m, nx, ny, t);
            const double d = depth_of(info, p);
            REQUIRE(std::isfinite(d));
            CHECK(d >= -1e-12);
            CHECK(d <= 1.0 + 1e-12);
            const glm::dvec3 q = view_position(info, nx, ny, d);
            const double err = glm::length(q - p) / std::max(glm::length(p), 1e-30);
            worst = std::max(worst, err);
        }
        CAPTURE(worst);
        CHECK(worst < 1e-6);
    }
}

TEST_CASE("projection: view_position at the viewport corners spans the frustum") {
    // A concrete check independent of depth_of: GL perspective, depth 0 at the
    // near plane's corners.
    const float n = 0.5f, f = 50.0f, fovy = glm::radians(90.0f);
    const glm::mat4 m = glm::perspective(fovy, 2.0f, n, f);
    ProjectionInfo info;
    std::string why;
    REQUIRE(analyse(m, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, info, why) == SSAO_OK);
    const glm::dvec3 corner = view_position(info, 1.0, 1.0, 0.0);
    CHECK(corner.z == doctest::Approx(-0.5));
    CHECK(corner.y == doctest::Approx(0.5));  // tan(45 deg) * near
    CHECK(corner.x == doctest::Approx(1.0));  // * aspect
    const glm::dvec3 far_centre = view_position(info, 0.0, 0.0, 1.0);
    CHECK(far_centre.z == doctest::Approx(-50.0).epsilon(1e-4));
    CHECK(far_centre.x == doctest::Approx(0.0).scale(1.0));
}

TEST_CASE("projection: invalid matrices are rejected") {
    struct Bad {
        const char* what;
        glm::mat4 m;
        ssao_status expected;
    };
    const glm::mat4 persp = glm::perspective(glm::radians(60.0f), 1.5f, 0.1f, 100.0f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    std::vector<Bad> bad;
    bad.push_back({"all zero", glm::mat4(0.0f), SSAO_ERROR_INVALID_PROJECTION});
    bad.push_back({"left-handed perspective (w = +z)", glm::perspectiveLH(glm::radians(60.0f), 1.5f, 0.1f, 100.0f),
                   SSAO_ERROR_INVALID_PROJECTION});
    bad.push_back({"left-handed perspective ZO", glm::perspectiveLH_ZO(glm::radians(60.0f), 1.5f, 0.1f, 100.0f),
                   SSAO_ERROR_INVALID_PROJECTION});
    for (int i = 0; i < 16; i += 5) {
        glm::mat4 m = persp;
        glm::value_ptr(m)[i] = nan;
        bad.push_back({"NaN element", m, SSAO_ERROR_INVALID_VALUE});
        m = persp;
        glm::value_ptr(m)[i] = (i & 1) ? -inf : inf;
        bad.push_back({"infinite element", m, SSAO_ERROR_INVALID_VALUE});
    }
    {
        glm::mat4 m = persp;
        m[3][2] = 0.0f;  // every point gets the same depth: singular
        bad.push_back({"singular perspective (no depth offset)", m, SSAO_ERROR_INVALID_PROJECTION});
        m = persp;
        m[0][0] = 0.0f;
        bad.push_back({"singular perspective (zero x scale)", m, SSAO_ERROR_INVALID_PROJECTION});
        m = persp;
        m[1][1] = 0.0f;
        bad.push_back({"singular perspective (zero y scale)", m, SSAO_ERROR_INVALID_PROJECTION});
        m = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f);
        m[2][2] = 0.0f;
        bad.push_back({"singular ortho (no depth scale)", m, SSAO_ERROR_INVALID_PROJECTION});
        m = glm::mat4(1.0f);
        m[3][3] = 0.0f;
        bad.push_back({"w always zero", m, SSAO_ERROR_INVALID_PROJECTION});
        m = persp;
        m[3][3] = 1.0f;  // w = -z + 1: neither perspective nor orthographic
        bad.push_back({"mixed w", m, SSAO_ERROR_INVALID_PROJECTION});
        m = persp;
        m[0][3] = 0.5f;  // w depends on x
        bad.push_back({"w depends on x", m, SSAO_ERROR_INVALID_PROJECTION});
        // Rank 3: the depth row is a multiple of the w row.
        m = persp;
        m[2][2] = 1.0f;
        m[3][2] = 0.0f;
        bad.push_back({"depth row = -w row", m, SSAO_ERROR_INVALID_PROJECTION});
    }
    for (const Bad& b : bad) {
        const std::string what_ = b.what;
        CAPTURE(what_);
        for (ssao_clip_range clip : {SSAO_CLIP_NEGATIVE_ONE_TO_ONE, SSAO_CLIP_ZERO_TO_ONE}) {
            ProjectionInfo info;
            info.near_distance = 12345.0;
            std::string why;
            CHECK(analyse(b.m, clip, info, why) == b.expected);
            CHECK_FALSE(why.empty());
            CHECK(info.near_distance == 12345.0);  // out untouched
        }
    }
}

TEST_CASE("projection: matrices whose float inverse is useless are rejected") {
    // Finite and invertible in double, but in the shaders' 32-bit floats the
    // matrix or its inverse overflows or flushes to zero: execute returned OK
    // with every pixel 1.0 before these were refused.
    const glm::mat4 persp = glm::perspective(glm::radians(60.0f), 1.5f, 0.1f, 100.0f);
    std::vector<std::pair<const char*, glm::mat4>> bad;
    glm::mat4 m = persp;
    m[0][0] = 1e-40f;  // denormal x scale: the inverse's 1e40 is inf in float
    m[1][1] = 1e-40f;
    bad.push_back({"denormal diagonal", m});
    m = glm::ortho(-1.0f, 1.0f, -1.0f, 1.0f, 0.1f, 10.0f);
    m[0][0] = m[1][1] = 3e38f;
    m[2][2] = -3e38f;
    bad.push_back({"3e38 diagonal (orthographic)", m});
    m = persp;
    m[0][0] = m[1][1] = 3e38f;
    bad.push_back({"3e38 scale (perspective)", m});
    m = persp;
    m[3][2] = -3e38f;
    bad.push_back({"3e38 depth offset", m});
    m = glm::mat4(0.0f);  // a near plane 9e59 away: its inverse overflows float
    m[0][0] = m[1][1] = 1.0f;
    m[2][3] = -1e-30f;
    m[3][2] = -9e29f;
    bad.push_back({"near plane beyond float range", m});
    for (const auto& [what, matrix] : bad) {
        const std::string what_ = what;
        CAPTURE(what_);
        ProjectionInfo info;
        std::string why;
        CHECK(analyse(matrix, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, info, why) == SSAO_ERROR_INVALID_PROJECTION);
        CHECK(why.find("32-bit float") != std::string::npos);
    }
    // Extreme but usable: a 1e-6 near plane, a 1e9 far plane, a 1e-4 degree field of view.
    for (const glm::mat4& ok : {glm::perspective(glm::radians(60.0f), 1.0f, 1e-6f, 1e9f),
                                glm::perspective(glm::radians(1e-4f), 1.0f, 0.1f, 100.0f),
                                glm::ortho(-1e9f, 1e9f, -1e9f, 1e9f, -1e9f, 1e9f)}) {
        ProjectionInfo info;
        std::string why;
        CHECK_MESSAGE(analyse(ok, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, info, why) == SSAO_OK, why);
    }
}

TEST_CASE("projection: a perspective with the near plane behind the camera is rejected") {
    ProjectionInfo info;
    std::string why;
    glm::mat4 m = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f);
    m[3][2] = -m[3][2];  // near at -0.1 (behind)
    CHECK(analyse(m, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, info, why) == SSAO_ERROR_INVALID_PROJECTION);
}

TEST_CASE("projection: view position from view z by multiply-adds equals the inverse projection's") {
    using ssao_impl::view_from_z;
    using ssao_impl::ViewFromZ;
    std::vector<Case> cases = all_cases();
    // A shear (x depending on y) and an oblique near plane (clip z with x and
    // y terms): the xy form holds for both, since neither changes clip w.
    glm::mat4 shear = glm::perspective(glm::radians(60.0f), 1.5f, 0.1f, 100.0f);
    shear[1][0] = 0.2f;
    cases.push_back({"sheared perspective", shear, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, false, false, false, 0.1, 100.0});
    glm::mat4 oblique = glm::perspective(glm::radians(60.0f), 1.5f, 0.1f, 100.0f);
    oblique[0][2] = 0.05f;
    oblique[1][2] = -0.03f;
    cases.push_back({"oblique near plane", oblique, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, false, false, false, 0.1, 100.0});
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int vw = 641, vh = 359;
    for (const Case& c : cases) {
        CAPTURE(c.name);
        ProjectionInfo info;
        std::string why;
        REQUIRE(analyse(c.m, c.clip, info, why) == SSAO_OK);
        const ViewFromZ vz = view_from_z(info, vw, vh);
        // What the shader does: float coefficients, float arithmetic.
        const glm::mat2 mul_z(vz.mul_z), mul_1(vz.mul_1);
        const glm::vec2 add_z(vz.add_z), add_1(vz.add_1);
        if (c.ortho) {
            CHECK(vz.mul_z == glm::dmat2(0.0));
            CHECK(vz.add_z == glm::dvec2(0.0));
        } else {
            CHECK(vz.mul_1 == glm::dmat2(0.0));
        }
        double worst = 0.0;
        for (int i = 0; i < 300; ++i) {
            const double px = unit(rng) * vw, py = unit(rng) * vh;
            const double nx = px / vw * 2.0 - 1.0, ny = py / vh * 2.0 - 1.0;
            const double u = 0.05 + 0.9 * unit(rng);
            const double d = c.reverse ? 1.0 - u : u;  // a depth value inside the range, either convention
            const glm::dvec3 p = view_position(info, nx, ny, d);
            if (!std::isfinite(p.x) || !std::isfinite(p.z)) continue;
            const glm::vec2 pf(static_cast<float>(px), static_cast<float>(py));
            const float zf = static_cast<float>(p.z);
            const glm::vec2 xy = (mul_z * pf + add_z) * zf + (mul_1 * pf + add_1);
            const glm::dvec3 q(xy.x, xy.y, zf);
            worst = std::max(worst, glm::length(q - p) / std::max(glm::length(p), 1e-30));
            // In double the form is exact.
            const glm::dvec3 qd = ssao_impl::view_position_from_z(vz, px, py, p.z);
            CHECK(glm::length(qd - p) <= 1e-9 * std::max(glm::length(p), 1.0));
        }
        CAPTURE(worst);
        CHECK(worst < 2e-6);  // a few float roundings
    }
}

TEST_CASE("projection: the depth step from view z follows the depth's own derivative") {
    using ssao_impl::view_from_z;
    for (const Case& c : all_cases()) {
        CAPTURE(c.name);
        ProjectionInfo info;
        std::string why;
        REQUIRE(analyse(c.m, c.clip, info, why) == SSAO_OK);
        const ssao_impl::ViewFromZ vz = view_from_z(info, 64, 48);
        for (double u : {0.1, 0.5, 0.9}) {
            const double d = c.reverse ? 1.0 - u : u;
            const double z = view_position(info, 0.0, 0.0, d).z;
            if (!std::isfinite(z)) continue;
            // d(view z)/d(ndc z) = w^2 / |det| against a central difference.
            const double w = vz.w_z * z + vz.w_1;
            const double analytic = w * w / std::abs(vz.det);
            const double h = 1e-6 * (c.reverse ? -1.0 : 1.0);
            const double ndc_per_depth = info.ndc_per_depth;
            const double z1 = view_position(info, 0.0, 0.0, d + h).z, z0 = view_position(info, 0.0, 0.0, d - h).z;
            const double numeric = std::abs(z1 - z0) / (2.0 * std::abs(h) * ndc_per_depth);
            CHECK(analytic == doctest::Approx(numeric).epsilon(1e-3));
        }
    }
}
