// Depth conventions, formats and range: the same scene gives the same AO in
// every convention, reconstruction matches the analytic hit within the
// format's precision, frame info reports the projection right, a tilted plane
// stays unoccluded out to the distance each format resolves, the bias scales
// with the depth step, and view depths beyond the half-float range work.
#include <doctest/doctest.h>

#include "conventions.h"
#include "cpu_ssao.h"
#include "hc_util.h"
#include "projection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

using analytic::GBuffer;
using analytic::Scene;

namespace {

using hc::Convention;

std::vector<Convention> perspective_conventions(double aspect, double n, double f) {
    return hc::perspective_conventions(aspect, n, f,
                                       {"GL [-1,1] D32F", "GL [-1,1] D24", "GL [-1,1] D24S8", "[0,1] D32F",
                                        "reverse-Z [0,1] D32F", "reverse-Z [0,1] D32FS8", "reverse-Z infinite D32F",
                                        "GL infinite D32F", "reverse-Z [-1,1] D32F", "GL infinite D24"});
}

std::vector<Convention> ortho_conventions(double hw, double hh, double n, double f) {
    return hc::ortho_conventions(hw, hh, n, f,
                                 {"ortho GL [-1,1] D32F", "ortho GL [-1,1] D24", "ortho GL [-1,1] D16",
                                  "ortho [0,1] D32F", "ortho reverse [0,1] D32F"});
}

void check_frame_info(testgl::Fixture& fx, const Convention& c) {
    ssao_frame_info info{};
    info.size = sizeof info;
    REQUIRE(fx.api().get_frame_info(fx.ctx(), &info) == SSAO_OK);
    const std::string cname = c.name; CAPTURE(cname);
    CHECK(info.orthographic == (c.ortho ? 1u : 0u));
    CHECK(info.reverse_z == (c.reverse ? 1u : 0u));
    CHECK(info.infinite_far == (c.infinite ? 1u : 0u));
    CHECK(info.depth_bits == static_cast<uint32_t>(hc::format_bits(c.format)));
    // The matrix is float: its near and far are those of the rounded matrix,
    // within float rounding amplified by f/n (the far plane of a float matrix
    // moves by about 1e-7 * f/n relative).
    CHECK(std::abs(info.near_distance - c.n) <= 1e-5 * c.n);
    if (c.infinite) {
        CHECK(std::isinf(info.far_distance));
        CHECK(info.far_distance > 0);
    } else {
        CHECK(std::abs(info.far_distance - c.f) <= (1e-5 + 2e-7 * c.f / c.n) * c.f);
    }
}

}  // namespace

TEST_CASE("depth conventions: the same scene gives the same AO in every clip range, reverse-Z, infinite far, D16/D24/D32F") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const double n = 0.1, f = 100.0;
    const Scene scene = hc::crease_scene();
    for (ssao_kernel_shape shape : {SSAO_KERNEL_HEMISPHERE, SSAO_KERNEL_SPHERE, SSAO_KERNEL_SEPARABLE}) {
        CAPTURE(shape);
        ssao_settings want = hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method);
        want.kernel_shape = shape;
        if (method == SSAO_METHOD_VISIBILITY && shape != SSAO_KERNEL_HEMISPHERE) continue;  // no kernel shape there
        const ssao_settings s = fx.settings(want);
        std::vector<float> ref;
        for (const auto& c : perspective_conventions(double(W) / H, n, f)) {
            const std::string cname = c.name;
            CAPTURE(cname);
            const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
            const auto r = hc::run(fx, g, c);
            REQUIRE(r.status == SSAO_OK);
            hc::check_unit_finite(r.ao, c.name);
            check_frame_info(fx, c);
            if (ref.empty()) {
                ref = r.ao;
                CHECK(*std::min_element(ref.begin(), ref.end()) < 0.8f);  // the crease darkens: not a blank AO
                continue;
            }
            hc::check_same_ao(ref, r.ao, s.sample_count,
                              "kernel " + std::to_string(shape) + ", " + cname + " vs GL D32F");
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth conventions: orthographic in [-1,1], [0,1] and reversed give the same AO") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const Scene scene = hc::crease_scene();
    const ssao_settings s = fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method));
    std::vector<float> ref;
    for (const auto& c : ortho_conventions(4.0, 3.0, 0.5, 60.0)) {
        const std::string cname = c.name; CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        const auto r = hc::run(fx, g, c);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, c.name);
        check_frame_info(fx, c);
        if (ref.empty()) {
            ref = r.ao;
            // Orthographic AO is neither inverted nor absent: the crease darkens.
            CHECK(*std::min_element(r.ao.begin(), r.ao.end()) < 0.8f);
            CHECK(hc::mean(r.ao) < 0.995);
            CHECK(hc::mean(r.ao) > 0.5);
            continue;
        }
        hc::check_same_ao(ref, r.ao, s.sample_count, cname + " vs ortho GL D32F");
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth conventions: open ground to the horizon under an infinite reverse-Z projection stays unoccluded") {
    // With a radius beyond the camera's height, steps rise above eye level and
    // land above the horizon; where a grid block or a pixel straddles it, they
    // read a ground texel past its plane's vanishing line, whose eye ray meets
    // the plane only behind the eye. Taken as a plane in front of the step,
    // that would block open ground far below the horizon. The camera level,
    // 1 above the ground; the image shifted so that the horizon crosses a
    // pixel (0.75) and a half-resolution block (both shifts) and a
    // quarter-resolution block (3) whose picked pixel is on the ground's side:
    // each resolution fails one of them without the guard.
    const int W = 96, H = 72;
    Scene scene;
    scene.add_quad({-1e5, -1.0, 1e5}, {2e5, 0.0, 0.0}, {0.0, 0.0, -2e5});
    testgl::Fixture fx;
    for (double shift : {0.75, 3.0})
    for (ssao_resolution resolution : {SSAO_RESOLUTION_DEFAULT, SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_QUARTER}) {
        CAPTURE(shift);
        CAPTURE(resolution);
        const auto proj = hc::pixel_shift(analytic::reverse_z_infinite(hc::kFov, double(W) / H, 0.1), 0.0, shift, W, H);
        const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_ZERO_TO_ONE, W, H);
        ssao_settings s{};
        s.radius = 1.5f;  // beyond the camera's height
        s.resolution = resolution;
        s.output_format = SSAO_OUTPUT_R16F;
        fx.settings(s);
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        int ground = 0, occluded = 0;
        float darkest = 1.0f;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (g.sky(x, y)) continue;
                // Rows right at the horizon meet the ground at grazing distances no step can resolve.
                if (glm::length(g.position[static_cast<size_t>(hc::at(x, y, W))]) > 200.0) continue;
                ++ground;
                const float ao = r.ao[hc::at(x, y, W)];
                occluded += ao < 0.99f;
                darkest = std::min(darkest, ao);
            }
        MESSAGE("shift " << shift << ", resolution " << resolution << ": " << occluded << " of " << ground << " ground pixels below 0.99, darkest " << darkest);
        CHECK(ground > W * H / 4);
        CHECK(occluded == 0);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth conventions: a projection scaled by any factor from 1e-19 to 1e19 gives the unscaled one's AO") {
    // k P maps every view point to the same NDC. Unless the library takes the
    // scale out, k = 1e19 or 1e-19 overflows the shaders' squares of clip w
    // and gives AO 1 everywhere with an OK status.
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 48, H = 36;
    const Scene scene = hc::crease_scene();
    const ssao_settings s = fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method));
    for (const glm::dmat4& proj : {analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0),
                                   hc::ortho_zo(4.0, 3.0, 0.5, 60.0)}) {
        const bool ortho = proj[3][3] != 0.0;
        CAPTURE(ortho);
        const ssao_clip_range clip = ortho ? SSAO_CLIP_ZERO_TO_ONE : SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
        const GBuffer g = analytic::render(scene, proj, clip, W, H);
        const auto ref = hc::run(fx, g, proj, clip);
        REQUIRE(ref.status == SSAO_OK);
        CHECK(*std::min_element(ref.ao.begin(), ref.ao.end()) < 0.8f);  // the crease darkens
        for (double k : {std::ldexp(1.0, -60), std::ldexp(1.0, 60), 1e-19, 1e19, 3.0}) {
            CAPTURE(k);
            const auto r = hc::run(fx, g, proj * k, clip);
            REQUIRE(r.status == SSAO_OK);
            if (std::ldexp(1.0, std::ilogb(k)) == k)  // a power of two: exact in floats, the same AO bit for bit
                CHECK(r.ao == ref.ao);
            else
                hc::check_same_ao(ref.ao, r.ao, s.sample_count, "k P vs P");
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth conventions: an off-centre frustum gives the AO of the matching half of the symmetric one") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const double n = 0.1, f = 100, b = std::tan(hc::kFov / 2) * n, a = b * W / H;
    const Scene scene = hc::crease_scene();
    fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_NONE, 0.5f, method));
    const auto full_proj = hc::frustum(-a, a, -b, b, n, f);
    const auto right_proj = hc::frustum(0, a, -b, b, n, f);  // the right half: pixels W/2..W-1
    const GBuffer full = analytic::render(scene, full_proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    const GBuffer right = analytic::render(scene, right_proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W / 2, H);
    const auto rf = hc::run(fx, full, full_proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    const auto rr = hc::run(fx, right, right_proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(rf.status == SSAO_OK);
    REQUIRE(rr.status == SSAO_OK);
    hc::check_unit_finite(rf.ao, "symmetric");
    hc::check_unit_finite(rr.ao, "off-centre");
    ssao_frame_info info{};
    info.size = sizeof info;
    REQUIRE(fx.api().get_frame_info(fx.ctx(), &info) == SSAO_OK);
    CHECK(info.near_distance == doctest::Approx(n).epsilon(1e-5));
    CHECK(info.far_distance == doctest::Approx(f).epsilon(1e-4));
    // Kernel footprint: radius 0.5 at the nearest visible depth (> 2.5) spans
    // at most 0.5 / 2.5 * H / (2 tan 30) ~ 8 pixels; stay 10 from the cut
    // and from the top/bottom rows.
    int compared = 0, off = 0;
    double worst = 0;
    for (int y = 10; y < H - 10; ++y)
        for (int x = 10; x < W / 2 - 10; ++x) {
            const double e = std::abs(rr.ao[hc::at(x, y, W / 2)] - rf.ao[hc::at(x + W / 2, y, W)]);
            worst = std::max(worst, e);
            ++compared;
            if (e > 1e-3) ++off;
        }
    MESSAGE("off-centre vs symmetric: " << off << " of " << compared << " differ by > 1e-3, worst " << worst);
    CHECK(off <= compared / 100);
    CHECK(worst <= 1.0 / 16 + 2e-3);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth conventions: a half-pixel jitter leaves the AO profile across the crease unchanged") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 96, H = 96;
    const glm::dmat4 view = hc::crease_view();
    const Scene scene = hc::crease_scene(1.0, false);
    const auto proj = analytic::reverse_z(hc::kFov, 1.0, 0.1, 100.0);
    const double radius = 1.5;
    // The floor's AO profile against the distance to the wall (world z + 6),
    // within 1.25 radii of it: one point per pixel row of floor (the mean
    // over its pixels, away from the image's sides). A jitter moves the rows
    // along the profile, so the jittered rows are compared with the
    // unjittered profile interpolated at their own distances.
    struct Row {
        double distance, ao;
    };
    // The sampling alone, and with the depth-aware blur, which keeps to the
    // floor's own side of the crease: there the profile falls by a third
    // within about one row, and a one-sided mean of the rows next to it would
    // move with where the jitter puts them; the blur's line fit reads the
    // profile at the row itself. Measured: visibility 0.025, the kernel
    // 0.051. The blur's two-way plane test (blur.frag depth_weight) keeps
    // every wall tap out of the floor's row at the crease, so the kernel's
    // steeper profile there is fitted from one side (a one-way test, which
    // lets the wall's taps next to the crease count, reads 0.028 here but
    // blurs folds and steps into stripes).
    const double aware_bound = method == SSAO_METHOD_KERNEL ? 0.06 : 0.03;
    const std::pair<ssao_blur, double> blurs[] = {{SSAO_BLUR_NONE, 0.03}, {SSAO_BLUR_DEPTH_AWARE, aware_bound}};
    for (const auto& blur_bound : blurs) {
        const ssao_blur blur = blur_bound.first;
        const double bound = blur_bound.second;
        CAPTURE(blur);
        fx.settings(hc::make(32, blur, SSAO_ROTATION_HASH, 1.5f, method));
        std::vector<std::vector<Row>> profiles;
        for (double jitter : {0.0, 0.5, -0.5}) {
            const auto p = hc::pixel_shift(proj, jitter, jitter * 0.5, W, H);
            const GBuffer g = analytic::render(scene, p, SSAO_CLIP_ZERO_TO_ONE, W, H);
            const auto r = hc::run(fx, g, p, SSAO_CLIP_ZERO_TO_ONE);
            REQUIRE(r.status == SSAO_OK);
            hc::check_unit_finite(r.ao, "jitter");
            std::vector<Row> rows;
            for (int y = 0; y < H; ++y) {
                double distance = 0, ao = 0;
                int n = 0;
                for (int x = 8; x < W - 8; ++x) {
                    if (g.sky(x, y)) continue;
                    const glm::dvec3 w =
                        glm::dvec3(glm::inverse(view) * glm::dvec4(g.position[hc::at(x, y, W)], 1.0));
                    if (std::abs(w.y) > 1e-6) continue;
                    distance += w.z + 6.0;
                    ao += r.ao[hc::at(x, y, W)];
                    ++n;
                }
                if (n > 20 && distance / n < 1.25 * radius) rows.push_back({distance / n, ao / n});
            }
            std::sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.distance < b.distance; });
            CHECK(rows.size() >= 5);
            profiles.push_back(rows);
        }
        const std::vector<Row>& ref = profiles[0];
        double worst = 0.0;
        for (size_t j = 1; j < profiles.size(); ++j) {
            CAPTURE(j);
            int compared = 0;
            for (const Row& row : profiles[j]) {
                const auto hi = std::lower_bound(ref.begin(), ref.end(), row.distance,
                                                 [](const Row& a, double d) { return a.distance < d; });
                if (hi == ref.begin() || hi == ref.end()) continue;  // outside the unjittered rows
                const Row& lo = *(hi - 1);
                const double t = (row.distance - lo.distance) / (hi->distance - lo.distance);
                CAPTURE(row.distance);
                const double moved = std::abs(row.ao - (lo.ao + t * (hi->ao - lo.ao)));
                CHECK(moved < bound);
                worst = std::max(worst, moved);
                ++compared;
            }
            CHECK(compared >= 4);
        }
        MESSAGE("blur " << blur << ": rows moved by up to " << worst);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("reconstruction: view positions rebuilt from float depth and a float matrix match the analytic ray-plane hit") {
    // The shader's view_position (float) and ssao_impl::view_position (double,
    // from the float-rounded matrix) against the exact hit, within the depth
    // format's step at the hit (docs/hard-cases.md, the depth-step table) plus float rounding.
    const int W = 40, H = 30;
    const Scene scene = hc::crease_scene();
    auto convs = perspective_conventions(double(W) / H, 0.1, 100.0);
    for (auto& c : ortho_conventions(4.0, 3.0, 0.5, 60.0)) convs.push_back(c);
    const double b = std::tan(hc::kFov / 2) * 0.1, a = b * W / H;
    convs.push_back({"off-centre GL D32F", hc::frustum(-0.3 * a, 1.7 * a, -0.8 * b, 1.1 * b, 0.1, 100), SSAO_CLIP_NEGATIVE_ONE_TO_ONE,
                     GL_DEPTH_COMPONENT32F, false, false, false, 0.1, 100});
    convs.push_back({"jittered reverse-Z D32F", hc::pixel_shift(analytic::reverse_z(hc::kFov, double(W) / H, 0.1, 100), 0.5, -0.5, W, H),
                     SSAO_CLIP_ZERO_TO_ONE, GL_DEPTH_COMPONENT32F, false, true, false, 0.1, 100});
    for (const auto& c : convs) {
        const std::string cname = c.name; CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        float m[16];
        analytic::to_floats(c.proj, m);
        ssao_impl::ProjectionInfo info;
        std::string why;
        REQUIRE(ssao_impl::analyse_projection(m, c.clip, info, why) == SSAO_OK);
        CHECK(info.orthographic == c.ortho);
        CHECK(info.reverse_z == c.reverse);
        CHECK(info.infinite_far == c.infinite);
        double worst_shader = 0, worst_core = 0;
        int checked = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (g.sky(x, y)) continue;
                const glm::dvec3 exact = g.position[hc::at(x, y, W)];
                const double t = -exact.z;
                const float d = static_cast<float>(hc::quantise(g.depth[hc::at(x, y, W)], c.format));
                // Allowed: the format's step (what the stored depth can say),
                // its effect on x and y along the ray, and float rounding of
                // the matrix and the arithmetic (a few ulps of |P|).
                const double step = hc::depth_step(c.proj, c.clip, c.format, t);
                const double ray = glm::length(exact) / t;  // |dP| per unit of dz along the ray
                const double allowed = 1.0 * step * ray + 2e-6 * glm::length(exact);
                const glm::dvec3 ps = glm::dvec3(hc::shader_view_position(c.proj, c.clip, x, y, W, H, d));
                const double ndc_x = (x + 0.5) / W * 2 - 1, ndc_y = (y + 0.5) / H * 2 - 1;
                const glm::dvec3 pc = ssao_impl::view_position(info, ndc_x, ndc_y, d);
                worst_shader = std::max(worst_shader, glm::length(ps - exact) / allowed);
                worst_core = std::max(worst_core, glm::length(pc - exact) / allowed);
                ++checked;
            }
        MESSAGE(std::string(c.name) << ": " << checked << " px; worst error / allowed: shader (float) " << worst_shader
                       << ", core (double) " << worst_core);
        CHECK(checked > W * H / 2);
        CHECK(worst_shader <= 1.0);
        CHECK(worst_core <= 1.0);
    }
}

namespace {

struct Format {
    const char* name;
    GLenum format;
    bool reverse_zo;          // reverse-Z with a [0,1] clip range (D32F only)
    bool reverse_gl = false;  // reverse-Z left in GL's [-1,1] clip range (D32F only)
};

const Format kFormats[] = {
    {"D16", GL_DEPTH_COMPONENT16, false},
    {"D24", GL_DEPTH_COMPONENT24, false},
    {"D32F", GL_DEPTH_COMPONENT32F, false},
    {"D32F reverse-Z", GL_DEPTH_COMPONENT32F, true},
    {"D32F reverse-Z in [-1,1]", GL_DEPTH_COMPONENT32F, false, true},
};

glm::dmat4 projection_for(const Format& fm, double n, double ratio, ssao_clip_range& clip) {
    const bool inf = std::isinf(ratio);
    clip = fm.reverse_zo ? SSAO_CLIP_ZERO_TO_ONE : SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
    if (fm.reverse_gl) {
        glm::dmat4 m = hc::reverse_z_gl(hc::kFov, 1.0, n, inf ? n * 1e12 : n * ratio);
        if (inf) { m[2][2] = 1.0; m[3][2] = 2.0 * n; }  // ndc = -1 + 2n/t
        return m;
    }
    if (fm.reverse_zo) return inf ? analytic::reverse_z_infinite(hc::kFov, 1.0, n) : analytic::reverse_z(hc::kFov, 1.0, n, n * ratio);
    return inf ? analytic::infinite(hc::kFov, 1.0, n) : analytic::perspective(hc::kFov, 1.0, n, n * ratio);
}

// A plane through (0, 0, -z0) tilted by `tilt` about the view x axis (0 =
// facing the camera, 89 = almost edge-on, seen at a grazing angle).
Scene tilted_plane(double z0, double tilt_deg) {
    const double a = tilt_deg * 3.14159265358979 / 180.0;
    const glm::dvec3 c(0, 0, -z0), u(1, 0, 0), v(0, std::cos(a), -std::sin(a));
    const double L = z0 * 1e3;
    Scene s;
    s.add_quad(c - u * L - v * L, u * (2 * L), v * (2 * L));
    return s;
}

struct Acne {
    int resolvable = 0, dark = 0;
    float min_ao = 1.0f;
};

// AO of the tilted plane over the pixels whose distance the format resolves:
// the depth step there is at most 1/16 of the radius (so the step-scaled
// bias, 2 x 2 steps, stays below a quarter of the radius and real occluders
// are still seen).
Acne tilted_run(testgl::Fixture& fx, const Format& fm, double n, double ratio, double z0, double tilt,
                double radius, int size = 32, double resolve_fraction = 1.0 / 16) {
    ssao_clip_range clip;
    const glm::dmat4 proj = projection_for(fm, n, ratio, clip);
    GBuffer g = analytic::render(tilted_plane(z0, tilt), proj, clip, size, size);
    hc::gl_window_depth(g, clip, fm.format);
    hc::RunOptions o;
    o.depth_format = fm.format;
    const auto r = hc::run(fx, g, proj, clip, o);
    REQUIRE(r.status == SSAO_OK);
    hc::check_unit_finite(r.ao, fm.name);
    Acne a;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (g.sky(x, y)) continue;
            const double t = -g.position[hc::at(x, y, size)].z;
            if (hc::depth_step(proj, clip, fm.format, t) > radius * resolve_fraction) continue;
            ++a.resolvable;
            const float v = r.ao[hc::at(x, y, size)];
            a.min_ao = std::min(a.min_ao, v);
            if (v < 0.98f) ++a.dark;
        }
    return a;
}

}  // namespace

TEST_CASE("depth formats and range: a plane tilted 0..89 degrees stays unoccluded wherever the format resolves its depth") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method));  // radius set per run below
    int runs = 0, total_resolvable = 0;
    for (const Format& fm : kFormats)
        for (double n : {1e-4, 1e-2, 1.0})
            for (double ratio : {1e3, 1e6, double(INFINITY)})
                for (double zr : {4.0, 40.0, 400.0, 4e4, 4e5}) {
                    const double z0 = zr * n;
                    if (!std::isinf(ratio) && z0 > 0.5 * n * ratio) continue;
                    const double radius = 0.1 * z0;
                    ssao_clip_range clip;
                    const glm::dmat4 proj = projection_for(fm, n, ratio, clip);
                    // Skip distances the format cannot resolve at all.
                    if (hc::depth_step(proj, clip, fm.format, z0) > radius / 16) continue;
                    ssao_settings s = hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(radius), method);
                    fx.settings(s);
                    for (double tilt : {0.0, 30.0, 60.0, 80.0, 89.0}) {
                        const std::string fname = fm.name; CAPTURE(fname);
                        CAPTURE(n);
                        CAPTURE(ratio);
                        CAPTURE(z0);
                        CAPTURE(tilt);
                        const Acne a = tilted_run(fx, fm, n, ratio, z0, tilt, radius);
                        ++runs;
                        total_resolvable += a.resolvable;
                        CHECK(a.dark == 0);
                        CHECK(a.min_ao >= 0.98f);
                    }
                }
    MESSAGE(runs << " runs, " << total_resolvable << " resolvable pixels checked");
    CHECK(runs > 100);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth formats and range: the tilted plane stays unoccluded with the two-plane kernel and the uniform distribution too") {
    // Kernel shapes and distributions: the kernel method's alone (the
    // visibility method ignores both; its tilted planes are the case above).
    const ssao_method method = SSAO_METHOD_KERNEL;
    testgl::Fixture fx;
    int runs = 0;
    for (ssao_kernel_shape shape : {SSAO_KERNEL_HEMISPHERE, SSAO_KERNEL_SEPARABLE})
        for (ssao_kernel_distribution dist : {SSAO_DISTRIBUTION_ACCELERATING, SSAO_DISTRIBUTION_UNIFORM})
            for (const Format& fm : kFormats)
                for (double zr : {4.0, 400.0, 4e4}) {
                    const double n = 0.01, ratio = 1e6, z0 = zr * n, radius = 0.1 * z0;
                    ssao_clip_range clip;
                    const glm::dmat4 proj = projection_for(fm, n, ratio, clip);
                    if (hc::depth_step(proj, clip, fm.format, z0) > radius / 16) continue;
                    ssao_settings s = hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(radius), method);
                    s.kernel_shape = shape;
                    s.distribution = dist;
                    fx.settings(s);
                    for (double tilt : {0.0, 45.0, 80.0, 89.0}) {
                        const std::string fname = fm.name;
                        CAPTURE(fname);
                        CAPTURE(shape);
                        CAPTURE(dist);
                        CAPTURE(z0);
                        CAPTURE(tilt);
                        const Acne a = tilted_run(fx, fm, n, ratio, z0, tilt, radius);
                        ++runs;
                        CHECK(a.dark == 0);
                    }
                }
    MESSAGE(runs << " runs");
    CHECK(runs > 50);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth formats: the bias follows the format's depth step (a tiny depth_step_bias shows acne where the default is clean)") {
    // D16, near 0.01, a plane 1000 near-distances away: the depth step there is
    // about 0.15 radius, far above the constant bias (0.025 radius). The
    // default step-scaled bias keeps it clean; with depth_step_bias = 1e-4
    // only the constant bias is left and the quantised plane shadows itself.
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const Format d16 = kFormats[0];
    const double n = 1e-2, ratio = 1e3, z0 = 1000 * n, radius = 0.1 * z0;
    ssao_clip_range clip;
    const glm::dmat4 proj = projection_for(d16, n, ratio, clip);
    const double step = hc::depth_step(proj, clip, d16.format, z0);
    ssao_settings s = hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(radius), method);
    const ssao_settings resolved = fx.settings(s);
    MESSAGE("D16, near " << n << ", plane at " << z0 << ": depth step " << step << " (" << step / radius
                         << " radius), constant bias " << resolved.bias << " (" << resolved.bias / step << " steps)");
    REQUIRE(step > 4.0 * resolved.bias);  // the constant bias alone is far too small here
    const double tilts[] = {10.0, 20.0, 40.0, 60.0};
    int clean_dark = 0, acne_dark = 0, pixels = 0;
    for (double tilt : tilts) {
        const Acne a = tilted_run(fx, d16, n, ratio, z0, tilt, radius, 48, 0.5);
        clean_dark += a.dark;
        pixels += a.resolvable;
        CHECK(a.resolvable > 500);
    }
    s.depth_step_bias = 1e-4f;
    fx.settings(s);
    for (double tilt : tilts) acne_dark += tilted_run(fx, d16, n, ratio, z0, tilt, radius, 48, 0.5).dark;
    MESSAGE("of " << pixels << " plane pixels, below 0.98: default depth_step_bias " << clean_dark
                  << ", depth_step_bias 1e-4 " << acne_dark);
    CHECK(clean_dark == 0);
    // Estimator-specific: the kernel counts every sample behind the
    // quantised plane, the visibility march only steps that land within
    // [bias, thickness] of it (a direction leaving the plane soon clears the
    // step's quantisation), so fewer pixels show the acne, but still many.
    CHECK(acne_dark > pixels / (method == SSAO_METHOD_VISIBILITY ? 10 : 4));
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth range: view depths beyond the half-float range (> 65504) give the AO of the same scene at unit scale") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const double k = 1e5;  // the crease at 1e5..1e6 units
    const ssao_settings s1 = fx.settings(hc::make(16, SSAO_BLUR_DEFAULT, SSAO_ROTATION_HASH, 1.0f, method));
    const auto p1 = analytic::reverse_z_infinite(hc::kFov, double(W) / H, 0.1);
    const GBuffer g1 = hc::crease_gbuffer(p1, SSAO_CLIP_ZERO_TO_ONE, W, H);
    const auto r1 = hc::run(fx, g1, p1, SSAO_CLIP_ZERO_TO_ONE);
    REQUIRE(r1.status == SSAO_OK);
    struct Case { const char* name; glm::dmat4 proj; };
    const Case cases[] = {
        {"reverse-Z infinite, near 0.1", analytic::reverse_z_infinite(hc::kFov, double(W) / H, 0.1)},
        {"reverse-Z infinite, near 1e4", analytic::reverse_z_infinite(hc::kFov, double(W) / H, 1e4)},
        {"reverse-Z, far 1e8", analytic::reverse_z(hc::kFov, double(W) / H, 0.1, 1e8)},
    };
    for (const Case& c : cases) {
        const std::string cname = c.name; CAPTURE(cname);
        fx.settings(hc::make(16, SSAO_BLUR_DEFAULT, SSAO_ROTATION_HASH, static_cast<float>(k), method));
        const GBuffer g = analytic::render(hc::crease_scene(k), c.proj, SSAO_CLIP_ZERO_TO_ONE, W, H);
        double zmax = 0;
        for (const auto& p : g.position) if (!std::isnan(p.z)) zmax = std::max(zmax, -p.z);
        REQUIRE(zmax > 65504.0 * 4);
        const auto r = hc::run(fx, g, c.proj, SSAO_CLIP_ZERO_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, c.name);
        const auto d = hc::diff(r1.ao, r.ao, {}, 1.0 / s1.sample_count);
        MESSAGE(std::string(c.name) << " (depths to " << zmax << "): mean |diff| to unit scale " << d.mean_abs << ", worst " << d.worst);
        CHECK(d.mean_abs < 0.004);
        CHECK(d.worst < 0.05);
        for (size_t i = 0; i < r.ao.size(); ++i)
            if (g.sky(static_cast<int>(i % W), static_cast<int>(i / W))) CHECK(r.ao[i] == 1.0f);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth precision: the rule-of-thumb step table of docs/hard-cases.md against the exact step of each format") {
    // The exact view-distance change of one depth step (unorm 1/(2^b - 1) or
    // one float ulp at the stored value) against the table's estimate: the
    // table is a rule of thumb, within a factor of 2.5 wherever it applies
    // (t well past the near plane; D32F standard Z: the float ulp near 1).
    struct Row { const char* name; GLenum fmt; bool reverse; };
    const Row rows[] = {
        {"D16", GL_DEPTH_COMPONENT16, false},
        {"D24", GL_DEPTH_COMPONENT24, false},
        {"D32F standard", GL_DEPTH_COMPONENT32F, false},
        {"D32F reverse-Z [0,1]", GL_DEPTH_COMPONENT32F, true},
    };
    for (const Row& r : rows)
        for (double n : {1e-4, 1e-2, 1.0}) {
            const double f = n * 1e6;
            const glm::dmat4 proj = r.reverse ? analytic::reverse_z(hc::kFov, 1.0, n, f) : analytic::perspective(hc::kFov, 1.0, n, f);
            const ssao_clip_range clip = r.reverse ? SSAO_CLIP_ZERO_TO_ONE : SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
            std::string line = std::string(r.name) + ", near " + std::to_string(n) + ": exact / table at t = ";
            for (double k : {10.0, 100.0, 1e3, 1e4, 1e5}) {
                const double t = k * n;
                const double exact = hc::depth_step(proj, clip, r.fmt, t), table = hc::design_step(r.fmt, r.reverse, n, t);
                line += std::to_string(static_cast<int>(k)) + "n: " + std::to_string(exact / table) + "  ";
                CAPTURE(line);
                CHECK(exact / table < 2.5);
                CHECK(exact / table > 1.0 / 2.5);
            }
            MESSAGE(line);
        }
}

TEST_CASE("depth formats and range: orthographic - a plane tilted 0..89 degrees stays unoccluded wherever the format resolves its depth") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    int runs = 0;
    struct OrthoFormat { const char* name; GLenum fmt; int kind; };  // kind 0: GL [-1,1], 1: [0,1], 2: reversed [0,1]
    const OrthoFormat fmts[] = {{"D16 GL", GL_DEPTH_COMPONENT16, 0}, {"D24 GL", GL_DEPTH_COMPONENT24, 0},
                                {"D32F [0,1]", GL_DEPTH_COMPONENT32F, 1}, {"D32F reversed", GL_DEPTH_COMPONENT32F, 2}};
    for (const auto& fm : fmts)
        for (double n : {1e-3, 1.0})
            for (double ratio : {1e2, 1e4})
                for (double zr : {4.0, 40.0}) {
                    const double z0 = zr * n, f = n * ratio;
                    if (z0 > 0.5 * f) continue;
                    const double hw = 0.577 * z0, radius = 0.1 * z0;
                    const ssao_clip_range clip = fm.kind == 0 ? SSAO_CLIP_NEGATIVE_ONE_TO_ONE : SSAO_CLIP_ZERO_TO_ONE;
                    const glm::dmat4 proj = fm.kind == 0 ? analytic::orthographic(hw, hw, n, f)
                                            : fm.kind == 1 ? hc::ortho_zo(hw, hw, n, f) : hc::ortho_reverse(hw, hw, n, f);
                    fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(radius), method));
                    for (double tilt : {0.0, 30.0, 60.0, 80.0, 89.0}) {
                        const std::string fname = fm.name;
                        CAPTURE(fname);
                        CAPTURE(n);
                        CAPTURE(ratio);
                        CAPTURE(z0);
                        CAPTURE(tilt);
                        GBuffer g = analytic::render(tilted_plane(z0, tilt), proj, clip, 32, 32);
                        hc::gl_window_depth(g, clip, fm.fmt);
                        hc::RunOptions o;
                        o.depth_format = fm.fmt;
                        const auto r = hc::run(fx, g, proj, clip, o);
                        REQUIRE(r.status == SSAO_OK);
                        hc::check_unit_finite(r.ao, fm.name);
                        int dark = 0, checked = 0;
                        for (int y = 0; y < 32; ++y)
                            for (int x = 0; x < 32; ++x) {
                                if (g.sky(x, y)) continue;
                                const double t = -g.position[hc::at(x, y, 32)].z;
                                if (hc::depth_step(proj, clip, fm.fmt, t) > radius / 16) continue;
                                ++checked;
                                if (r.ao[hc::at(x, y, 32)] < 0.98f) ++dark;
                            }
                        ++runs;
                        CHECK(dark == 0);
                    }
                }
    MESSAGE(runs << " orthographic runs");
    CHECK(runs > 50);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("finding F1, kept executable: the old snap guard is what made tilted planes self-occlude, and the GPU follows the guard-free formula") {
    // tests/support/cpu_ssao with and without the removed line (Input::legacy_snap_guard).
    // The old snap guard was the kernel pass's: kernel method only.
    const ssao_method method = SSAO_METHOD_KERNEL;
    testgl::Fixture fx;
    const Format d16 = kFormats[0];
    const double n = 1.0, ratio = 1e3, z0 = 4.0, tilt = 60.0, radius = 0.4;
    ssao_clip_range clip;
    const glm::dmat4 proj = projection_for(d16, n, ratio, clip);
    GBuffer g = analytic::render(tilted_plane(z0, tilt), proj, clip, 32, 32);
    for (auto& d : g.depth) d = static_cast<float>(hc::quantise(d, d16.format));
    const ssao_settings rs = fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(radius), method));
    hc::RunOptions o;
    o.depth_format = d16.format;
    const auto r = hc::run(fx, g, proj, clip, o);
    REQUIRE(r.status == SSAO_OK);
    cpu::Input in;
    in.gbuffer = &g;
    analytic::to_floats(proj, in.projection);
    in.clip = clip;
    in.depth_step = 1.0 / 65535.0;
    cpu::Input old_shader = in;
    old_shader.legacy_snap_guard = true;
    int dark_old = 0, dark_now = 0, gpu_off = 0, plane = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            if (g.sky(x, y)) continue;
            ++plane;
            const float now = cpu::ao(in, rs, x, y), old = cpu::ao(old_shader, rs, x, y);
            dark_now += now < 0.98f;
            dark_old += old < 0.98f;
            gpu_off += std::abs(now - r.ao[hc::at(x, y, 32)]) > 2e-3f;
        }
    MESSAGE("D16 plane at 4, tilt 60, " << plane << " px: below 0.98 with the old guard " << dark_old << ", without " << dark_now
                                        << "; GPU differs from the guard-free CPU at " << gpu_off);
    CHECK(dark_old > plane / 10);
    CHECK(dark_now == 0);
    CHECK(gpu_off <= plane / 50);
    CHECK(fx.gl_errors().empty());
}
