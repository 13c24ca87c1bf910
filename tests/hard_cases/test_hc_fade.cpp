// Distance fade (settings fade_start/fade_end, variant FADE): per pixel
// against the unfaded output of the same settings: before fade_start bit for
// bit, beyond fade_end exactly 1, in between the linear blend
// ao + (1 - ao) * (depth - start) / (end - start), depth = the view distance
// along the view axis; the sky stays exactly 1. And the hard cases hold with
// the fade on: every depth convention (reverse-Z, infinite far,
// orthographic, D16..D32F) fades at the same depths, a viewport inside larger
// textures gives the same AO, odd sizes stay in [0,1].
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

using hc::Convention;

std::vector<Convention> conventions(double aspect) {
    return hc::perspective_conventions(aspect, 0.1, 100.0,
                                       {"GL [-1,1] D32F", "GL [-1,1] D24", "GL [-1,1] D16", "reverse-Z [0,1] D32F",
                                        "reverse-Z infinite D32F", "GL infinite D24"}) +
           hc::ortho_conventions(4.0, 3.0, 0.5, 60.0, {"ortho GL [-1,1] D32F", "ortho reverse [0,1] D32F"});
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Checks the faded image against the unfaded one pixel by pixel. Pixels
// whose view depth lies within `margin` (relative) of fade_start or fade_end
// are left out of the exact checks: the shader's depth is rebuilt from the
// stored depth value, not the analytic hit.
struct FadeCheck {
    size_t before = 0, beyond = 0, between = 0, sky = 0;
    size_t before_changed = 0, beyond_not_one = 0, between_off = 0, sky_not_one = 0;
    double worst_between = 0;
};

FadeCheck check_fade(const GBuffer& g, const std::vector<float>& plain, const std::vector<float>& faded, double start,
                     double end, double margin, double tolerance) {
    FadeCheck c;
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            const size_t i = hc::at(x, y, g.width);
            if (g.sky(x, y)) {
                ++c.sky;
                c.sky_not_one += faded[i] != 1.0f;
                continue;
            }
            const double depth = -g.position[i].z;
            if (depth < start * (1 - margin)) {
                ++c.before;
                c.before_changed += !same_bits(plain[i], faded[i]);
            } else if (depth > end * (1 + margin)) {
                ++c.beyond;
                c.beyond_not_one += faded[i] != 1.0f;
            } else if (depth > start * (1 + margin) && depth < end * (1 - margin)) {
                ++c.between;
                const double f = (depth - start) / (end - start);
                const double want = plain[i] + (1.0 - plain[i]) * f;
                const double err = std::abs(faded[i] - want);
                c.worst_between = std::max(c.worst_between, err);
                c.between_off += err > tolerance;
            }
        }
    return c;
}

}  // namespace

TEST_CASE("fade: before fade_start bit for bit, beyond fade_end exactly 1, linear in view depth between, sky 1") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 96, H = 64;
    const Scene scene = hc::crease_scene();
    for (const auto& c : conventions(double(W) / H)) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        ssao_settings s = hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method);
        s.output_format = SSAO_OUTPUT_R16F;
        fx.settings(s);
        const auto plain = hc::run(fx, g, c);
        REQUIRE(plain.status == SSAO_OK);
        // The crease scene spans view depths of about 2..7 (orthographic: and sky).
        s.fade_start = 3.0f;
        s.fade_end = 5.0f;
        fx.settings(s);
        const auto faded = hc::run(fx, g, c);
        REQUIRE(faded.status == SSAO_OK);
        hc::check_unit_finite(faded.ao, c.name);
        // R16F output: each value carries at most half an ulp of 1 (2^-12)
        // of rounding, the blend formula is evaluated from the rounded plain value.
        const FadeCheck k = check_fade(g, plain.ao, faded.ao, s.fade_start, s.fade_end, 1e-3, 1.5e-3);
        MESSAGE(cname << ": " << k.before << " px before, " << k.between << " between (worst |blend error| "
                      << k.worst_between << "), " << k.beyond << " beyond, " << k.sky << " sky");
        CHECK(k.before > 200);
        CHECK(k.between > 200);
        CHECK(k.beyond > 200);
        CHECK(k.before_changed == 0);
        CHECK(k.beyond_not_one == 0);
        CHECK(k.between_off == 0);
        CHECK(k.sky_not_one == 0);
        // The fade did something where there is occlusion to fade.
        CHECK(hc::mean(faded.ao) > hc::mean(plain.ao));
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE_FIXTURE(hc::CreaseGl, "fade: fading from the camera (fade_start 0) and a fade beyond the scene change what they should") {
    HC_EACH_METHOD(method);
    ssao_settings s = hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_NOISE_4X4, 1.0f, method);
    fx.settings(s);
    const auto plain = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(plain.status == SSAO_OK);
    // A fade starting far beyond the scene changes no pixel.
    s.fade_start = 500.0f;
    s.fade_end = 600.0f;
    fx.settings(s);
    const auto far = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(far.status == SSAO_OK);
    CHECK(std::memcmp(far.ao.data(), plain.ao.data(), plain.ao.size() * sizeof(float)) == 0);
    CHECK(far.output.passes_run == plain.output.passes_run);
    // fade_start 0: the blend runs from the camera.
    s.fade_start = 0.0f;
    s.fade_end = 20.0f;
    fx.settings(s);
    const auto near = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(near.status == SSAO_OK);
    const FadeCheck k = check_fade(g, plain.ao, near.ao, 0.0, 20.0, 1e-3, 1.5e-3);
    CHECK(k.between > 1000);
    CHECK(k.between_off == 0);
    // A fade ending before the nearest surface: every pixel is 1.
    s.fade_end = 0.5f;
    fx.settings(s);
    const auto all = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(all.status == SSAO_OK);
    CHECK(std::all_of(all.ao.begin(), all.ao.end(), [](float v) { return v == 1.0f; }));
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("fade: hard cases with the fade on - a viewport inside larger textures, odd sizes, broken normals, half resolution") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const Scene scene = hc::crease_scene();
    ssao_settings s = hc::make(16, SSAO_BLUR_DEPTH_AWARE, SSAO_ROTATION_NOISE_4X4, 1.0f, method);
    s.fade_start = 3.0f;
    s.fade_end = 5.0f;
    fx.settings(s);
    {
        // Padding around the viewport holds garbage: the AO is that of the G-buffer alone, exactly.
        const int W = 61, H = 37;
        const glm::dmat4 proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
        const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
        const auto alone = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        hc::RunOptions o;
        o.pad_x = 5, o.pad_y = 3, o.pad_right = 7, o.pad_top = 2;
        const auto inside = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, o);
        REQUIRE(alone.status == SSAO_OK);
        REQUIRE(inside.status == SSAO_OK);
        hc::check_unit_finite(alone.ao, "odd size 61x37");
        CHECK(std::memcmp(alone.ao.data(), inside.ao.data(), alone.ao.size() * sizeof(float)) == 0);
    }
    {
        // Broken normals (zero, NaN, inf, back-facing) stay finite and in [0,1].
        const int W = 32, H = 24;
        const glm::dmat4 proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
        const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
        std::vector<glm::vec3> normals = g.normal;
        const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
        for (size_t i = 0; i < normals.size(); i += 7) {
            const glm::vec3 bad[4] = {glm::vec3(0.0f), glm::vec3(nan, 0, 1), glm::vec3(0, inf, 0), -normals[i]};
            normals[i] = bad[(i / 7) % 4];
        }
        hc::RunOptions o;
        o.normal_format = GL_RGBA32F;
        o.normals = &normals;
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, o);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "broken normals");
    }
    for (ssao_resolution res : {SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER}) {
        // Reduced resolution: the sampling pass fades on its grid; the
        // depth-aware upsample keeps faded-out areas at 1 away from nearer
        // geometry, and pixels before fade_start match the unfaded run.
        CAPTURE(res);
        const int W = 64, H = 48;
        const glm::dmat4 proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
        const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
        ssao_settings r = s;
        r.resolution = res;
        r.blur = SSAO_BLUR_NONE;
        r.fade_start = r.fade_end = 0.0f;
        fx.settings(r);
        const auto plain = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        r.fade_start = 3.0f;
        r.fade_end = 5.0f;
        fx.settings(r);
        const auto faded = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(plain.status == SSAO_OK);
        REQUIRE(faded.status == SSAO_OK);
        hc::check_unit_finite(faded.ao, "reduced resolution");
        // Depth margins of a few grid blocks' depth change around the ends.
        const FadeCheck k = check_fade(g, plain.ao, faded.ao, 3.0, 5.0, 0.15, 2.0);
        CHECK(k.before > 100);
        CHECK(k.beyond > 100);
        CHECK(k.before_changed == 0);
        CHECK(k.beyond_not_one == 0);
        CHECK(k.sky_not_one == 0);
        fx.settings(s);
    }
    CHECK(fx.gl_errors().empty());
}
