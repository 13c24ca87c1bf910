// Scale, silhouettes, screen borders, sky, broken normals, radius extremes,
// odd sizes, float16 inputs.
#include <doctest/doctest.h>

#include "cpu_ssao.h"
#include "conventions.h"
#include "hc_util.h"

#include <algorithm>
#include <map>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

using analytic::GBuffer;
using analytic::Scene;

namespace {

// The AO values a depth-aware/gaussian blur may produce at pixel (x, y): the
// range of the raw AO over the taps it may use (same side of a depth step,
// not sky) within `r` pixels in x and y (separable: x pass then y pass).
struct Hull {
    float lo, hi;
};
Hull hull(const std::vector<float>& raw, int W, int H, int x, int y, int r, const std::function<bool(int, int)>& usable) {
    Hull h{2.0f, -1.0f};
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
            const int tx = x + dx, ty = y + dy;
            if (tx < 0 || ty < 0 || tx >= W || ty >= H || !usable(tx, ty)) continue;
            h.lo = std::min(h.lo, raw[hc::at(tx, ty, W)]);
            h.hi = std::max(h.hi, raw[hc::at(tx, ty, W)]);
        }
    return h;
}

// Whether any pixel flagged in `mask` lies in the screen box of the cube of
// half-size r around pixel (x, y)'s view position: every texel a march of
// length r from there can read. A cube reaching behind the eye reads anything.
bool march_box_holds(const GBuffer& g, const glm::dmat4& proj, int x, int y, double r, const std::vector<char>& mask) {
    const glm::dvec3 P = g.position[hc::at(x, y, g.width)];
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (int c = 0; c < 8; ++c) {
        const glm::dvec3 q = P + r * glm::dvec3(c & 1 ? 1 : -1, c & 2 ? 1 : -1, c & 4 ? 1 : -1);
        const glm::dvec4 k = proj * glm::dvec4(q, 1.0);
        if (!(k.w > 1e-9)) return true;
        const double px = (k.x / k.w * 0.5 + 0.5) * g.width, py = (k.y / k.w * 0.5 + 0.5) * g.height;
        x0 = std::min(x0, px); x1 = std::max(x1, px);
        y0 = std::min(y0, py); y1 = std::max(y1, py);
    }
    for (int ty = std::max(0, int(std::floor(y0))); ty <= std::min(g.height - 1, int(std::floor(y1))); ++ty)
        for (int tx = std::max(0, int(std::floor(x0))); tx <= std::min(g.width - 1, int(std::floor(x1))); ++tx)
            if (mask[hc::at(tx, ty, g.width)]) return true;
    return false;
}

}  // namespace

TEST_CASE("scale: the scene modelled 1000 (and 1e20) times larger with a radius as much larger gives the same AO") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    struct Case { const char* name; double k; bool scale_near; ssao_clip_range clip; GLenum fmt; bool reverse; };
    const Case cases[] = {
        {"GL D24, near and far scaled too", 1000.0, true, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, GL_DEPTH_COMPONENT24, false},
        {"reverse-Z D32F, same near", 1000.0, false, SSAO_CLIP_ZERO_TO_ONE, GL_DEPTH_COMPONENT32F, true},
        // View depths past 1e19, where clip w squared overflows a float.
        {"GL D32F, 1e20 times larger", 1e20, true, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, GL_DEPTH_COMPONENT32F, false},
        {"reverse-Z D32F, 1e20 times larger", 1e20, true, SSAO_CLIP_ZERO_TO_ONE, GL_DEPTH_COMPONENT32F, true},
    };
    for (const Case& c : cases) {
        const std::string cname = c.name;
        CAPTURE(cname);
        std::vector<float> ao[2];
        for (int i = 0; i < 2; ++i) {
            const double k = i ? c.k : 1.0;
            const double n = 0.1 * (c.scale_near ? k : 1.0), f = 100.0 * k;
            const auto proj = c.reverse ? analytic::reverse_z(hc::kFov, double(W) / H, n, f)
                                        : analytic::perspective(hc::kFov, double(W) / H, n, f);
            fx.settings(hc::make(16, SSAO_BLUR_DEFAULT, SSAO_ROTATION_NOISE_4X4, static_cast<float>(1.0 * k), method));
            const GBuffer g = analytic::render(hc::crease_scene(k), proj, c.clip, W, H);
            hc::RunOptions o;
            o.depth_format = c.fmt;
            const auto r = hc::run(fx, g, proj, c.clip, o);
            REQUIRE(r.status == SSAO_OK);
            hc::check_unit_finite(r.ao, c.name);
            ao[i] = r.ao;
        }
        CHECK(*std::min_element(ao[0].begin(), ao[0].end()) < 0.8f);  // the crease darkens: not a blank AO on both
        const auto d = hc::diff(ao[0], ao[1], {}, 1.0 / 16);
        MESSAGE(cname << ": mean |diff| " << d.mean_abs << ", worst " << d.worst << ", " << d.over_1e3 << " of " << d.compared << " px > 1e-3");
        CHECK(d.mean_abs < 0.002);
        CHECK(d.worst <= 1.0 / 16 + 2e-3);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("scale: a scene 1e5 units from the world origin, world-space normals, gives the AO of the same scene at the origin") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const auto proj = analytic::reverse_z(hc::kFov, double(W) / H, 0.1, 100.0);
    // A camera yawed 30 degrees so world and view normals differ.
    auto view_at = [](glm::dvec3 origin) {
        const double a = 0.5236, c = std::cos(a), s = std::sin(a);
        glm::dmat4 yaw(1.0);
        yaw[0][0] = c; yaw[0][2] = -s; yaw[2][0] = s; yaw[2][2] = c;
        glm::dmat4 shift(1.0);
        shift[3] = glm::dvec4(-origin, 1.0);
        return hc::crease_view() * yaw * shift;
    };
    fx.settings(hc::make(16, SSAO_BLUR_DEFAULT, SSAO_ROTATION_HASH, 1.0f, method));
    std::vector<float> ao[3];
    const glm::dvec3 origins[] = {glm::dvec3(0.0), glm::dvec3(1e5, 0.0, 1e5), glm::dvec3(-1e5, 3e4, 1e5)};
    for (int i = 0; i < 3; ++i) {
        const glm::dmat4 view = view_at(origins[i]);
        const GBuffer g = analytic::render(hc::to_view(hc::crease_world(1.0, true, origins[i]), view), proj, SSAO_CLIP_ZERO_TO_ONE, W, H);
        hc::RunOptions o;
        o.normal_space = SSAO_NORMAL_SPACE_WORLD;
        o.view_matrix = view;  // rounded to float for the plugin, translation ~1e5
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, o);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "far from origin");
        ao[i] = r.ao;
    }
    // And view-space normals at the origin: the same again.
    const glm::dmat4 v0 = view_at(glm::dvec3(0.0));
    const GBuffer g0 = analytic::render(hc::to_view(hc::crease_world(), v0), proj, SSAO_CLIP_ZERO_TO_ONE, W, H);
    const auto rv = hc::run(fx, g0, proj, SSAO_CLIP_ZERO_TO_ONE);
    REQUIRE(rv.status == SSAO_OK);
    for (const std::vector<float>* other : {static_cast<const std::vector<float>*>(&ao[1]), static_cast<const std::vector<float>*>(&ao[2]), &rv.ao}) {
        const auto d = hc::diff(ao[0], *other, {}, 1.0 / 16);
        MESSAGE("vs origin with world normals: mean |diff| " << d.mean_abs << ", worst " << d.worst);
        CHECK(d.mean_abs < 0.002);
        CHECK(d.worst <= 1.0 / 16 + 2e-3);
    }
    CHECK(*std::min_element(ao[0].begin(), ao[0].end()) < 0.8f);  // the scene has occlusion to lose
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("silhouettes: a box floating well above the radius casts no halo on the floor") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 96, H = 72;
    const double R = 0.5;
    const auto proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
    const glm::dmat4 view = hc::crease_view();
    Scene floor_only;
    floor_only.add_quad({-50, 0, 50}, {100, 0, 0}, {0, 0, -100});
    fx.settings(hc::make(32, SSAO_BLUR_DEFAULT, SSAO_ROTATION_HASH, static_cast<float>(R), method));
    const GBuffer g0 = analytic::render(hc::to_view(floor_only, view), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    const auto r0 = hc::run(fx, g0, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(r0.status == SSAO_OK);
    hc::check_unit_finite(r0.ao, "floor");
    for (double height : {3.0 * R, 6.0 * R}) {
        CAPTURE(height);
        Scene scene = floor_only;
        scene.add_box({-0.8, height, -5.0}, {0.8, height + 1.0, -3.6});
        const GBuffer g = analytic::render(hc::to_view(scene, view), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "floating box");
        // Floor pixels: no darker than the same floor without the box. At 3
        // radii the range check's tail (smoothstep(R / |dz|) = 0.26 at 3R) may
        // still count one sample of 32 at part weight; at 6 radii nothing.
        const float limit = height < 4 * R ? 1.0f / 32 + 2e-3f : 5e-3f;
        float worst = 0;
        int floor_px = 0, darker = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (g.sky(x, y)) continue;
                const glm::dvec3 w = glm::dvec3(glm::inverse(view) * glm::dvec4(g.position[hc::at(x, y, W)], 1.0));
                if (std::abs(w.y) > 1e-6) continue;
                ++floor_px;
                const float d = r0.ao[hc::at(x, y, W)] - r.ao[hc::at(x, y, W)];
                worst = std::max(worst, d);
                if (d > limit) ++darker;
            }
        MESSAGE("box " << height / R << " radii above the floor: " << darker << " of " << floor_px
                       << " floor px darker by > " << limit << ", worst " << worst);
        CHECK(darker == 0);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("silhouettes: the depth-aware blur keeps each side of a depth step within its own values") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const auto proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
    // Left: a concave corner (dark) 3 units away; right: a flat wall 8 away.
    Scene scene;
    scene.add_quad({-6, -4, -3}, {6, 0, 0}, {0, 8, 0});       // near wall, x < 0
    scene.add_quad({-1.5, -4, -3}, {0, 0, 2.5}, {0, 8, 0});   // side wall towards the camera: a corner
    scene.add_quad({-20, -20, -8}, {40, 0, 0}, {0, 40, 0});   // far wall
    const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    const ssao_settings s = hc::make(32, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method);
    fx.settings(s);
    const auto raw = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(raw.status == SSAO_OK);
    auto zof = [&](int x, int y) { return -g.position[hc::at(x, y, W)].z; };
    const ssao_settings blurred_settings = [&] {
        ssao_settings b = s;
        b.blur = SSAO_BLUR_DEPTH_AWARE;
        b.blur_radius = 4;
        return fx.settings(b);
    }();
    const auto blurred = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(blurred.status == SSAO_OK);
    hc::check_unit_finite(raw.ao, "raw");
    hc::check_unit_finite(blurred.ao, "blurred");
    const float eps = 2e-3f;  // R16F storage of the intermediate passes
    int outside = 0, near_step = 0;
    float raw_min_near = 1.0f;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (g.sky(x, y)) continue;
            const double z0 = zof(x, y);
            if (z0 < 5) raw_min_near = std::min(raw_min_near, raw.ao[hc::at(x, y, W)]);
            const Hull h = hull(raw.ao, W, H, x, y, static_cast<int>(blurred_settings.blur_radius), [&](int tx, int ty) {
                return !g.sky(tx, ty) && hc::blur_depth_weight(g, proj, blurred_settings.blur_depth_tolerance, x, y, tx, ty) > 0.0;
            });
            const float v = blurred.ao[hc::at(x, y, W)];
            bool has_other_side = false;
            for (int d = -4; d <= 4; ++d)
                if (x + d >= 0 && x + d < W && !g.sky(x + d, y) && std::abs(zof(x + d, y) - z0) > 0.5 * z0) has_other_side = true;
            if (has_other_side) ++near_step;
            if (v < h.lo - eps || v > h.hi + eps) {
                ++outside;
                if (outside < 5) MESSAGE("pixel " << x << "," << y << ": blurred " << v << " outside its side's range [" << h.lo << ", " << h.hi << "]");
            }
        }
    MESSAGE(near_step << " px within the blur radius of the step, " << outside << " outside their side's range; darkest raw AO on the near side " << raw_min_near);
    CHECK(near_step > 50);
    CHECK(raw_min_near < 0.8f);  // there is something to leak
    CHECK(outside == 0);
    // The detector detects: a plain gaussian does carry AO across the step.
    ssao_settings gs = blurred_settings;
    gs.blur = SSAO_BLUR_GAUSSIAN;
    fx.settings(gs);
    const auto gauss = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    int leaked = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (g.sky(x, y)) continue;
            const double z0 = zof(x, y);
            const Hull h = hull(raw.ao, W, H, x, y, 4, [&](int tx, int ty) {
                return !g.sky(tx, ty) && std::abs(zof(tx, ty) - z0) <= 0.05 * z0;
            });
            if (gauss.ao[hc::at(x, y, W)] < h.lo - eps) ++leaked;
        }
    MESSAGE("plain gaussian: " << leaked << " px darkened beyond their side's range");
    CHECK(leaked > 10);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("screen borders: a full-screen plane has border pixels equal to its interior") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 48, H = 36;
    const auto proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
    struct Case { const char* name; Scene scene; };
    Scene facing, floor;
    facing.add_quad({-100, -100, -5}, {200, 0, 0}, {0, 200, 0});
    floor.add_quad({-100, 0, 100}, {200, 0, 0}, {0, 0, -200});
    // Look down 45 degrees at the floor from 3 units: the floor fills the screen.
    glm::dmat4 view(1.0);
    const double a = 0.785398, c = std::cos(a), s = std::sin(a);
    view[1][1] = c; view[1][2] = s; view[2][1] = -s; view[2][2] = c;
    glm::dmat4 tr(1.0);
    tr[3] = glm::dvec4(0, -3, 0, 1);
    const Case cases[] = {{"facing plane", facing}, {"floor at 45 degrees", hc::to_view(floor, view * tr)}};
    for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4}) {
        fx.settings(hc::make(16, blur, SSAO_ROTATION_NOISE_4X4, 0.5f, method));
        for (const Case& cs : cases) {
            const std::string cname = cs.name;
            CAPTURE(cname);
            CAPTURE(blur);
            const GBuffer g = analytic::render(cs.scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
            for (int i = 0; i < W * H; ++i) REQUIRE_FALSE(g.sky(i % W, i / W));
            const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
            REQUIRE(r.status == SSAO_OK);
            hc::check_unit_finite(r.ao, cs.name);
            const double interior = hc::mean(r.ao, [&](size_t i) {
                const int x = static_cast<int>(i % W), y = static_cast<int>(i / W);
                return x >= 8 && y >= 8 && x < W - 8 && y < H - 8;
            });
            double worst = 0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x)
                    if (x < 2 || y < 2 || x >= W - 2 || y >= H - 2)
                        worst = std::max(worst, std::abs(r.ao[hc::at(x, y, W)] - interior));
            MESSAGE(cname << ", blur " << blur << ": interior " << interior << ", worst border deviation " << worst);
            CHECK(interior >= 0.98);
            CHECK(worst <= 0.01);
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("screen borders: a viewport inside larger textures gives exactly the AO of the same G-buffer alone") {
    // Everything the shader does is viewport-relative (noise tiles and the
    // hash start at the viewport's corner), so this invariance is exact for
    // every rotation mode and blur, borders included.
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 45, H = 31;
    const auto proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
    const GBuffer g = hc::crease_gbuffer(proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    for (ssao_rotation rot : {SSAO_ROTATION_GRADIENT_NOISE, SSAO_ROTATION_NOISE_4X4, SSAO_ROTATION_HASH, SSAO_ROTATION_NONE})
        for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4}) {
            CAPTURE(rot);
            CAPTURE(blur);
            fx.settings(hc::make(16, blur, rot, 1.0f, method));
            const auto alone = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
            hc::RunOptions o;
            o.pad_x = 7;
            o.pad_y = 5;
            o.pad_right = 6;
            o.pad_top = 9;
            const auto inside = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, o);
            REQUIRE(alone.status == SSAO_OK);
            REQUIRE(inside.status == SSAO_OK);
            hc::check_unit_finite(inside.ao, "viewport");
            int differ = 0;
            for (size_t i = 0; i < alone.ao.size(); ++i)
                if (alone.ao[i] != inside.ao[i]) ++differ;
            CHECK(differ == 0);
        }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("screen borders: panning the projection by whole pixels shifts the AO exactly (rotation NONE, or noise with multiples of 4)") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const auto proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
    const Scene scene = hc::crease_scene();
    const GBuffer g0 = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    struct Case { ssao_rotation rot; int kx, ky; };
    // NONE: any shift. NOISE_4X4 tiles from the viewport's corner: only shifts
    // that are multiples of 4 keep each pixel's rotation. HASH depends on the
    // viewport pixel, so no pan is exact for it (not tested here).
    const Case cases[] = {{SSAO_ROTATION_NONE, 3, 2}, {SSAO_ROTATION_NONE, -5, 1}, {SSAO_ROTATION_NOISE_4X4, 4, -8}};
    for (const Case& c : cases) {
        CAPTURE(c.rot);
        CAPTURE(c.kx);
        CAPTURE(c.ky);
        fx.settings(hc::make(16, SSAO_BLUR_NONE, c.rot, 0.5f, method));
        const auto r0 = hc::run(fx, g0, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        const auto p1 = hc::pixel_shift(proj, c.kx, c.ky, W, H);
        const GBuffer g1 = analytic::render(scene, p1, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
        const auto r1 = hc::run(fx, g1, p1, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(r0.status == SSAO_OK);
        REQUIRE(r1.status == SSAO_OK);
        hc::check_unit_finite(r1.ao, "panned");
        // Compare where every kernel sample stays on both screens: radius 0.5
        // at depth > 2.5 spans < 8 px; keep 10 px from every edge.
        int compared = 0, exact = 0;
        double worst = 0;
        for (int y = 10; y < H - 10; ++y)
            for (int x = 10; x < W - 10; ++x) {
                const int x1 = x + c.kx, y1 = y + c.ky;
                if (x1 < 10 || y1 < 10 || x1 >= W - 10 || y1 >= H - 10) continue;
                const float a = r0.ao[hc::at(x, y, W)], b = r1.ao[hc::at(x1, y1, W)];
                ++compared;
                if (a == b) ++exact;
                worst = std::max(worst, double(std::abs(a - b)));
            }
        MESSAGE("pan " << c.kx << "," << c.ky << ": " << exact << " of " << compared << " px bit-identical, worst " << worst);
        // The G-buffers are identical, but the plugin inverts a different
        // float matrix: a sample lying within ~1e-5 px of a texel edge may
        // land in the neighbour. Allow that for one pixel in 500.
        CHECK(compared > 300);
        CHECK(compared - exact <= compared / 500 + 1);
        CHECK(worst <= 1.0 / 16 + 2e-3);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("sky: far-plane pixels output exactly 1 in every convention and do not darken their neighbours through the blur") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 48, H = 40;
    const Scene scene = hc::sky_scene();
    const auto cases =
        hc::perspective_conventions(double(W) / H, 0.1, 100.0,
                                    {"GL [-1,1] D24", "GL [-1,1] D16", "[0,1] D32F", "reverse-Z [0,1] D32F",
                                     "reverse-Z infinite D32F", "GL infinite D24S8"}) +
        hc::ortho_conventions(4.0, 3.3, 0.1, 50.0, {"ortho GL [-1,1] D32F"});
    for (const hc::Convention& c : cases) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        int sky = 0;
        for (int i = 0; i < W * H; ++i) sky += g.sky(i % W, i / W);
        REQUIRE(sky > W * H / 4);
        fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 0.8f, method));
        const auto raw = hc::run(fx, g, c);
        REQUIRE(raw.status == SSAO_OK);
        for (ssao_output_format of : {SSAO_OUTPUT_R8, SSAO_OUTPUT_R16F})
            for (ssao_blur blur : {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_BOX_4X4}) {
                CAPTURE(of);
                CAPTURE(blur);
                ssao_settings s = hc::make(16, blur, SSAO_ROTATION_HASH, 0.8f, method);
                s.output_format = of;
                s.blur_radius = 3;
                fx.settings(s);
                const auto r = hc::run(fx, g, c);
                REQUIRE(r.status == SSAO_OK);
                hc::check_unit_finite(r.ao, c.name);
                int sky_not_one = 0, darkened = 0;
                const float eps = of == SSAO_OUTPUT_R8 ? 0.5f / 255 + 2e-3f : 2e-3f;
                for (int y = 0; y < H; ++y)
                    for (int x = 0; x < W; ++x) {
                        const float v = r.ao[hc::at(x, y, W)];
                        if (g.sky(x, y)) {
                            if (v != 1.0f) ++sky_not_one;
                            continue;
                        }
                        // Blurred geometry stays within the range of the raw
                        // geometry taps around it: the sky adds nothing.
                        const Hull h = hull(raw.ao, W, H, x, y, blur == SSAO_BLUR_BOX_4X4 ? 2 : 3, [&](int tx, int ty) { return !g.sky(tx, ty); });
                        if (v < h.lo - eps) ++darkened;
                    }
                CHECK(sky_not_one == 0);
                CHECK(darkened == 0);
            }
        // Geometry next to the sky is not occluded by it: the facing quad's
        // pixels (z = -6) away from the box and the ledge (more than the
        // radius 0.8 from both) read as open, its borders with the sky too.
        int open_checked = 0, occluded = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                if (g.sky(x, y)) continue;
                const glm::dvec3 p = g.position[static_cast<size_t>(hc::at(x, y, W))];
                if (std::abs(p.z + 6.0) > 1e-6 || p.x > -0.35 || p.y > -0.35) continue;
                ++open_checked;
                occluded += raw.ao[hc::at(x, y, W)] < 0.98f;
            }
        CHECK(open_checked > 20);
        CHECK(occluded == 0);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE_FIXTURE(hc::CreaseReverseZ, "normals: zero, NaN, infinite, non-unit and back-facing normals stay finite and in [0,1] and spread no further than the blur") {
    HC_EACH_METHOD(method);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    struct Bad { const char* name; std::function<glm::vec3(glm::vec3)> make; bool same_ao; };
    const Bad bads[] = {
        {"zero", [](glm::vec3) { return glm::vec3(0.0f); }, false},
        {"NaN", [nan](glm::vec3) { return glm::vec3(nan, 0.0f, 1.0f); }, false},
        {"all NaN", [nan](glm::vec3) { return glm::vec3(nan); }, false},
        {"+inf", [inf](glm::vec3) { return glm::vec3(inf, 1.0f, 0.0f); }, false},
        {"-inf", [inf](glm::vec3) { return glm::vec3(0.0f, -inf, -inf); }, false},
        {"tiny 1e-4", [](glm::vec3 n) { return n * 1e-4f; }, true},
        {"long x7", [](glm::vec3 n) { return n * 7.0f; }, true},
        {"huge 1e4", [](glm::vec3 n) { return n * 1e4f; }, true},
        {"facing away", [](glm::vec3 n) { return -n; }, false},
    };
    const Bad bads32[] = {
        {"denormal-small 1e-25 (RGBA32F only)", [](glm::vec3 n) { return n * 1e-25f; }, false},
        {"max float", [](glm::vec3) { return glm::vec3(3.4e38f, 3.4e38f, 0.0f); }, false},
    };
    for (GLenum nf : {GLenum(GL_RGBA16F), GLenum(GL_RGBA32F)})
        for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_GAUSSIAN}) {
            ssao_settings s = hc::make(16, blur, SSAO_ROTATION_HASH, 1.0f, method);
            s.blur_radius = 3;
            const ssao_settings rs = fx.settings(s);
            hc::RunOptions o;
            o.normal_format = nf;
            const auto clean = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, o);
            REQUIRE(clean.status == SSAO_OK);
            const int spread = blur == SSAO_BLUR_NONE ? 0 : static_cast<int>(rs.blur_radius);
            std::vector<const Bad*> list;
            for (const Bad& b : bads) list.push_back(&b);
            if (nf == GL_RGBA32F)
                for (const Bad& b : bads32) list.push_back(&b);
            for (const Bad* bp : list) {
                const Bad& b = *bp;
                const std::string bname = b.name;
                CAPTURE(bname);
                CAPTURE(nf);
                CAPTURE(blur);
                // Corrupt a 5x4 block and a single pixel, both on geometry.
                std::vector<glm::vec3> normals = g.normal;
                std::vector<char> bad(W * H, 0);
                for (int y = 20; y < 24; ++y)
                    for (int x = 30; x < 35; ++x) bad[hc::at(x, y, W)] = 1;
                bad[hc::at(10, 12, W)] = 1;
                for (size_t i = 0; i < bad.size(); ++i)
                    if (bad[i]) normals[i] = b.make(normals[i]);
                o.normals = &normals;
                const auto r = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, o);
                o.normals = nullptr;
                REQUIRE(r.status == SSAO_OK);
                hc::check_unit_finite(r.ao, b.name);
                // Only pixels within the blur's reach of a pixel that reads a
                // bad normal may change. The kernel pass reads no neighbour's
                // normal; the visibility pass reads the normal of every texel
                // its march crosses (the tangent-plane read), so there a pixel
                // reads a bad normal when one lies inside the screen box of
                // the cube P +- radius.
                std::vector<char> reads_bad = bad;
                if (method == SSAO_METHOD_VISIBILITY)
                    for (int y = 0; y < H; ++y)
                        for (int x = 0; x < W; ++x)
                            if (!g.sky(x, y)) reads_bad[hc::at(x, y, W)] = march_box_holds(g, proj, x, y, rs.radius, bad);
                int changed_far = 0, changed_bad = 0;
                for (int y = 0; y < H; ++y)
                    for (int x = 0; x < W; ++x) {
                        bool near_bad = false;
                        for (int dy = -spread; dy <= spread && !near_bad; ++dy)
                            for (int dx = -spread; dx <= spread; ++dx) {
                                const int tx = x + dx, ty = y + dy;
                                if (tx >= 0 && ty >= 0 && tx < W && ty < H && reads_bad[hc::at(tx, ty, W)]) { near_bad = true; break; }
                            }
                        const float d = std::abs(r.ao[hc::at(x, y, W)] - clean.ao[hc::at(x, y, W)]);
                        if (!near_bad && d != 0.0f) ++changed_far;
                        if (near_bad && d > 2e-3f) ++changed_bad;
                    }
                CHECK(changed_far == 0);
                // A non-unit normal is the same normal: the same AO (up to
                // the half-float rounding of the scaled vector).
                if (b.same_ao) CHECK(changed_bad <= 1);
            }
        }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE_FIXTURE(hc::CreaseGl, "radius: as the radius goes to 0 the AO goes to 1 monotonically - a huge radius stays finite and fast") {
    HC_EACH_METHOD(method);
    double previous = -1;
    std::vector<float> prev_ao;
    for (double radius : {4.0, 2.0, 1.0, 0.5, 0.25, 0.1, 0.03, 0.01, 1e-3, 1e-4}) {
        CAPTURE(radius);
        fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_NONE, static_cast<float>(radius), method));
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "radius");
        const double m = hc::mean(r.ao);
        MESSAGE("radius " << radius << ": mean AO " << m);
        CHECK(m >= previous - 1e-3);
        previous = m;
        prev_ao = r.ao;
    }
    CHECK(previous >= 0.999);
    CHECK(*std::min_element(prev_ao.begin(), prev_ao.end()) >= 0.98f);

    // Thousands of times the scene size: every sample leaves the screen or
    // goes behind the eye; the loop is bounded by the sample count.
    fx.settings(hc::make(64, SSAO_BLUR_DEFAULT, SSAO_ROTATION_HASH, 1.0f, method));
    hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);  // warm-up
    const auto normal = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    for (float radius : {1e5f, 1e8f, 1e30f}) {
        CAPTURE(radius);
        fx.settings(hc::make(64, SSAO_BLUR_DEFAULT, SSAO_ROTATION_HASH, radius, method));
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "huge radius");
        MESSAGE("radius " << radius << ": " << r.ms << " ms (radius 1: " << normal.ms << " ms)");
        CHECK(r.ms < 3 * normal.ms + 200);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("radius: the wall case is non-increasing in the radius") {
    // Floor pixels in front of the wall: a larger radius reaches more of the
    // wall. Per pixel with a fixed kernel (rotation NONE) a sample can only
    // flip from open to occluded as it grows, except where it leaves the
    // screen; binned means must not rise.
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 96, H = 72;
    const glm::dmat4 view = hc::crease_view();
    const auto proj = analytic::perspective(hc::kFov, double(W) / H, 0.1, 100.0);
    const GBuffer g = analytic::render(hc::crease_scene(1.0, false), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    std::vector<double> prev;
    for (double radius : {0.25, 0.5, 1.0, 1.5, 2.0, 3.0}) {
        CAPTURE(radius);
        fx.settings(hc::make(32, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(radius), method));
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "wall");
        std::vector<double> sum(6, 0), cnt(6, 0);
        for (int y = 0; y < H; ++y)
            for (int x = 12; x < W - 12; ++x) {
                if (g.sky(x, y)) continue;
                const glm::dvec3 w = glm::dvec3(glm::inverse(view) * glm::dvec4(g.position[hc::at(x, y, W)], 1.0));
                if (std::abs(w.y) > 1e-6) continue;
                const int b = static_cast<int>((w.z + 6.0) / 0.25);  // distance to the wall, 0.25 bins
                if (b < 0 || b >= 6) continue;
                sum[b] += r.ao[hc::at(x, y, W)];
                cnt[b] += 1;
            }
        std::vector<double> m(6);
        for (int b = 0; b < 6; ++b) {
            REQUIRE(cnt[b] > 20);
            m[b] = sum[b] / cnt[b];
            if (!prev.empty()) {
                CAPTURE(b);
                CHECK(m[b] <= prev[b] + 0.01);
            }
        }
        MESSAGE("radius " << radius << ": AO at 0.125, 0.625, 1.375 from the wall: " << m[0] << ", " << m[2] << ", " << m[5]);
        prev = m;
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("sizes: 1x1, 1x2, 2x1, 3x5, 17x9 and 257x131 run, stay in [0,1] and match the CPU formula") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    struct Size { int w, h; };
    for (Size sz : {Size{1, 1}, Size{1, 2}, Size{2, 1}, Size{3, 5}, Size{17, 9}, Size{257, 131}}) {
        CAPTURE(sz.w);
        CAPTURE(sz.h);
        const auto proj = analytic::perspective(hc::kFov, double(sz.w) / sz.h, 0.1, 100.0);
        const GBuffer g = hc::crease_gbuffer(proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, sz.w, sz.h);
        cpu::Input in;
        in.gbuffer = &g;
        analytic::to_floats(proj, in.projection);
        in.clip = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
        for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4}) {
            CAPTURE(blur);
            const ssao_settings rs = fx.settings(hc::make(16, blur, SSAO_ROTATION_HASH, 1.0f, method));
            const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
            REQUIRE(r.status == SSAO_OK);
            REQUIRE(r.ao.size() == static_cast<size_t>(sz.w) * sz.h);
            hc::check_unit_finite(r.ao, "size");
            if (blur != SSAO_BLUR_NONE) continue;
            int off = 0, compared = 0;
            const int step = sz.w * sz.h > 1000 ? 7 : 1;
            for (int y = 0; y < sz.h; y += (sz.h > 50 ? step : 1))
                for (int x = 0; x < sz.w; x += (sz.w > 50 ? step : 1)) {
                    const float e = std::abs(cpu::ao(in, rs, x, y) - r.ao[hc::at(x, y, sz.w)]);
                    ++compared;
                    if (e > 2e-3f) ++off;
                    CHECK(e <= 1.0f / 16 + 2e-3f);
                }
            CHECK(off <= compared / 50);
        }
        // Odd sizes: no line down the middle (the centre column and row read
        // like their neighbours on a smooth, blurred result).
        if (sz.w >= 17) {
            fx.settings(hc::make(16, SSAO_BLUR_DEPTH_AWARE, SSAO_ROTATION_HASH, 1.0f, method));
            const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
            auto col = [&](int x) { double s = 0; for (int y = 0; y < sz.h; ++y) s += r.ao[hc::at(x, y, sz.w)]; return s / sz.h; };
            auto row = [&](int y) { double s = 0; for (int x = 0; x < sz.w; ++x) s += r.ao[hc::at(x, y, sz.w)]; return s / sz.w; };
            const int cx = sz.w / 2, cy = sz.h / 2;
            // A seam (one line off by d) bends the middle line by d and its
            // neighbours by d/2; the scene's own crease next to the middle
            // bends a neighbour most. The visibility estimator's hash-rotated
            // marches leave more noise per row than the kernel's.
            const double smooth = method == SSAO_METHOD_VISIBILITY ? 0.045 : 0.03;
            auto bend = [](const std::function<double(int)>& line, int c) {
                return std::abs(line(c) - 0.5 * (line(c - 1) + line(c + 1)));
            };
            auto nearby = [&](const std::function<double(int)>& line, int c) {
                double m = smooth;
                for (int k : {c - 1, c + 1}) m = std::max(m, bend(line, k));
                return m;
            };
            CHECK(bend(col, cx) < nearby(col, cx));
            CHECK(bend(row, cy) < nearby(row, cy));
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("sizes: swapping width and height with the camera rolled 90 degrees rotates the AO image") {
    // The kernel basis comes from the view-space normal, so rolling the
    // camera turns the kernel relative to the scene: pixels are not equal one
    // by one, but the rotated image has the same AO statistically. Compared
    // on the blurred output, 64 samples: per-pixel mean |diff| and the means.
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 48, H = 32;
    const double b = std::tan(hc::kFov / 2), a = b * W / H, n = 0.1;
    const auto proj = hc::frustum(-a * n, a * n, -b * n, b * n, n, 100);
    const auto proj_t = hc::frustum(-b * n, b * n, -a * n, a * n, n, 100);  // H x W
    const glm::dmat4 view = hc::crease_view();
    glm::dmat4 roll(1.0);  // +90 degrees about the view axis: (x, y) -> (-y, x)
    roll[0][0] = 0; roll[0][1] = 1; roll[1][0] = -1; roll[1][1] = 0;
    const Scene world = hc::crease_world();
    const GBuffer g = analytic::render(hc::to_view(world, view), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    const GBuffer gt = analytic::render(hc::to_view(world, roll * view), proj_t, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, H, W);
    ssao_settings s = hc::make(64, SSAO_BLUR_GAUSSIAN, SSAO_ROTATION_NONE, 1.0f, method);
    s.blur_radius = 3;
    fx.settings(s);
    const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    const auto rt = hc::run(fx, gt, proj_t, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(r.status == SSAO_OK);
    REQUIRE(rt.status == SSAO_OK);
    hc::check_unit_finite(r.ao, "original");
    hc::check_unit_finite(rt.ao, "rolled");
    // Pixel (x, y) of the W x H image is pixel (H-1-y, x) of the H x W one.
    double sum = 0, m0 = 0, m1 = 0;
    int geometry_mismatch = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const size_t i0 = hc::at(x, y, W), i1 = hc::at(H - 1 - y, x, H);
            if (g.sky(x, y) != gt.sky(H - 1 - y, x) || std::abs(g.depth[i0] - gt.depth[i1]) > 1e-6f) ++geometry_mismatch;
            sum += std::abs(r.ao[i0] - rt.ao[i1]);
            m0 += r.ao[i0];
            m1 += rt.ao[i1];
        }
    const double N = double(W) * H;
    MESSAGE("rolled: mean |diff| " << sum / N << ", means " << m0 / N << " vs " << m1 / N);
    CHECK(geometry_mismatch == 0);  // the set-up is right: the same G-buffer, rotated
    CHECK(sum / N < 0.03);
    CHECK(std::abs(m0 - m1) / N < 0.01);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE_FIXTURE(hc::CreaseReverseZ, "float16 inputs: RGBA16F and RGB16F normals give the AO of RGBA32F normals - R16F output matches R8") {
    HC_EACH_METHOD(method);
    fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method));
    hc::RunOptions o;
    o.normal_format = GL_RGBA32F;
    const auto ref = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, o);
    REQUIRE(ref.status == SSAO_OK);
    for (GLenum nf : {GLenum(GL_RGBA16F), GLenum(GL_RGB16F), GLenum(GL_RGBA8)}) {
        CAPTURE(nf);
        o.normal_format = nf;
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, o);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "float16 normals");
        const auto d = hc::diff(ref.ao, r.ao, {}, 1.0 / 16);
        MESSAGE("normals " << nf << " vs RGBA32F: mean |diff| " << d.mean_abs << ", " << d.over_1e3 << " px differ, worst " << d.worst);
        // Half floats carry ~1e-3 relative: a sample near a threshold may flip.
        CHECK(d.mean_abs < (nf == GL_RGBA8 ? 0.01 : 0.003));
        CHECK(d.over_one_sample <= d.compared / 100);
    }
    ssao_settings s8 = hc::make(16, SSAO_BLUR_DEPTH_AWARE, SSAO_ROTATION_HASH, 1.0f, method);
    ssao_settings s16 = s8;
    s8.output_format = SSAO_OUTPUT_R8;
    fx.settings(s8);
    const auto r8 = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE);
    fx.settings(s16);
    const auto r16 = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE);
    REQUIRE(r8.status == SSAO_OK);
    REQUIRE(r16.status == SSAO_OK);
    const auto d = hc::diff(r16.ao, r8.ao, {}, 1.0);
    CHECK(d.worst <= 0.5 / 255 + 1e-3);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE_FIXTURE(hc::CreaseReverseZ, "normals: a huge but finite normal (x 1e20, RGBA32F) is the same direction as the unit one") {
    // Finding F2: dot(n, n) overflows to +inf for |n| > ~1.8e19, and the
    // shader then treats the normal as broken (falls back to the direction
    // towards the camera) instead of normalising it.
    HC_EACH_METHOD(method);
    fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method));
    hc::RunOptions o;
    o.normal_format = GL_RGBA32F;
    const auto clean = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, o);
    REQUIRE(clean.status == SSAO_OK);
    for (float scale : {1e16f, 1e20f, 1e30f}) {
        CAPTURE(scale);
        std::vector<glm::vec3> normals = g.normal;
        for (auto& n : normals) n *= scale;
        o.normals = &normals;
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, o);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "huge normals");
        const auto d = hc::diff(clean.ao, r.ao, {}, 1.0 / 16);
        MESSAGE("normals x " << scale << ": " << d.over_1e3 << " of " << d.compared << " px differ from unit normals, worst " << d.worst);
        CHECK(d.over_1e3 <= d.compared / 100);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE_FIXTURE(hc::CreaseReverseZ, "depth: NaN, infinite and out-of-range values in a D32F input stay finite, in [0,1] and contained") {
    // A float depth buffer can hold anything the host writes (or uploads).
    // Whatever GL keeps of such values, the output must stay finite and in
    // range, and pixels farther than the kernel footprint + blur radius from
    // the bad ones must be unchanged.
    HC_EACH_METHOD(method);
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_BOX_4X4}) {
        ssao_settings s = hc::make(16, blur, SSAO_ROTATION_HASH, 0.5f, method);
        s.blur_radius = 2;
        fx.settings(s);
        const auto clean = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE);
        REQUIRE(clean.status == SSAO_OK);
        for (float bad : {nan, inf, -inf, 2.0f, -1.0f, 1e-45f}) {
            CAPTURE(blur);
            CAPTURE(bad);
            GBuffer b = g;
            std::vector<char> mask(W * H, 0);
            for (int y = 22; y < 25; ++y)
                for (int x = 30; x < 33; ++x) {
                    b.depth[hc::at(x, y, W)] = bad;
                    mask[hc::at(x, y, W)] = 1;
                }
            const auto r = hc::run(fx, b, proj, SSAO_CLIP_ZERO_TO_ONE);
            REQUIRE(r.status == SSAO_OK);
            hc::check_unit_finite(r.ao, "bad depth");
            // Kernel footprint: radius 0.5 at depth > 2.5 is < 8 px; + blur 2.
            int changed_far = 0;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    const bool near_bad = std::abs(x - 31) <= 1 + 12 && std::abs(y - 23) <= 1 + 12;
                    if (!near_bad && r.ao[hc::at(x, y, W)] != clean.ao[hc::at(x, y, W)]) ++changed_far;
                }
            CHECK(changed_far == 0);
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE_FIXTURE(hc::CreaseReverseZ, "normals: every broken normal (zero, NaN in any component, inf) takes the same documented fallback") {
    // ao.frag: "a broken normal (zero, NaN, inf) falls back to the direction
    // towards the camera". Whole-image runs, RGBA32F, no blur: each kind of
    // broken normal must give the AO of the all-zero normal buffer.
    HC_EACH_METHOD(method);
    fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method));
    hc::RunOptions o;
    o.normal_format = GL_RGBA32F;
    const std::vector<glm::vec3> zero(g.normal.size(), glm::vec3(0.0f));
    o.normals = &zero;
    const auto ref = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, o);
    REQUIRE(ref.status == SSAO_OK);
    CHECK(hc::mean(ref.ao) < 0.95);  // the fallback normal does see the crease
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    const struct { const char* name; glm::vec3 n; } kinds[] = {
        {"(NaN, 0, 1)", {nan, 0.0f, 1.0f}}, {"(0, 1, NaN)", {0.0f, 1.0f, nan}}, {"all NaN", {nan, nan, nan}},
        {"(inf, 1, 0)", {inf, 1.0f, 0.0f}}, {"(0, -inf, 1)", {0.0f, -inf, 1.0f}}, {"(1e-35, 0, 0)", {1e-35f, 0.0f, 0.0f}},
    };
    for (const auto& k : kinds) {
        const std::string kname = k.name;
        CAPTURE(kname);
        const std::vector<glm::vec3> bad(g.normal.size(), k.n);
        o.normals = &bad;
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, o);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, k.name);
        const auto d = hc::diff(ref.ao, r.ao, {}, 1.0 / 16);
        MESSAGE(kname << ": " << d.over_1e3 << " of " << d.compared << " px differ from the zero-normal fallback, mean AO " << hc::mean(r.ao));
        CHECK(d.over_1e3 == 0);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("settings extremes: 1 or 64 samples, strength off..8, power 0.01..16, every blur: finite, in [0,1], monotone in strength and power") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 48, H = 36;
    const auto proj = analytic::reverse_z_infinite(hc::kFov, double(W) / H, 0.1);
    const GBuffer g = hc::crease_gbuffer(proj, SSAO_CLIP_ZERO_TO_ONE, W, H);
    for (uint32_t samples : {1u, 64u})
        for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_BOX_4X4}) {
            // Unblurred AO at each (power, strength), for the formula's check below.
            std::map<std::pair<float, float>, std::vector<float>> raw;
            for (float power : {0.01f, 1.0f, 16.0f}) {
                CAPTURE(samples);
                CAPTURE(blur);
                CAPTURE(power);
                std::vector<float> prev;
                for (float strength : {SSAO_STRENGTH_OFF, 0.5f, 1.0f, 8.0f}) {
                    CAPTURE(strength);
                    ssao_settings s = hc::make(samples, blur, SSAO_ROTATION_HASH, 1.0f, method);
                    s.power = power;
                    s.strength = strength;
                    s.blur_radius = 16;
                    fx.settings(s);
                    const auto r = hc::run(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE);
                    REQUIRE(r.status == SSAO_OK);
                    hc::check_unit_finite(r.ao, "extremes");
                    if (strength == SSAO_STRENGTH_OFF) CHECK(*std::min_element(r.ao.begin(), r.ao.end()) == 1.0f);
                    if (!prev.empty() && blur == SSAO_BLUR_NONE) {
                        int rose = 0;
                        for (size_t i = 0; i < r.ao.size(); ++i) rose += r.ao[i] > prev[i] + 1e-3f;
                        CHECK(rose == 0);  // more strength never lightens a pixel
                    }
                    if (blur == SSAO_BLUR_NONE) raw[{power, strength}] = r.ao;
                    prev = r.ao;
                }
            }
            if (blur != SSAO_BLUR_NONE || samples == 1) continue;  // one sample may see no occlusion
            // The formula, AO = clamp(1 - strength x occlusion, 0, 1)^power, against the occlusion that strength 1,
            // power 1 shows (the same noise, so the same occlusion): what ignoring either setting would fail.
            CAPTURE(samples);
            const std::vector<float>& plain = raw.at({1.0f, 1.0f});
            REQUIRE(*std::min_element(plain.begin(), plain.end()) < 0.8f);  // there is occlusion to scale
            for (const auto& [key, ao] : raw) {
                const float power = key.first, strength = key.second;
                if (strength == SSAO_STRENGTH_OFF) continue;
                CAPTURE(power);
                CAPTURE(strength);
                int checked = 0, off = 0;
                for (size_t i = 0; i < ao.size(); ++i) {
                    if (plain[i] < 0.05f) continue;  // power 0.01's slope there magnifies the R16F rounding
                    const double want = std::pow(std::clamp(1.0 - strength * (1.0 - plain[i]), 0.0, 1.0), power);
                    // R16F rounds the occlusion by 2^-11 at most; strength and power scale that.
                    const double slope = strength * power * std::max(std::pow(std::max(want, 1e-6), 1.0 - 1.0 / power), 1.0);
                    off += std::abs(ao[i] - want) > 1e-3 + slope * 1e-3;
                    ++checked;
                }
                CHECK(checked > 100);
                CHECK(off == 0);
            }
        }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("orthographic with the near plane behind the camera: surfaces at view z = 0 stay finite through the depth-aware blur") {
    // Orthographic cameras (CAD, shadow-style views) may put the near plane
    // behind the eye; a surface through z = 0 then has zero view depth, and
    // the blur's relative tolerance (0.05 * |z|) becomes 0 there.
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 48, H = 36;
    const auto proj = analytic::orthographic(4.0, 3.0, -10.0, 10.0);
    Scene facing, tilted;
    facing.add_quad({-20, -20, 0}, {40, 0, 0}, {0, 40, 0});            // exactly at z = 0
    tilted.add_quad({-20, -20, -5}, {40, 0, 0}, {0, 40, 10});          // crosses z = 0
    tilted.add_box({-1, -1, -1}, {1, 1, 1});                           // straddles z = 0
    for (const Scene* sc : {&facing, &tilted})
        for (ssao_blur blur : {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_BOX_4X4, SSAO_BLUR_NONE}) {
            CAPTURE(blur);
            CAPTURE(sc == &facing);
            const GBuffer g = analytic::render(*sc, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
            fx.settings(hc::make(16, blur, SSAO_ROTATION_HASH, 0.5f, method));
            const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
            REQUIRE(r.status == SSAO_OK);
            hc::check_unit_finite(r.ao, "ortho z = 0");
            if (sc == &facing) CHECK(*std::min_element(r.ao.begin(), r.ao.end()) >= 0.98f);
        }
    CHECK(fx.gl_errors().empty());
}
