// The exact depth-only limit (reference/depth_limit.cpp) against an independent
// brute-force march of the same definition (limit_oracle.h), on the bundled
// scenes at a small size with the tools' camera and radius.
//
// Both march the same directions per pixel (the limit's own cosine-weighted
// sets, rebuilt here from the documented seeds), so a per-pixel difference is
// the marchers' disagreement, not sampling noise. The brute force misses only
// blocked intervals shorter than R / steps; a definition that blocks such
// slivers (a lone tangent plane extrapolated over a grazing texel's footprint)
// makes the exact limit darker than any stepped march, and this test fails.
#include "camera.h"
#include "depth_limit.h"
#include "limit_oracle.h"
#include "metrics.h"
#include "raytracer.h"
#include "row_pool.h"
#include "sampling.h"
#include "scene.h"

#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace {

constexpr int kWidth = 96, kHeight = 54;
constexpr int kDirections = 128;   // per pixel, both marchers
constexpr int kSteps = 512;        // the oracle's march points per direction
constexpr int kTruthSamples = 256; // V_R rays per pixel
constexpr uint32_t kSeed = 1;

// The directions depth_limit::Layer::visibility marches at a pixel: kReplicas
// Hammersley sets, each rotated by a hash of the pixel seed, around the normal.
std::vector<glm::dvec3> limit_directions(const glm::dvec3& n, uint32_t pixel_seed) {
    glm::dvec3 tx, ty;
    sampling::basis(n, tx, ty);
    const int per = kDirections / depth_limit::kReplicas;
    std::vector<glm::dvec3> out;
    for (int r = 0; r < depth_limit::kReplicas; ++r) {
        const sampling::Shift shift = sampling::shift_from(sampling::hash32(pixel_seed + uint32_t(r) * 0x9E3779B1u));
        for (int i = 0; i < per; ++i) {
            const glm::dvec3 c = sampling::cosine_direction(i, per, shift);
            out.push_back(glm::normalize(tx * c.x + ty * c.y + n * c.z));
        }
    }
    return out;
}

struct Compared {
    metrics::Stats limit_all, limit_sil, oracle_all, oracle_sil;  // each against V_R
    metrics::Stats diff_all, diff_sil;                             // limit against the oracle, per pixel
};

Compared compare(const std::string& path) {
    scene::Scene sc;
    std::string error;
    REQUIRE_MESSAGE(scene::load(path, sc, error), error);
    const camera::Camera cam = camera::choose(sc, float(kWidth) / float(kHeight));
    const auto r = scene::ao_radius(sc);
    REQUIRE(r.has_value());
    const double radius = r->radius, thickness = depth_limit::kDefaultThicknessOfR * radius;

    raytrace::Tracer tracer(sc.mesh);
    REQUIRE(tracer.ok());
    raytrace::RenderOptions ro;
    ro.width = kWidth;
    ro.height = kHeight;
    ro.radius = float(radius);
    ro.samples = kTruthSamples;
    raytrace::Image img;
    REQUIRE_MESSAGE(tracer.render(cam, ro, img, error), error);

    depth_limit::Options lo;
    lo.radius = radius;
    lo.thickness = thickness;
    lo.directions = kDirections;
    lo.seed = kSeed;
    depth_limit::Image limit;
    REQUIRE_MESSAGE(depth_limit::compute(cam, img, lo, limit, error), error);

    const limit_oracle::DepthLayer layer(cam, img);
    limit_oracle::Options oo;
    oo.radius = radius;
    oo.thickness = thickness;
    oo.steps = kSteps;
    std::vector<float> oracle(size_t(kWidth) * kHeight, 1.0f);
    row_pool::run(kHeight, 0, false, "marched", [&](int y) {
        for (int x = 0; x < kWidth; ++x) {
            if (!layer.geometry(x, y)) continue;
            const auto dirs = limit_directions(layer.normal(x, y), depth_limit::pixel_seed(kSeed, x, y, kWidth));
            oracle[size_t(y) * kWidth + size_t(x)] = float(layer.visibility(x, y, dirs, oo));
        }
    });

    auto stats = [&](const std::vector<float>& test, const std::vector<float>& ref, std::vector<metrics::Stats>& out) {
        metrics::Inputs in;
        in.width = kWidth;
        in.height = kHeight;
        in.test = &test;
        in.reference = &ref;
        in.sky = &img.mask;
        in.depth = &img.depth;
        in.band = 2;  // the silhouette band: within 2 px of a depth discontinuity
        std::string err;
        REQUIRE_MESSAGE(metrics::compute(in, out, err), err);
        REQUIRE(out.size() == 4);
        REQUIRE(out[2].pixels > 100);
    };
    std::vector<metrics::Stats> s;
    Compared c;
    stats(limit.ao, img.ao, s);
    c.limit_all = s[0];
    c.limit_sil = s[2];
    stats(oracle, img.ao, s);
    c.oracle_all = s[0];
    c.oracle_sil = s[2];
    stats(limit.ao, oracle, s);
    c.diff_all = s[0];
    c.diff_sil = s[2];
    return c;
}

}  // namespace

TEST_SUITE("limit_oracle") {

TEST_CASE("the exact limit agrees with a brute-force march of its definition on every bundled scene") {
    for (const char* rel : {"models/spot-on-ground.glb", "models/teapot-on-ground.glb", "scenes/corner.gltf"}) {
        const std::string path = std::string(SSAO_TEST_ASSETS_DIR) + "/" + rel;
        CAPTURE(path);
        const Compared c = compare(path);
        MESSAGE(std::filesystem::path(path).filename().string()
                << " " << kWidth << "x" << kHeight << ", against V_R: limit PSNR " << c.limit_all.psnr
                << " dB (silhouette RMSE " << c.limit_sil.rmse << ", bias " << c.limit_sil.mean_error
                << "), oracle PSNR " << c.oracle_all.psnr << " dB (silhouette RMSE " << c.oracle_sil.rmse
                << ", bias " << c.oracle_sil.mean_error << "); limit - oracle per pixel: RMSE " << c.diff_all.rmse
                << " (silhouette " << c.diff_sil.rmse << "), mean " << c.diff_all.mean_error << ", largest "
                << c.diff_all.max_abs_error);
        // The bounds, against V_R.
        CHECK(std::fabs(c.limit_all.psnr - c.oracle_all.psnr) <= 0.3);
        CHECK(std::fabs(c.limit_sil.rmse - c.oracle_sil.rmse) <= 0.01);
        // Per pixel, on the same directions: only slivers shorter than R / 512 may differ.
        CHECK(c.diff_all.rmse <= 0.005);
        CHECK(c.diff_sil.rmse <= 0.01);
        CHECK(std::fabs(c.diff_all.mean_error) <= 0.001);
    }
}

}  // TEST_SUITE
