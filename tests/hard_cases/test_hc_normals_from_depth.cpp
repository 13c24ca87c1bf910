// Depth-only input: normal_texture = 0 rebuilds
// view-space normals from depth in the grid pass. Read through the debug
// view RECONSTRUCTED_NORMALS (float precision: a host RGBA32F output):
// a plane gives its analytic normal in every depth convention and at the
// viewport's border, a sphere is within a stated angle except one pixel from
// its silhouette, a crease and box silhouettes keep each side's normal. Then
// the AO from depth alone against the AO from exact normals, and the hard
// cases with normal_texture = 0 for both estimators.
#include <doctest/doctest.h>

#include "conventions.h"
#include "hc_util.h"
#include "normals_view_util.h"

#include <algorithm>
#include <cmath>
#include <string>

using analytic::GBuffer;
using analytic::Scene;

namespace {

constexpr int kW = 64, kH = 48;

// A plane through view point c with unit normal n, large enough to fill the view.
Scene plane(glm::dvec3 c, glm::dvec3 n) {
    n = glm::normalize(n);
    const glm::dvec3 u = glm::normalize(glm::cross(n, std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)));
    const glm::dvec3 v = glm::cross(n, u);
    Scene s;
    s.add_quad(c - 40.0 * u - 40.0 * v, 80.0 * u, 80.0 * v);
    return s;
}

// The reconstruction's error budget at view distance t: float rounding of
// the positions (measured: at most 2.5e-4 rad at these sizes, 1e-5 with
// reverse-Z) plus the depth format's step at t over one pixel's footprint
// (two positions, each off by up to half a step along the view ray, make one
// tangent; a tilted plane stretches that by up to 1.5 here). D32F and D24
// are within 3e-4 rad everywhere; D16 at 6 units with near 0.1 (a step of
// 0.005 units) reaches 0.054 rad, its quantisation and nothing else.
double plane_tolerance(const nfd::Convention& c, double t) {
    const double step = hc::depth_step(c.proj, c.clip, c.format, t);
    return 3e-4 + 3.0 * step / nfd::pixel_size(c, t, kH);
}

}  // namespace

TEST_CASE("normals from depth: a plane gives its analytic normal in every depth convention, border pixels included") {
    testgl::Fixture fx;
    const glm::dvec3 normals[] = {{0, 0, 1}, {0.3, 0.4, 0.866}, {-0.6, 0.2, 0.77}, {0.1, -0.6, 0.79}};
    for (const auto& c : nfd::conventions(double(kW) / kH, 3.0)) {
        CAPTURE(c.name);
        for (const glm::dvec3& pn : normals) {
            CAPTURE(pn.x);
            CAPTURE(pn.y);
            const GBuffer g = analytic::render(plane({0, 0, -6}, pn), c.proj, c.clip, kW, kH);
            nfd::ViewOptions o;
            o.pad = 2;  // garbage around the viewport: the border pixels must use their one inner side
            const auto r = nfd::run_view(fx, g, c.proj, c.clip, c.format, o);
            REQUIRE(r.status == SSAO_OK);
            double worst = 0, worst_border = 0, worst_ratio = 0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    const size_t i = hc::at(x, y, kW);
                    REQUIRE(!g.sky(x, y));
                    const double t = -g.position[i].z;
                    const double e = nfd::angle(r.n[i], g.normal[i]);
                    worst = std::max(worst, e);
                    if (x == 0 || y == 0 || x == kW - 1 || y == kH - 1) worst_border = std::max(worst_border, e);
                    worst_ratio = std::max(worst_ratio, e / plane_tolerance(c, t));
                }
            MESSAGE(c.name << " n=(" << pn.x << "," << pn.y << "): worst " << worst << " rad, border " << worst_border
                           << ", of budget " << worst_ratio);
            CHECK(worst_ratio <= 1.0);
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("normals from depth: a sphere is within 6 degrees of its normal except one pixel from its silhouette") {
    testgl::Fixture fx;
    for (const auto& c : nfd::conventions(double(kW) / kH, 3.0)) {
        if (hc::format_bits(c.format) == 16) continue;  // D16's step at the sphere is a degree by itself (plane test)
        CAPTURE(c.name);
        for (double wall : {-9.0, 1.0}) {  // a wall behind it, or sky
            CAPTURE(wall);
            const GBuffer g = nfd::sphere_gbuffer(c.proj, c.clip, kW, kH, {0.3, -0.2, -6.0}, 1.8, wall);
            const auto r = nfd::run_view(fx, g, c.proj, c.clip, c.format);
            REQUIRE(r.status == SSAO_OK);
            // Which object a pixel shows: the sphere (its normal is not +z
            // everywhere), the wall, or sky.
            auto object = [&](int x, int y) {
                if (g.sky(x, y)) return 0;
                const glm::dvec3 p = g.position[hc::at(x, y, kW)];
                return std::abs(p.z - wall) < 1e-6 ? 1 : 2;
            };
            double worst = 0, worst_near = 0;
            size_t sphere_px = 0, near_px = 0;
            for (int y = 0; y < kH; ++y)
                for (int x = 0; x < kW; ++x) {
                    const int o = object(x, y);
                    if (o == 0) continue;
                    // One pixel from the silhouette: a neighbour (8-connected,
                    // inside the viewport) shows something else.
                    bool near = false;
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            const int nx = x + dx, ny = y + dy;
                            if (nx >= 0 && ny >= 0 && nx < kW && ny < kH && object(nx, ny) != o) near = true;
                        }
                    const size_t i = hc::at(x, y, kW);
                    const double e = nfd::angle(r.n[i], g.normal[i]);
                    if (o == 2) ++sphere_px;
                    if (near) {
                        ++near_px;
                        worst_near = std::max(worst_near, e);
                        // Even there: unit length, facing the camera.
                        CHECK(std::abs(glm::length(r.n[i]) - 1.0f) < 1e-4f);
                        const glm::dvec3 to_eye = c.ortho ? glm::dvec3(0, 0, 1) : -glm::normalize(g.position[i]);
                        CHECK(glm::dot(glm::dvec3(r.n[i]), to_eye) >= 0.0);
                        continue;
                    }
                    worst = std::max(worst, e);
                }
            MESSAGE(c.name << " wall " << wall << ": " << sphere_px << " sphere px, worst " << worst * 180 / M_PI
                           << " deg away from the silhouette, " << worst_near * 180 / M_PI << " deg at it (" << near_px
                           << " px)");
            CHECK(sphere_px > 300);
            CHECK(worst <= 6.0 * M_PI / 180);
        }
    }
    CHECK(fx.gl_errors().empty());
}

// Does pixel p have, along axis d, a side whose two pixels (p + s d and
// p + 2 s d) lie on p's own plane? That is what the reconstruction needs to
// be exact; a pixel without such a side on some axis is the crease pixel
// itself (or a face seen so obliquely that it is one pixel wide): no
// neighbour there knows its plane.
bool resolvable(const GBuffer& g, int x, int y, glm::ivec2 d) {
    const size_t i = hc::at(x, y, g.width);
    auto same_plane = [&](int qx, int qy) {
        if (qx < 0 || qy < 0 || qx >= g.width || qy >= g.height || g.sky(qx, qy)) return false;
        const size_t j = hc::at(qx, qy, g.width);
        const glm::dvec3 n(g.normal[i]);
        return glm::dot(g.normal[j], g.normal[i]) > 0.99999f &&
               std::abs(glm::dot(g.position[j] - g.position[i], n)) < 1e-6 * glm::length(g.position[i]);
    };
    for (int s : {-1, 1})
        if (same_plane(x + s * d.x, y + s * d.y) && same_plane(x + 2 * s * d.x, y + 2 * s * d.y)) return true;
    return false;
}

TEST_CASE("normals from depth: a crease and box silhouettes keep each side's exact normal up to the crease pixel, no smear across") {
    testgl::Fixture fx;
    const Scene scene = hc::crease_scene();
    for (const auto& c : nfd::conventions(double(kW) / kH, 3.0)) {
        if (hc::format_bits(c.format) != 32) continue;  // the plane test covers the formats
        CAPTURE(c.name);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, kW, kH);
        const auto r = nfd::run_view(fx, g, c.proj, c.clip, c.format);
        REQUIRE(r.status == SSAO_OK);
        size_t edge_px = 0, crease_px = 0, wrong = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                if (g.sky(x, y)) continue;
                const size_t i = hc::at(x, y, kW);
                // Beside a crease or a silhouette: a 4-neighbour shows
                // another plane or sky.
                bool edge = false;
                for (glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
                    const int nx = x + d.x, ny = y + d.y;
                    if (nx < 0 || ny < 0 || nx >= kW || ny >= kH) continue;
                    if (g.sky(nx, ny) || glm::dot(g.normal[hc::at(nx, ny, kW)], g.normal[i]) < 0.99999f) edge = true;
                }
                edge_px += edge;
                const glm::dvec3 to_eye = c.ortho ? glm::dvec3(0, 0, 1) : -glm::normalize(g.position[i]);
                CHECK(std::abs(glm::length(r.n[i]) - 1.0f) < 1e-4f);
                CHECK(glm::dot(glm::dvec3(r.n[i]), to_eye) >= 0.0);
                if (!resolvable(g, x, y, {1, 0}) || !resolvable(g, x, y, {0, 1})) {
                    ++crease_px;
                    continue;
                }
                const double e = nfd::angle(r.n[i], g.normal[i]);
                if (e > plane_tolerance(c, -g.position[i].z)) {
                    ++wrong;
                    MESSAGE("pixel " << x << "," << y << ": " << e << " rad off" << (edge ? ", beside an edge" : ""));
                }
            }
        MESSAGE(c.name << ": " << edge_px << " pixels beside a crease or silhouette, " << crease_px
                       << " crease pixels, " << wrong << " others off their plane's normal");
        CHECK(edge_px > 100);
        CHECK(crease_px < edge_px / 2);
        CHECK(wrong == 0);
    }
    CHECK(fx.gl_errors().empty());
}

namespace {

ssao_settings at_resolution(ssao_method m, ssao_resolution res, ssao_blur blur, float radius) {
    ssao_settings s = hc::make(16, blur, SSAO_ROTATION_HASH, radius, m);
    s.resolution = res;
    return s;
}

}  // namespace

// The tolerance: the AO of a pixel reads its own normal only (the samples
// and steps read depth), so where the reconstruction is exact (every pixel
// that has two pixels of its own plane on one side per axis: crease test
// above) the two runs agree but for float rounding of nearly equal normals,
// which may move one sample across a depth comparison at a rare pixel. The
// crease pixels themselves (a face one pixel wide, the crease line) get
// another normal by construction; the blur (2 taps) and the grid (scale
// pixels per texel) spread that a few pixels. So: away from crease pixels no
// pixel differs by more than one sample (1/16); over the whole image the
// mean difference stays below 0.003 (measured: 0 to 0.0018).
TEST_CASE("normals from depth: the AO from depth alone equals the AO from exact normals (full, half and quarter resolution)") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const Scene scene = hc::crease_scene();
    for (const auto& c : nfd::conventions(double(kW) / kH, 3.0)) {
        if (hc::format_bits(c.format) != 32) continue;  // coarser formats: the plane test bounds their normals
        CAPTURE(c.name);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, kW, kH);
        std::vector<glm::ivec2> crease;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                if (!g.sky(x, y) && (!resolvable(g, x, y, {1, 0}) || !resolvable(g, x, y, {0, 1})))
                    crease.push_back({x, y});
        for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER}) {
            CAPTURE(res);
            const ssao_settings s = fx.settings(at_resolution(method, res, SSAO_BLUR_DEPTH_AWARE, 1.0f));
            const int scale = res == SSAO_RESOLUTION_FULL ? 1 : res == SSAO_RESOLUTION_HALF ? 2 : 4;
            const int reach = (static_cast<int>(s.blur_radius) + 1) * scale;
            auto away = [&](size_t i) {
                const int x = static_cast<int>(i % kW), y = static_cast<int>(i / kW);
                for (const glm::ivec2& q : crease)
                    if (std::abs(q.x - x) <= reach && std::abs(q.y - y) <= reach) return false;
                return true;
            };
            hc::RunOptions o;
            o.depth_format = c.format;
            const auto exact = hc::run(fx, g, c.proj, c.clip, o);
            o.depth_only = true;
            const auto rebuilt = hc::run(fx, g, c.proj, c.clip, o);
            REQUIRE(exact.status == SSAO_OK);
            REQUIRE(rebuilt.status == SSAO_OK);
            CHECK((rebuilt.output.passes_run & SSAO_PASS_GRID) != 0);  // the grid pass rebuilt them
            hc::check_unit_finite(rebuilt.ao, c.name.c_str());
            const double one = 1.0 / s.sample_count;
            const auto all = hc::diff(exact.ao, rebuilt.ao, {}, one);
            const auto far = hc::diff(exact.ao, rebuilt.ao, away, one);
            MESSAGE(c.name << " res " << res << ": mean |diff| " << all.mean_abs << ", worst " << all.worst
                           << "; away from " << crease.size() << " crease pixels: worst " << far.worst << " over "
                           << far.compared << " px");
            // The crease pixels' differences, which the depth-aware blur's
            // line fit (blur.frag) carries onto the crease line: measured
            // up to 0.0032 (visibility, reverse-Z, half resolution).
            CHECK(all.mean_abs < 0.0035);
            CHECK(far.compared > all.compared / 4);  // quarter resolution reaches 12 pixels around each
            CHECK(far.worst <= one + 2e-3);
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("normals from depth, hard cases: a plane tilted 0..80 degrees stays unoccluded in every convention and format") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    int runs = 0;
    for (const auto& c : nfd::conventions(double(kW) / kH, 3.0)) {
        CAPTURE(c.name);
        for (double tilt : {0.0, 40.0, 70.0, 80.0}) {
            CAPTURE(tilt);
            for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF}) {
                CAPTURE(res);
                const double a = tilt * M_PI / 180;
                const GBuffer g = analytic::render(plane({0, 0, -4}, {0, std::sin(a), std::cos(a)}), c.proj, c.clip, kW, kH);
                const float radius = 0.4f;
                fx.settings(at_resolution(method, res, SSAO_BLUR_NONE, radius));
                hc::RunOptions o;
                o.depth_format = c.format;
                o.depth_only = true;
                const auto r = hc::run(fx, g, c.proj, c.clip, o);
                REQUIRE(r.status == SSAO_OK);
                ++runs;
                // Pixels whose depth the format resolves to a sixteenth of
                // the radius (the criterion of the G-buffer's tilted-plane case).
                int resolvable = 0, dark = 0;
                for (int y = 0; y < kH; ++y)
                    for (int x = 0; x < kW; ++x) {
                        const size_t i = hc::at(x, y, kW);
                        const double t = -g.position[i].z;
                        if (hc::depth_step(c.proj, c.clip, c.format, t) > radius / 16) continue;
                        ++resolvable;
                        if (r.ao[i] < 0.98f) ++dark;
                    }
                CHECK(resolvable > 0);
                CHECK(dark == 0);
            }
        }
    }
    MESSAGE(runs << " runs");
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("normals from depth, hard cases: sky stays exactly 1, odd sizes and a viewport inside larger textures stay finite and in [0,1]") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const Scene scene = hc::sky_scene();
    const int sizes[][2] = {{48, 40}, {17, 9}, {1, 1}, {2, 1}, {1, 3}};
    for (const auto& c : nfd::conventions(48.0 / 40.0, 3.3)) {
        CAPTURE(c.name);
        for (const auto& sz : sizes) {
            const int W = sz[0], H = sz[1];
            CAPTURE(W);
            CAPTURE(H);
            glm::dmat4 proj = c.proj;
            proj[0][0] *= (48.0 / 40.0) / (double(W) / H);  // keep square pixels at every size
            const GBuffer g = analytic::render(scene, proj, c.clip, W, H);
            for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF}) {
                CAPTURE(res);
                fx.settings(at_resolution(method, res, SSAO_BLUR_DEPTH_AWARE, 0.8f));
                hc::RunOptions o;
                o.depth_format = c.format;
                o.depth_only = true;
                o.pad_x = 2;
                o.pad_y = 1;
                o.pad_right = 3;
                o.pad_top = 2;
                const auto r = hc::run(fx, g, proj, c.clip, o);
                REQUIRE(r.status == SSAO_OK);
                hc::check_unit_finite(r.ao, c.name.c_str());
                int sky_not_one = 0;
                for (int y = 0; y < H; ++y)
                    for (int x = 0; x < W; ++x)
                        if (g.sky(x, y) && r.ao[hc::at(x, y, W)] != 1.0f) ++sky_not_one;
                CHECK(sky_not_one == 0);
            }
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("normals from depth: a scene at tiny view depths (1e-11 and 1e-20 times the unit scene) gives the unit scene's AO") {
    // Pixel-sized tangents there would underflow their cross product (the
    // normal then faces the camera), and at 1e-20 the direction to the eye
    // itself: unscaled, the AO differed by 0.14 on average at 1e-11.
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    std::vector<float> unit;
    for (double k : {1.0, 1e-11, 1e-20}) {
        CAPTURE(k);
        const auto proj = analytic::perspective(hc::kFov, double(kW) / kH, 0.1 * k, 100.0 * k);
        const GBuffer g = analytic::render(hc::crease_scene(k), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH);
        const ssao_settings s =
            fx.settings(hc::make(16, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, static_cast<float>(1.0 * k), method));
        hc::RunOptions o;
        o.depth_only = true;
        const auto r = hc::run(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, o);
        REQUIRE(r.status == SSAO_OK);
        hc::check_unit_finite(r.ao, "tiny");
        if (unit.empty()) {
            unit = r.ao;
            CHECK(*std::min_element(unit.begin(), unit.end()) < 0.8f);  // the crease darkens
            continue;
        }
        hc::check_same_ao(unit, r.ao, s.sample_count, "depth-only normals at a tiny scale");
    }
    CHECK(fx.gl_errors().empty());
}
