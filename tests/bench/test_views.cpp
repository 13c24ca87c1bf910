// The benchmark's views frame every default scene: the high view looks down
// steeply and still fills the image with the scene, the close-up's radius
// covers several times the pixels of the standard view's.
#include "raytracer.h"
#include "scene.h"
#include "views.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

const int kW = 96, kH = 54;

struct Framing {
    double coverage = 0;      // fraction of pixels that hit the scene
    double median_depth = 0;  // view depth over those pixels
};

Framing frame(const raytrace::Tracer& tracer, const camera::Camera& cam) {
    raytrace::RenderOptions ro;
    ro.width = kW;
    ro.height = kH;
    ro.samples = 16;
    ro.radius = 0.01f;
    raytrace::Image img;
    std::string error;
    REQUIRE_MESSAGE(tracer.render(cam, ro, img, error), error);
    std::vector<float> depths;
    for (size_t i = 0; i < img.mask.size(); ++i)
        if (img.mask[i] > 0.5f) depths.push_back(img.depth[i]);
    Framing f;
    f.coverage = double(depths.size()) / double(img.mask.size());
    if (!depths.empty()) {
        std::nth_element(depths.begin(), depths.begin() + long(depths.size() / 2), depths.end());
        f.median_depth = depths[depths.size() / 2];
    }
    return f;
}

}  // namespace

TEST_SUITE("views") {

TEST_CASE("three views and three radii spanning 4x") {
    CHECK(bench::all_views().size() == 3);
    const std::vector<float>& r = bench::radius_scales();
    REQUIRE(r.size() == 3);
    CHECK(r.front() == doctest::Approx(0.5));
    CHECK(r[1] == doctest::Approx(1.0));
    CHECK(r.back() / r.front() == doctest::Approx(4.0));
}

TEST_CASE("every default scene is framed by the high view and the close-up") {
    for (const std::string& rel : bench::scene_files()) {
        const std::string scene_name = rel;
        CAPTURE(scene_name);
        scene::Scene sc;
        std::string error;
        REQUIRE_MESSAGE(scene::load(std::string(SSAO_TEST_ASSETS_DIR) + "/" + rel, sc, error), error);
        raytrace::Tracer tracer(sc.mesh);
        REQUIRE(tracer.ok());
        const float aspect = float(kW) / float(kH);
        const float radius = scene::ao_radius(sc)->radius;

        const camera::Camera standard = bench::view_camera(sc, aspect, bench::View::standard, tracer);
        const camera::Camera high = bench::view_camera(sc, aspect, bench::View::high, tracer);
        const camera::Camera close = bench::view_camera(sc, aspect, bench::View::close, tracer);
        const Framing fs = frame(tracer, standard), fh = frame(tracer, high), fc = frame(tracer, close);
        CAPTURE(fs.coverage);
        CAPTURE(fh.coverage);
        CAPTURE(fc.coverage);

        // The high view looks down at least 60 degrees below the horizon.
        const glm::vec3 dir = glm::normalize(high.target - high.eye);
        CHECK(-dir.y >= std::sin(glm::radians(60.0f)));
        // Both fill their images with scene (sky above a finite floor aside) at
        // least as well as the standard view does.
        CHECK(fh.coverage >= 0.6);
        CHECK(fh.coverage >= fs.coverage - 0.05);
        CHECK(fc.coverage >= 0.6);
        CHECK(fc.coverage >= fs.coverage - 0.05);
        // The close-up's centre is the point the standard view's centre ray meets.
        const glm::vec3 fwd = glm::normalize(standard.target - standard.eye);
        float t = 0;
        glm::vec3 n;
        REQUIRE(tracer.intersect(standard.eye, fwd, 0.0f, 1e30f, t, n));
        CHECK(glm::length(close.target - (standard.eye + fwd * t)) <= 1e-3f * t);
        // Its radius covers several times the pixels of the standard view's.
        const float px_standard = bench::radius_pixels(standard, radius, float(fs.median_depth), kH);
        const float px_close = bench::radius_pixels(close, radius, float(fc.median_depth), kH);
        CAPTURE(px_standard);
        CAPTURE(px_close);
        CHECK(px_close >= 2.5f * px_standard);
        // Nothing it sees is cut by the near plane: the nearest hit lies beyond it.
        CHECK(fc.median_depth > close.znear);
    }
}

TEST_CASE("radius in pixels: half the image height at the depth where the radius spans half the view") {
    camera::Camera c;
    c.yfov = 2.0f * std::atan(0.5f);  // half-height at depth d is d / 2
    CHECK(bench::radius_pixels(c, 1.0f, 2.0f, 100) == doctest::Approx(50.0f));
    CHECK(bench::radius_pixels(c, 1.0f, 4.0f, 100) == doctest::Approx(25.0f));
    c.orthographic = true;
    c.ortho_half_height = 2.0f;
    CHECK(bench::radius_pixels(c, 1.0f, 123.0f, 100) == doctest::Approx(25.0f));
}

}  // TEST_SUITE
