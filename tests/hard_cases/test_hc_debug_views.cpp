// Debug views RAW_AO and BLUR_WEIGHTS (ssao_settings.debug_view) through the
// ABI: RAW_AO at full resolution is exactly the output with blur NONE, and
// below full resolution every pixel of a block shows its grid texel (no depth
// weights); BLUR_WEIGHTS is exactly 1 on a flat plane and for the blurs that
// ignore depth, below 1 beside a silhouette; and the hard cases hold with
// each view on: sky pixels exactly 1, odd sizes and inset viewports written
// exactly inside the viewport, every depth convention and format, both
// estimators. The GL state the host set is restored and no GL error is raised.
#include <doctest/doctest.h>

#include "conventions.h"
#include "hc_util.h"
#include "uniforms.h"  // SSAO_BLUR_SLOPE_DAMPING (shaders/ssao_constants.h)

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using analytic::GBuffer;
using analytic::Scene;

namespace {

const ssao_debug_view kViews[] = {SSAO_DEBUG_VIEW_RAW_AO, SSAO_DEBUG_VIEW_BLUR_WEIGHTS};
const ssao_resolution kResolutions[] = {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER};

ssao_settings make(ssao_method method, ssao_blur blur, ssao_resolution res, ssao_debug_view view) {
    ssao_settings s = hc::make(16, blur, SSAO_ROTATION_HASH, 1.0f, method);
    s.resolution = res;
    s.debug_view = view;
    return s;
}

// A wall facing the camera (every pixel at view distance 6, so one depth
// value) with a box 2 units in front of it: silhouettes against the wall.
Scene wall_and_box(bool box) {
    Scene s;
    s.add_quad({-40, -40, -6}, {80, 0, 0}, {0, 80, 0});
    if (box) s.add_box({-0.6, -0.6, -4.5}, {0.6, 0.6, -3.5});
    return s;
}

using hc::Convention;

std::vector<Convention> conventions(double aspect) {
    return hc::perspective_conventions(aspect, 0.1, 100.0,
                                       {"GL [-1,1] D32F", "GL [-1,1] D24", "GL [-1,1] D16", "[0,1] D32F",
                                        "reverse-Z [0,1] D32F", "reverse-Z infinite D32F", "GL infinite D32F",
                                        "reverse-Z [-1,1] D32F"}) +
           hc::ortho_conventions(4.0, 3.0, 0.5, 60.0,
                                 {"ortho GL [-1,1] D32F", "ortho [0,1] D16", "ortho reverse [0,1] D32F"});
}

// Pixels at least `margin` pixels from any pixel whose depth differs from
// the wall's (the box, or the sky): where every blur tap lies on the wall.
std::vector<bool> far_from_box(const GBuffer& g, float wall_depth, int margin) {
    std::vector<bool> far(g.depth.size(), true);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            if (g.depth[hc::at(x, y, g.width)] == wall_depth) continue;
            for (int dy = -margin; dy <= margin; ++dy)
                for (int dx = -margin; dx <= margin; ++dx) {
                    const int u = x + dx, v = y + dy;
                    if (u >= 0 && v >= 0 && u < g.width && v < g.height) far[hc::at(u, v, g.width)] = false;
                }
        }
    return far;
}

}  // namespace

TEST_CASE("debug views: RAW_AO at full resolution is exactly the output with blur NONE") {
    HC_EACH_METHOD(m);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const Scene scene = hc::crease_scene();
    for (const Convention& c : conventions(double(W) / H)) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        for (ssao_output_format of : {SSAO_OUTPUT_R8, SSAO_OUTPUT_R16F}) {
            CAPTURE(of);
            ssao_settings none = make(m, SSAO_BLUR_NONE, SSAO_RESOLUTION_FULL, SSAO_DEBUG_VIEW_NONE);
            none.output_format = of;
            fx.settings(none);
            const auto want = run(fx, g, c);
            REQUIRE(want.status == SSAO_OK);
            for (ssao_blur blur : {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_NONE}) {
                CAPTURE(blur);
                ssao_settings raw = make(m, blur, SSAO_RESOLUTION_FULL, SSAO_DEBUG_VIEW_RAW_AO);
                raw.output_format = of;
                fx.settings(raw);
                const auto got = run(fx, g, c);
                REQUIRE(got.status == SSAO_OK);
                // The visibility march reads the grid at full resolution too.
                CHECK(got.output.passes_run ==
                      (m == SSAO_METHOD_VISIBILITY ? uint32_t(SSAO_PASS_GRID | SSAO_PASS_OCCLUSION) : uint32_t(SSAO_PASS_OCCLUSION)));
                CHECK(got.ao == want.ao);
            }
            CHECK(*std::min_element(want.ao.begin(), want.ao.end()) < 0.8f);  // the crease darkens: AO is there
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("debug views: RAW_AO below full resolution shows each block's own grid texel") {
    HC_EACH_METHOD(m);
    testgl::Fixture fx;
    const int W = 67, H = 41;  // odd: partial blocks on the right and at the top
    const auto proj = analytic::reverse_z(hc::kFov, double(W) / H, 0.1, 100.0);
    const GBuffer g = analytic::render(hc::crease_scene(), proj, SSAO_CLIP_ZERO_TO_ONE, W, H);
    for (ssao_resolution res : {SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER}) {
        CAPTURE(res);
        const int scale = res == SSAO_RESOLUTION_HALF ? 2 : 4;
        fx.settings(make(m, SSAO_BLUR_DEPTH_AWARE, res, SSAO_DEBUG_VIEW_RAW_AO));
        const auto raw = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE);
        REQUIRE(raw.status == SSAO_OK);
        CHECK(raw.output.passes_run == uint32_t(SSAO_PASS_GRID | SSAO_PASS_OCCLUSION | SSAO_PASS_UPSAMPLE));
        hc::check_unit_finite(raw.ao, "raw ao");
        // Every surface pixel of a block has the same value (no depth
        // weights, no distance weights), and the view is not flat.
        int mixed_blocks = 0, blocks = 0;
        float lo = 1.0f;
        for (int by = 0; by < H; by += scale)
            for (int bx = 0; bx < W; bx += scale) {
                bool seen = false, mixed = false;
                float v0 = 0.0f;
                for (int y = by; y < std::min(by + scale, H); ++y)
                    for (int x = bx; x < std::min(bx + scale, W); ++x) {
                        if (g.sky(x, y)) continue;
                        const float v = raw.ao[hc::at(x, y, W)];
                        lo = std::min(lo, v);
                        if (!seen) v0 = v;
                        mixed = mixed || (seen && v != v0);
                        seen = true;
                    }
                blocks += seen;
                mixed_blocks += mixed;
            }
        CHECK(blocks > 50);
        CHECK(mixed_blocks == 0);
        CHECK(lo < 0.8f);
        // The same grid as the blur-NONE AO: the two differ only where the
        // upsample's weights mix neighbouring texels, so their means agree.
        fx.settings(make(m, SSAO_BLUR_NONE, res, SSAO_DEBUG_VIEW_NONE));
        const auto none = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE);
        REQUIRE(none.status == SSAO_OK);
        CHECK(std::abs(hc::mean(raw.ao) - hc::mean(none.ao)) < 0.02);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("debug views: BLUR_WEIGHTS is exactly 1 on a flat wall, below 1 beside a silhouette, 1 for blurs that ignore depth") {
    HC_EACH_METHOD(m);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    for (const Convention& c : conventions(double(W) / H)) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer flat = analytic::render(wall_and_box(false), c.proj, c.clip, W, H);
        const GBuffer boxed = analytic::render(wall_and_box(true), c.proj, c.clip, W, H);
        const float wall = flat.depth[0];
        for (ssao_resolution res : kResolutions)
            for (ssao_blur blur : {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_NONE}) {
                CAPTURE(res);
                CAPTURE(blur);
                const ssao_settings s = fx.settings(make(m, blur, res, SSAO_DEBUG_VIEW_BLUR_WEIGHTS));
                const auto f = run(fx, flat, c);
                REQUIRE(f.status == SSAO_OK);
                CHECK(std::all_of(f.ao.begin(), f.ao.end(), [](float v) { return v == 1.0f; }));
                const auto b = run(fx, boxed, c);
                REQUIRE(b.status == SSAO_OK);
                hc::check_unit_finite(b.ao, c.name);
                if (blur == SSAO_BLUR_NONE) CHECK(b.output.passes_run == uint32_t(SSAO_PASS_CLEAR));
                // Below full resolution every blur is depth-aware (plan.cpp).
                const bool weighs_depth = blur != SSAO_BLUR_NONE &&
                                          (blur == SSAO_BLUR_DEPTH_AWARE || res != SSAO_RESOLUTION_FULL);
                int below_one = 0, far_below_one = 0;
                const int scale = res == SSAO_RESOLUTION_FULL ? 1 : res == SSAO_RESOLUTION_HALF ? 2 : 4;
                const std::vector<bool> far = far_from_box(boxed, wall, (std::max(int(s.blur_radius), 2) + 1) * scale + 1);
                for (size_t i = 0; i < b.ao.size(); ++i) {
                    below_one += b.ao[i] < 1.0f;
                    far_below_one += far[i] && b.ao[i] != 1.0f;
                }
                CHECK(far_below_one == 0);
                if (weighs_depth)
                    CHECK(below_one > 0);
                else
                    CHECK(below_one == 0);
            }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("debug views: sky pixels are exactly 1 with each view, every resolution and blur") {
    HC_EACH_METHOD(m);
    testgl::Fixture fx;
    const int W = 48, H = 40;
    const Scene scene = hc::sky_scene();
    for (const Convention& c : conventions(double(W) / H)) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        for (ssao_debug_view view : kViews)
            for (ssao_resolution res : kResolutions)
                for (ssao_blur blur : {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_BOX_4X4}) {
                    CAPTURE(view);
                    CAPTURE(res);
                    CAPTURE(blur);
                    fx.settings(make(m, blur, res, view));
                    const auto r = run(fx, g, c);
                    REQUIRE(r.status == SSAO_OK);
                    hc::check_unit_finite(r.ao, c.name);
                    int sky = 0, sky_not_one = 0;
                    for (int y = 0; y < H; ++y)
                        for (int x = 0; x < W; ++x)
                            if (g.sky(x, y)) {
                                ++sky;
                                sky_not_one += r.ao[hc::at(x, y, W)] != 1.0f;
                            }
                    CHECK(sky > 100);
                    CHECK(sky_not_one == 0);
                }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("debug views: odd sizes and inset viewports - every viewport pixel written, nothing outside, same values") {
    HC_EACH_METHOD(m);
    testgl::Fixture fx;
    GladGLContext& gl = fx.gl();
    const int sizes[][2] = {{67, 41}, {1, 1}, {2, 1}, {3, 5}};
    for (const auto& sz : sizes) {
        const int W = sz[0], H = sz[1];
        CAPTURE(W);
        CAPTURE(H);
        const auto proj = analytic::reverse_z(hc::kFov, double(W) / H, 0.1, 100.0);
        const GBuffer g = analytic::render(hc::crease_scene(), proj, SSAO_CLIP_ZERO_TO_ONE, W, H);
        const int TW = W + 4, TH = H + 6, ox = 2, oy = 3;
        const testgl::Textures inset = hc::inset_textures(fx, g, ox, oy, TW, TH);
        const GLuint dt = inset.depth, nt = inset.normal;
        for (ssao_debug_view view : kViews)
            for (ssao_resolution res : kResolutions) {
                CAPTURE(view);
                CAPTURE(res);
                fx.settings(make(m, SSAO_BLUR_DEPTH_AWARE, res, view));
                // The same G-buffer alone, in the library's own output.
                const auto alone = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE);
                REQUIRE(alone.status == SSAO_OK);
                const GLuint out = hc::sentinel_texture(gl, TW, TH, -7.0f);
                ssao_inputs in = fx.inputs(dt, nt, proj, SSAO_CLIP_ZERO_TO_ONE);
                testgl::set_viewport(in, ox, oy, W, H);
                in.output_texture = out;
                ssao_output o{};
                o.size = sizeof o;
                REQUIRE(fx.api().execute(fx.ctx(), &in, &o) == SSAO_OK);
                const std::vector<float> all = fx.read_red(out, TW, TH);
                int unwritten = 0, outside_written = 0, bad = 0, differs = 0;
                for (int y = 0; y < TH; ++y)
                    for (int x = 0; x < TW; ++x) {
                        const float v = all[hc::at(x, y, TW)];
                        const bool inside = x >= ox && x < ox + W && y >= oy && y < oy + H;
                        if (!inside) {
                            outside_written += v != -7.0f;
                            continue;
                        }
                        unwritten += v == -7.0f;
                        bad += !(v >= 0.0f && v <= 1.0f);
                        // R16F (alone) against R32F (here): one half-float step.
                        differs += std::abs(v - alone.ao[hc::at(x - ox, y - oy, W)]) > 1e-3f;
                    }
                CHECK(unwritten == 0);
                CHECK(outside_written == 0);
                CHECK(bad == 0);
                CHECK(differs == 0);
                gl.DeleteTextures(1, &out);
            }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("debug views: the same scene gives the same raw AO in every depth convention and format") {
    HC_EACH_METHOD(m);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const Scene scene = hc::crease_scene();
    for (ssao_resolution res : kResolutions) {
        CAPTURE(res);
        const ssao_settings s = fx.settings(make(m, SSAO_BLUR_DEPTH_AWARE, res, SSAO_DEBUG_VIEW_RAW_AO));
        std::vector<float> ref;
        for (const Convention& c : conventions(double(W) / H)) {
            if (std::string(c.name).rfind("ortho", 0) == 0) continue;  // another camera: another picture
            const std::string cname = c.name;
            CAPTURE(cname);
            const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
            const auto r = run(fx, g, c);
            REQUIRE(r.status == SSAO_OK);
            hc::check_unit_finite(r.ao, c.name);
            if (ref.empty()) {
                ref = r.ao;
                continue;
            }
            const auto d = hc::diff(ref, r.ao, {}, 1.0 / s.sample_count);
            // The bounds of the half-resolution conventions test: depth
            // precision flips a sample here and there (D16 most).
            CHECK(d.mean_abs < 0.01);
            CHECK(d.over_one_sample <= d.compared / 20);
        }
    }
    CHECK(fx.gl_errors().empty());
}

namespace {

// The taps of one pass of blur.frag's gaussian at pixel (x, y) along
// (dx, dy), the centre excepted (it counts with weight 1): for each in-bounds
// non-sky tap at offset k, tap(k, u, v, gaussian, depth weight), the gaussian
// of the resolved sigma and the depth weight hc::blur_depth_weight.
template <typename Tap>
void for_each_tap(const GBuffer& g, const glm::dmat4& proj, const ssao_settings& s, int x, int y, int dx, int dy,
                  Tap tap) {
    const int r = int(s.blur_radius);
    for (int k = -r; k <= r; ++k) {
        const int u = x + k * dx, v = y + k * dy;
        if (k == 0 || u < 0 || v < 0 || u >= g.width || v >= g.height || g.sky(u, v)) continue;
        tap(k, u, v, std::exp(-double(k * k) * 0.5 / (double(s.blur_sigma) * double(s.blur_sigma))),
            hc::blur_depth_weight(g, proj, s.blur_depth_tolerance, x, y, u, v));
    }
}

// blur.frag's share of one pass, in double: sum(gaussian * depth weight) /
// sum(gaussian) over the taps; the centre counts 1 in both sums.
double pass_share(const GBuffer& g, const glm::dmat4& proj, const ssao_settings& s, int x, int y, int dx, int dy) {
    double kept = 1.0, all = 1.0;
    for_each_tap(g, proj, s, x, y, dx, dy, [&](int, int, int, double gaussian, double depth) {
        all += gaussian;
        kept += gaussian * depth;
    });
    return kept / all;
}

}  // namespace

TEST_CASE("debug views: BLUR_WEIGHTS of the depth-aware blur is the product of both passes' shares (CPU oracle)") {
    HC_EACH_METHOD(m);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const auto proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
    // The wall and box (weights 0 or 1 across the silhouette, fractional on
    // the box's sides) and the crease (a floor seen at a slant: fractional
    // weights everywhere, a wall, boxes).
    for (const Scene& scene : {wall_and_box(true), hc::crease_scene()}) {
        const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
        // The oracle's tangent planes come from the normals as the plugin
        // reads them (the fixture uploads RGBA16F): the plane test's
        // tolerance is tight enough for half-float rounding to show.
        GBuffer read = g;
        for (glm::vec3& n : read.normal) n = glm::unpackHalf4x16(glm::packHalf4x16(glm::vec4(n, 0.0f)));
        for (uint32_t radius : {2u, 5u}) {
            CAPTURE(radius);
            ssao_settings want = make(m, SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_FULL, SSAO_DEBUG_VIEW_BLUR_WEIGHTS);
            want.blur_radius = radius;
            const ssao_settings s = fx.settings(want);
            const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
            REQUIRE(r.status == SSAO_OK);
            int off = 0, fractional = 0;
            double worst = 0.0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    const double oracle =
                        g.sky(x, y) ? 1.0 : pass_share(read, proj, s, x, y, 1, 0) * pass_share(read, proj, s, x, y, 0, 1);
                    const double d = std::abs(oracle - double(r.ao[hc::at(x, y, W)]));
                    worst = std::max(worst, d);
                    off += d > 2e-3;  // R16F output (a step below 1 is 4.9e-4); measured worst 4.8e-4
                    fractional += oracle < 0.999 && oracle > 0.001;
                }
            MESSAGE("blur radius " << radius << ": worst |GPU - oracle| " << worst << ", " << fractional
                                   << " pixels strictly between 0 and 1");
            CHECK(off == 0);
            CHECK(fractional > 50);
        }
    }
    CHECK(fx.gl_errors().empty());
}

namespace {

// One pass of blur.frag's depth-aware gaussian over `ao` at pixel (x, y)
// along (dx, dy), in double, from its definition: the weighted least-squares
// line through the taps (weights gaussian times depth weight; the centre at
// offset 0 with weight 1), its slope damped by SSAO_BLUR_SLOPE_DAMPING, read
// at the centre and clamped to [0, 1]; `fit` false: the weighted mean.
double blur_pass(const GBuffer& g, const glm::dmat4& proj, const ssao_settings& s, const std::vector<double>& ao,
                 int x, int y, int dx, int dy, bool fit) {
    double w_sum = 1.0, a_sum = ao[hc::at(x, y, g.width)], k_sum = 0.0, kk_sum = 0.0, ka_sum = 0.0;
    for_each_tap(g, proj, s, x, y, dx, dy, [&](int k, int u, int v, double gaussian, double depth) {
        const double w = gaussian * depth, a = ao[hc::at(u, v, g.width)];
        w_sum += w;
        a_sum += w * a;
        k_sum += w * k;
        kk_sum += w * k * k;
        ka_sum += w * k * a;
    });
    const double mean = a_sum / w_sum, k_mean = k_sum / w_sum;
    if (!fit) return mean;
    const double slope = (ka_sum / w_sum - k_mean * mean) / (kk_sum / w_sum - k_mean * k_mean + SSAO_BLUR_SLOPE_DAMPING);
    return std::clamp(mean - k_mean * slope, 0.0, 1.0);
}

// Both passes (horizontal, then vertical over its result) over the raw AO.
std::vector<double> blur_oracle(const GBuffer& g, const glm::dmat4& proj, const ssao_settings& s,
                                const std::vector<float>& raw, bool fit) {
    std::vector<double> in(raw.begin(), raw.end()), across(in.size(), 1.0), out(in.size(), 1.0);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            if (!g.sky(x, y)) across[hc::at(x, y, g.width)] = blur_pass(g, proj, s, in, x, y, 1, 0, fit);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            if (!g.sky(x, y)) out[hc::at(x, y, g.width)] = blur_pass(g, proj, s, across, x, y, 0, 1, fit);
    return out;
}

}  // namespace

TEST_CASE("debug views: the depth-aware blur is a damped least-squares line through its taps, read at the centre (CPU oracle over RAW_AO)") {
    HC_EACH_METHOD(m);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const auto proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
    // The crease (floor meeting a wall: the AO is darkest on the crease line,
    // where the depth test leaves the blur taps on one side) and the wall
    // and box (silhouettes).
    int sloped = 0;
    for (const Scene& scene : {hc::crease_scene(), wall_and_box(true)}) {
        const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
        GBuffer read = g;  // the normals as the plugin reads them (BLUR_WEIGHTS oracle above)
        for (glm::vec3& n : read.normal) n = glm::unpackHalf4x16(glm::packHalf4x16(glm::vec4(n, 0.0f)));
        const ssao_settings s =
            fx.settings(make(m, SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_FULL, SSAO_DEBUG_VIEW_RAW_AO));
        const auto raw = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        fx.settings(make(m, SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_FULL, SSAO_DEBUG_VIEW_NONE));
        const auto blurred = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(raw.status == SSAO_OK);
        REQUIRE(blurred.status == SSAO_OK);
        const std::vector<double> line = blur_oracle(read, proj, s, raw.ao, true);
        const std::vector<double> mean = blur_oracle(read, proj, s, raw.ao, false);
        double worst = 0.0;
        int off = 0;
        for (size_t i = 0; i < line.size(); ++i) {
            const double d = std::abs(line[i] - double(blurred.ao[i]));
            worst = std::max(worst, d);
            off += d > 3e-3;  // R16F raw AO in, R16F out (a step below 1 is 4.9e-4)
            sloped += std::abs(line[i] - mean[i]) > 0.01;
        }
        MESSAGE("worst |GPU - oracle| " << worst << "; " << sloped
                                         << " pixels so far where the line and the mean differ by > 0.01");
        CHECK(off == 0);
    }
    // Where the line differs from the mean, a blur that took the mean fails
    // the check above (the crease; the kernel sees the wall and box as open).
    CHECK(sloped > 100);
    CHECK(fx.gl_errors().empty());
}
