// Radius in pixels (settings.radius_pixels, variant RADIUS_PIXELS): a pixel's
// radius is radius_pixels times the view-space size of one viewport pixel at
// its depth, at most `radius`; bias and thickness scale with it. Checked
// against runs at the view-unit radius it maps to: everywhere under an
// orthographic projection (one pixel is the same size at every depth), on a
// frontal wall under perspective, off-centre and reverse-Z projections (one
// depth, one size); the clamp gives the plain run bit for bit; at half
// resolution the pixels are the viewport's, not the grid's. And the hard
// cases hold with it on.
#include <doctest/doctest.h>

#include "conventions.h"
#include "hc_util.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

using analytic::GBuffer;
using analytic::Scene;

namespace {

// One viewport pixel's view-space size at view depth `depth` (the geometric
// mean of its width and height), from the projection matrix: a perspective
// divides by w = depth, an orthographic projection does not.
double pixel_size(const glm::dmat4& proj, int W, int H, double depth) {
    const double w = proj[2][3] != 0.0 ? depth : 1.0;
    return std::sqrt(2.0 * w / (W * proj[0][0]) * 2.0 * w / (H * proj[1][1]));
}

// Settings whose bias and thickness are those `radius_pixels` scales to at
// radius r (R = the settings' radius the pixel radius is clamped to).
ssao_settings equivalent(ssao_settings s, double r) {
    const double k = r / s.radius;
    s.radius = float(r);
    s.bias = float(s.bias * k);
    s.thickness = float(s.thickness * k);
    s.radius_pixels = 0.0f;
    return s;
}

void check_close(const std::vector<float>& a, const std::vector<float>& b, const std::function<bool(size_t)>& mask,
                 uint32_t samples, const std::string& what) {
    const auto d = hc::diff(a, b, mask, 1.0 / samples);
    MESSAGE(what << ": mean |diff| " << d.mean_abs << ", worst " << d.worst << ", " << d.over_one_sample
                 << " px > one sample, of " << d.compared);
    CHECK(d.compared > 100);
    // The per-pixel radius is computed in float on the GPU: samples within
    // float rounding of a comparison threshold may flip, rarely.
    CHECK(d.mean_abs < 0.004);
    CHECK(d.over_one_sample <= d.compared / 100 + 1);
    CHECK(d.worst <= 2.0 / samples + 2e-3);
}

ssao_settings base(ssao_method method) {
    ssao_settings s = hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 100.0f, method);
    s.bias = 2.5f;          // 0.025 x radius, stated so the scaled runs can state theirs
    s.thickness = 100.0f;   // 1 x radius
    return s;
}

}  // namespace

TEST_CASE("radius in pixels: orthographic - every pixel gets the view-unit radius N pixels span ([-1,1], [0,1], reversed)") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const Scene scene = hc::crease_scene();
    const double hw = 4.0, hh = 3.0;  // 0.125 view units per pixel both ways
    struct C { const char* name; glm::dmat4 proj; ssao_clip_range clip; };
    const C cases[] = {
        {"ortho GL [-1,1]", analytic::orthographic(hw, hh, 0.5, 60.0), SSAO_CLIP_NEGATIVE_ONE_TO_ONE},
        {"ortho [0,1]", hc::ortho_zo(hw, hh, 0.5, 60.0), SSAO_CLIP_ZERO_TO_ONE},
        {"ortho reverse [0,1]", hc::ortho_reverse(hw, hh, 0.5, 60.0), SSAO_CLIP_ZERO_TO_ONE},
    };
    for (const C& c : cases) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        ssao_settings s = base(method);
        s.radius_pixels = 8.0f;
        const double r = 8.0 * pixel_size(c.proj, W, H, 1.0);
        CHECK(r == doctest::Approx(1.0));
        fx.settings(s);
        const auto px = hc::run(fx, g, c.proj, c.clip);
        fx.settings(equivalent(s, r));
        const auto units = hc::run(fx, g, c.proj, c.clip);
        REQUIRE(px.status == SSAO_OK);
        REQUIRE(units.status == SSAO_OK);
        hc::check_unit_finite(px.ao, c.name);
        CHECK(hc::mean(px.ao) < 0.99);  // there is occlusion to compare
        check_close(px.ao, units.ao, {}, s.sample_count, cname);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("radius in pixels: perspective, off-centre, reverse-Z infinite - a frontal wall gets the radius N pixels span at its depth") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    // Camera at the origin looking down -z at a wall z = -5; a floor y = -1
    // runs up to it, so the wall's lower rows are occluded by the floor.
    Scene scene;
    scene.add_quad(glm::dvec3(-20, -1, -0.5), glm::dvec3(40, 0, 0), glm::dvec3(0, 0, -4.5));
    scene.add_quad(glm::dvec3(-20, -1, -5), glm::dvec3(40, 0, 0), glm::dvec3(0, 20, 0));
    const double n = 0.1, aspect = double(W) / H;
    struct C { const char* name; glm::dmat4 proj; ssao_clip_range clip; };
    const double t = n * std::tan(hc::kFov / 2), r = t * aspect;
    const C cases[] = {
        {"GL [-1,1]", analytic::perspective(hc::kFov, aspect, n, 100.0), SSAO_CLIP_NEGATIVE_ONE_TO_ONE},
        {"reverse-Z infinite [0,1]", analytic::reverse_z_infinite(hc::kFov, aspect, n), SSAO_CLIP_ZERO_TO_ONE},
        // Off-centre, the same pixel size: the view shifted up by a quarter of its height.
        {"off-centre frustum", hc::frustum(-r, r, -0.5 * t, 1.5 * t, n, 100.0), SSAO_CLIP_NEGATIVE_ONE_TO_ONE},
    };
    for (const C& c : cases) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        ssao_settings s = base(method);
        s.radius_pixels = 6.0f;
        const double rw = 6.0 * pixel_size(c.proj, W, H, 5.0);
        fx.settings(s);
        const auto px = hc::run(fx, g, c.proj, c.clip);
        fx.settings(equivalent(s, rw));
        const auto units = hc::run(fx, g, c.proj, c.clip);
        REQUIRE(px.status == SSAO_OK);
        REQUIRE(units.status == SSAO_OK);
        hc::check_unit_finite(px.ao, c.name);
        auto wall = [&](size_t i) { return std::abs(g.position[i].z + 5.0) < 1e-9; };
        double wall_mean = hc::mean(px.ao, wall);
        CHECK(wall_mean < 0.995);  // the floor occludes the wall's lower rows
        check_close(px.ao, units.ao, wall, s.sample_count, cname + " (wall pixels)");
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE_FIXTURE(hc::CreaseGl, "radius in pixels: the clamp - where N pixels span more than `radius` the AO is the plain run's bit for bit") {
    HC_EACH_METHOD(method);
    ssao_settings s = base(method);
    s.radius = 1.0f, s.bias = 0.025f, s.thickness = 1.0f;
    fx.settings(s);
    const auto plain = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    // 16384 pixels: clamped everywhere.
    s.radius_pixels = 16384.0f;
    fx.settings(s);
    const auto all = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(plain.status == SSAO_OK);
    REQUIRE(all.status == SSAO_OK);
    CHECK(std::memcmp(all.ao.data(), plain.ao.data(), plain.ao.size() * sizeof(float)) == 0);
    // 8 pixels: 1 view unit at the depth where 8 pixels span 1; clamped
    // (plain bit for bit) beyond it, smaller radius (more AO-free) nearer.
    s.radius_pixels = 8.0f;
    fx.settings(s);
    const auto part = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(part.status == SSAO_OK);
    const double crossover = 1.0 / (8.0 * pixel_size(proj, W, H, 1.0));  // depth where 8 px = radius
    size_t far = 0, far_same = 0, near = 0;
    for (size_t i = 0; i < g.position.size(); ++i) {
        const double depth = -g.position[i].z;
        if (!(depth > 0)) continue;
        if (depth > crossover * 1.001) {
            ++far;
            far_same += std::memcmp(&part.ao[i], &plain.ao[i], sizeof(float)) == 0;
        } else if (depth < crossover * 0.999) {
            ++near;
        }
    }
    MESSAGE("crossover depth " << crossover << ": " << far << " px clamped, " << near << " px nearer");
    CHECK(far > 200);
    CHECK(near > 200);
    CHECK(far_same == far);
    hc::check_unit_finite(part.ao, "partly clamped");
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("radius in pixels: half and quarter resolution count viewport pixels, not grid texels") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const glm::dmat4 proj = analytic::orthographic(4.0, 3.0, 0.5, 60.0);
    const GBuffer g = hc::crease_gbuffer(proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    for (ssao_resolution res : {SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER}) {
        CAPTURE(res);
        ssao_settings s = base(method);
        s.resolution = res;
        s.radius_pixels = 8.0f;
        fx.settings(s);
        const auto px = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        fx.settings(equivalent(s, 1.0));  // 8 viewport pixels of 0.125
        const auto units = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(px.status == SSAO_OK);
        REQUIRE(units.status == SSAO_OK);
        check_close(px.ao, units.ao, {}, s.sample_count, res == SSAO_RESOLUTION_HALF ? "half" : "quarter");
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("radius in pixels: hard cases with it on - every depth convention alike, padding exact, sky 1, tiny radius unoccluded") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const double aspect = double(W) / H, n = 0.1, f = 100.0;
    const Scene scene = hc::crease_scene();
    const auto cases = hc::perspective_conventions(aspect, n, f,
                                                   {"GL [-1,1] D32F", "GL [-1,1] D24", "[0,1] D32F",
                                                    "reverse-Z [0,1] D32F", "reverse-Z infinite D32F",
                                                    "GL infinite D24", "reverse-Z [-1,1] D32F"});
    ssao_settings s = hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 2.0f, method);
    s.radius_pixels = 10.0f;
    fx.settings(s);
    std::vector<float> ref;
    for (const hc::Convention& c : cases) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        hc::RunOptions o;
        const auto r = hc::run(fx, g, c, o);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, c.name);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x)
                if (g.sky(x, y)) CHECK(r.ao[hc::at(x, y, W)] == 1.0f);
        if (ref.empty()) {
            ref = r.ao;
            CHECK(hc::mean(r.ao) < 0.98);
            // A viewport inside larger textures: exactly the same AO.
            o.pad_x = 3, o.pad_y = 5, o.pad_right = 4, o.pad_top = 1;
            const auto inside = hc::run(fx, g, c, o);
            REQUIRE(inside.status == SSAO_OK);
            CHECK(std::memcmp(inside.ao.data(), r.ao.data(), r.ao.size() * sizeof(float)) == 0);
            continue;
        }
        hc::check_same_ao(ref, r.ao, s.sample_count, cname + " vs GL D32F");
    }
    // A hundredth of a pixel: the radius goes to 0 and so does the occlusion.
    s.radius_pixels = 0.01f;
    fx.settings(s);
    const glm::dmat4 proj = analytic::perspective(hc::kFov, aspect, n, f);
    const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    const auto tiny = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(tiny.status == SSAO_OK);
    CHECK(hc::mean(tiny.ao) > 0.999);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("radius in pixels: a scene 1e-20 and 1e21 times the unit scene gives the unit scene's AO") {
    // A pixel's size at such view depths is a length whose square under- or
    // overflows a float: the radius in pixels would turn into 0 or inf.
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    std::vector<float> unit;
    for (double k : {1.0, 1e-20, 1e21}) {
        CAPTURE(k);
        const auto proj = analytic::perspective(hc::kFov, double(W) / H, 0.1 * k, 100.0 * k);
        const GBuffer g = analytic::render(hc::crease_scene(k), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
        ssao_settings s = hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(2.0 * k), method);
        s.radius_pixels = 10.0f;  // the pixel radius, below `radius` here, decides
        const ssao_settings resolved = fx.settings(s);
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "radius in pixels at a scale");
        if (unit.empty()) {
            unit = r.ao;
            CHECK(hc::mean(unit) < 0.98);
            continue;
        }
        hc::check_same_ao(unit, r.ao, resolved.sample_count, "radius in pixels at a scale");
    }
    CHECK(fx.gl_errors().empty());
}
