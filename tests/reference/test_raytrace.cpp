// The ray tracer against closed forms of V_R (listed in docs/reference.md, "Ground truth:
// the ray-traced reference", Tests),
// within 4 standard errors (plus a small allowance for finite geometry).
#include "geometry.h"
#include "raytracer.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

namespace {

const double kPi = 3.14159265358979323846;
const int kRays = 16384;
const float kInf = std::numeric_limits<float>::infinity();

void check_close(const raytrace::Estimate& e, double expected, double slack) {
    INFO("estimate " << e.visibility << " +- " << e.std_error << ", expected " << expected);
    CHECK(std::fabs(e.visibility - expected) <= 4.0 * e.std_error + slack);
    // The stratified (Hammersley) samples do far better than the Bernoulli bound:
    // measured errors are below 5e-4 at 16384 rays. Catch regressions hiding in 4 sigma.
    CHECK(std::fabs(e.visibility - expected) <= 3e-3);
}

}  // namespace

TEST_SUITE("raytrace") {

TEST_CASE("plane: V = 1") {
    scene::Mesh m;
    testgeo::add_floor(m, 10.0f);
    raytrace::Tracer t(m);
    REQUIRE(t.ok());
    for (float R : {0.1f, 1.0f, 100.0f, kInf}) {
        const auto e = t.ao_at({0.3f, 0.0f, -0.2f}, {0, 1, 0}, R, 4096, 7);
        CHECK(e.visibility == 1.0);
        CHECK(e.std_error == 0.0);
        CHECK(e.rays == 4096);
    }
}

TEST_CASE("infinite perpendicular wall at distance d") {
    const float R = 1.0f;
    for (float d : {0.05f, 0.3f, 0.6f, 0.95f, 1.5f}) {
        scene::Mesh m;
        testgeo::add_floor(m, 50.0f);
        testgeo::add_quad(m, {d, -1, 50}, {d, -1, -50}, {d, 50, -50}, {d, 50, 50});  // x = d, facing -x
        raytrace::Tracer t(m);
        REQUIRE(t.ok());
        const double a = std::min(double(d) / R, 1.0);
        const double expected = 1.0 - (std::acos(a) - a * std::sqrt(1.0 - a * a)) / kPi;
        INFO("d = " << d);
        check_close(t.ao_at({0, 0, 0}, {0, 1, 0}, R, kRays, 3), expected, 2e-3);
    }
}

TEST_CASE("wedge of interior angle alpha, R infinite") {
    for (double deg : {30.0, 60.0, 90.0, 120.0, 150.0}) {
        const double al = deg * kPi / 180.0;
        const float L = 100.0f;
        scene::Mesh m;
        testgeo::add_floor(m, L);
        const glm::vec3 dir(float(std::cos(al)), float(std::sin(al)), 0.0f);
        testgeo::add_quad(m, {0, 0, -L}, {0, 0, L}, dir * L + glm::vec3(0, 0, L), dir * L + glm::vec3(0, 0, -L));
        raytrace::Tracer t(m);
        REQUIRE(t.ok());
        INFO("alpha = " << deg << " degrees");
        check_close(t.ao_at({0.01f, 0, 0}, {0, 1, 0}, kInf, kRays, 5), (1.0 - std::cos(al)) / 2.0, 3e-3);
    }
}

TEST_CASE("sphere resting on the floor, R infinite") {
    const float r = 1.0f;
    scene::Mesh m;
    testgeo::add_floor(m, 200.0f);
    testgeo::add_sphere(m, {0, r, 0}, r, 256, 128);
    raytrace::Tracer t(m);
    REQUIRE(t.ok());
    for (float x : {1.0f, 1.5f, 2.0f, 3.0f, 5.0f}) {
        const double expected = 1.0 - double(r * r * r) / std::pow(double(x * x + r * r), 1.5);
        INFO("x = " << x);
        check_close(t.ao_at({x, 0, 0}, {0, 1, 0}, kInf, kRays, 11), expected, 2e-3);
        // Any direction around the contact point gives the same value.
        check_close(t.ao_at({0, 0, -x}, {0, 1, 0}, kInf, kRays, 12), expected, 2e-3);
    }
}

TEST_CASE("radius limits occlusion: a far wall does not occlude") {
    scene::Mesh m;
    testgeo::add_floor(m, 50.0f);
    testgeo::add_quad(m, {2, -1, 50}, {2, -1, -50}, {2, 50, -50}, {2, 50, 50});
    raytrace::Tracer t(m);
    CHECK(t.ao_at({0, 0, 0}, {0, 1, 0}, 1.9f, 4096, 1).visibility == 1.0);
    CHECK(t.ao_at({0, 0, 0}, {0, 1, 0}, 10.0f, 4096, 1).visibility < 0.9);
}

TEST_CASE("same seed, same result, another seed, within the noise") {
    scene::Mesh m;
    testgeo::add_floor(m, 50.0f);
    testgeo::add_quad(m, {0.4f, -1, 50}, {0.4f, -1, -50}, {0.4f, 50, -50}, {0.4f, 50, 50});
    raytrace::Tracer t(m);
    const auto a = t.ao_at({0, 0, 0}, {0, 1, 0}, 1.0f, 4096, 1);
    const auto b = t.ao_at({0, 0, 0}, {0, 1, 0}, 1.0f, 4096, 1);
    const auto c = t.ao_at({0, 0, 0}, {0, 1, 0}, 1.0f, 4096, 2);
    CHECK(a.visibility == b.visibility);
    CHECK(std::fabs(a.visibility - c.visibility) <= 4.0 * std::hypot(a.std_error, c.std_error));
}

// Looking straight down at the floor from height 5: every pixel's view depth is
// 5 whatever the projection, the view normal is +z and AO is 1. The floor covers
// only z < 0, which is the top half of the picture (camera up = -z).
TEST_CASE("image: primary rays match the projection (perspective, infinite, reverse-Z, orthographic)") {
    scene::Mesh m;
    testgeo::add_quad(m, {-50, 0, 0}, {50, 0, 0}, {50, 0, -50}, {-50, 0, -50});
    raytrace::Tracer t(m);
    REQUIRE(t.ok());
    struct Variant {
        const char* name;
        bool ortho, reverse, zero_to_one;
        float zfar;
    };
    const Variant variants[] = {
        {"perspective", false, false, false, 100.0f},
        {"perspective infinite", false, false, false, kInf},
        {"perspective [0,1]", false, false, true, 100.0f},
        {"reverse-Z", false, true, true, 100.0f},
        {"reverse-Z infinite", false, true, true, kInf},
        {"orthographic", true, false, false, 100.0f},
        {"orthographic reverse-Z", true, true, true, 100.0f},
    };
    for (const auto& v : variants) {
        camera::Camera c;
        c.eye = {0, 5, 0};
        c.target = {0, 0, 0};
        c.up = {0, 0, -1};
        c.yfov = 0.8f;
        c.znear = 0.5f;
        c.zfar = v.zfar;
        c.orthographic = v.ortho;
        c.ortho_half_height = 2.0f;
        c.reverse_z = v.reverse;
        c.zero_to_one = v.zero_to_one;
        raytrace::RenderOptions o;
        o.width = 9;
        o.height = 6;
        o.samples = 64;
        o.radius = 0.5f;
        raytrace::Image img;
        std::string err;
        INFO(v.name);
        REQUIRE(t.render(c, o, img, err));
        REQUIRE(img.ao.size() == 54u);
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 9; ++x) {
                const size_t i = size_t(y) * 9 + size_t(x);
                INFO("pixel " << x << "," << y);
                CHECK(img.mask[i] == (y < 3 ? 1.0f : 0.0f));
                if (y < 3) {
                    CHECK(img.depth[i] == doctest::Approx(5.0).epsilon(1e-4));
                    CHECK(img.normal[i * 3 + 2] == doctest::Approx(1.0).epsilon(1e-5));
                    CHECK(img.ao[i] == 1.0f);
                } else {
                    CHECK(img.ao[i] == 1.0f);
                    CHECK(std::isinf(img.depth[i]));
                }
            }
    }
}

TEST_CASE("image: the far plane clips like the rasteriser") {
    scene::Mesh m;
    testgeo::add_floor(m, 50.0f);
    raytrace::Tracer t(m);
    camera::Camera c;
    c.eye = {0, 5, 0};
    c.target = {0, 0, 0};
    c.up = {0, 0, -1};
    c.znear = 0.5f;
    c.zfar = 4.9f;  // the floor lies beyond
    raytrace::RenderOptions o;
    o.width = 4;
    o.height = 4;
    o.samples = 8;
    raytrace::Image img;
    std::string err;
    REQUIRE(t.render(c, o, img, err));
    for (float v : img.mask) CHECK(v == 0.0f);
}

TEST_CASE("image: a corner darkens towards the wall, with standard errors") {
    scene::Mesh m;
    testgeo::add_floor(m, 50.0f);
    testgeo::add_quad(m, {0, -1, 50}, {0, -1, -50}, {0, 50, -50}, {0, 50, 50});  // wall x = 0 facing -x
    raytrace::Tracer t(m);
    camera::Camera c;
    c.eye = {-3, 4, 0};
    c.target = {-1, 0, 0};
    c.up = {1, 0, 0};
    c.znear = 0.1f;
    c.zfar = 100.0f;
    raytrace::RenderOptions o;
    o.width = 16;
    o.height = 8;
    o.samples = 1024;
    o.radius = 1.0f;
    o.threads = 2;
    raytrace::Image img;
    std::string err;
    REQUIRE(t.render(c, o, img, err));
    double se_max = 0.0;
    for (size_t i = 0; i < img.ao.size(); ++i) {
        REQUIRE(img.mask[i] == 1.0f);
        CHECK(img.ao[i] >= 0.0f);
        CHECK(img.ao[i] <= 1.0f);
        se_max = std::max(se_max, double(img.std_error[i]));
    }
    CHECK(se_max <= 0.5 / std::sqrt(1023.0) + 1e-6);
    CHECK(se_max > 0.0);
    CHECK(img.rays > uint64_t(16 * 8 * 1024));
    // Same seed, same image, whatever the thread count.
    o.threads = 1;
    raytrace::Image one;
    REQUIRE(t.render(c, o, one, err));
    CHECK(one.ao == img.ao);
}

TEST_CASE("render rejects bad options") {
    scene::Mesh m;
    testgeo::add_floor(m, 1.0f);
    raytrace::Tracer t(m);
    camera::Camera c;
    raytrace::Image img;
    std::string err;
    raytrace::RenderOptions o;
    o.width = 0;
    o.height = 4;
    CHECK_FALSE(t.render(c, o, img, err));
    CHECK_FALSE(err.empty());
    o.width = 4;
    o.radius = -1.0f;
    CHECK_FALSE(t.render(c, o, img, err));
}

}  // TEST_SUITE
