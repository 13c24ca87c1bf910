// Noise for TAA hosts (inputs.frame_index, variant FRAME_NOISE): a fixed
// index is bit-stable, index 0 is the fixed pattern of every earlier version
// bit for bit, and the mean of 16 consecutive indices lands closer to the
// converged result than any single frame by about the factor a TAA host
// expects from averaging 16 frames (docs/api.md, "Noise for TAA hosts").
#include <doctest/doctest.h>

#include "hc_util.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

using analytic::GBuffer;
using analytic::Scene;

namespace {

// The crease scene's G-buffer uploaded once; execute with any frame index
// (and any inputs struct size) as often as needed.
struct Frames {
    testgl::Fixture& fx;
    GBuffer g;
    ssao_inputs in{};

    Frames(testgl::Fixture& f, int w, int h) : fx(f) {
        const glm::dmat4 proj = analytic::perspective(hc::kFov, double(w) / h, 0.1, 100.0);
        g = hc::crease_gbuffer(proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, w, h);
        const GLuint dt = fx.make_depth(GL_DEPTH_COMPONENT32F, w, h, g.depth);
        const GLuint nt = fx.make_normals(GL_RGBA16F, w, h, g.normal);
        in = fx.inputs(dt, nt, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    }

    std::vector<float> run(uint32_t frame_index, uint32_t inputs_size = sizeof(ssao_inputs)) {
        ssao_inputs i = in;
        i.size = inputs_size;
        i.frame_index = frame_index;
        ssao_output out{};
        out.size = sizeof out;
        const ssao_status st = fx.api().execute(fx.ctx(), &i, &out);
        REQUIRE(st == SSAO_OK);
        return fx.read_red(out.texture, g.width, g.height);
    }
};

double rmse(const std::vector<float>& a, const std::vector<double>& ref) {
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) sum += (a[i] - ref[i]) * (a[i] - ref[i]);
    return std::sqrt(sum / double(a.size()));
}

bool identical(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](float x, float y) {
               return std::memcmp(&x, &y, sizeof x) == 0;
           });
}

}  // namespace

TEST_CASE("frame noise: a fixed frame index gives bit-identical AO twice, index 0 gives the 1.1 output bit for bit") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    Frames fr(fx, 64, 48);
    for (ssao_rotation rot : {SSAO_ROTATION_GRADIENT_NOISE, SSAO_ROTATION_NOISE_4X4, SSAO_ROTATION_HASH, SSAO_ROTATION_NONE}) {
        CAPTURE(rot);
        fx.settings(hc::make(8, SSAO_BLUR_NONE, rot, 1.0f, method));
        // A 1.1-sized inputs struct has no frame_index: the output every
        // earlier version gave. Index 0 in a 1.2 struct must be it exactly.
        const std::vector<float> old = fr.run(0, SSAO_INPUTS_SIZE_1_1);
        CHECK(identical(fr.run(0), old));
        for (uint32_t n : {1u, 7u, 4294967295u}) {
            CAPTURE(n);
            const std::vector<float> a = fr.run(n), b = fr.run(n);
            CHECK(identical(a, b));
            hc::check_unit_finite(a, "frame noise");
            // It does move the noise (and only the noise: the mean stays).
            CHECK_FALSE(identical(a, old));
            CHECK(std::abs(hc::mean(a) - hc::mean(old)) < 0.02);
        }
        // Back to index 0: the fixed pattern again (no state carried over).
        CHECK(identical(fr.run(0), old));
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("frame noise: the mean of 16 consecutive frame indices is >= 3.5x closer (RMSE) to the converged AO than any single frame (sqrt(16) = 4 expected)") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const int W = 64, H = 48;
    Frames fr(fx, W, H);
    // Few samples, no blur: the noise a TAA host averages. The converged AO
    // is what averaging tends to: the mean over 256 frame indices of the same
    // settings (the estimator's own limit). A run with many samples and steps
    // is reported beside it: it differs from that limit by the estimator's
    // bias at few samples (the kernel's fixed radial distribution, the march's
    // fixed step count), which no averaging of rotations removes.
    ssao_settings many = hc::make(64, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method);
    many.step_count = 16;
    fx.settings(many);
    const std::vector<float> many_run = fr.run(0);
    const std::vector<double> many_samples(many_run.begin(), many_run.end());
    ssao_settings s = hc::make(8, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 1.0f, method);
    s.step_count = 4;
    for (ssao_rotation rot : {SSAO_ROTATION_HASH, SSAO_ROTATION_NOISE_4X4}) {
        CAPTURE(rot);
        s.rotation = rot;
        fx.settings(s);
        const size_t n = size_t(W) * H;
        std::vector<double> converged(n, 0.0);
        const int kConverged = 256;
        for (int k = 0; k < kConverged; ++k) {
            const std::vector<float> a = fr.run(uint32_t(1000 + k));
            for (size_t i = 0; i < n; ++i) converged[i] += a[i] / kConverged;
        }
        for (uint32_t first : {1u, 4000000000u}) {
            CAPTURE(first);
            std::vector<double> sum(n, 0.0);
            double best_single = 1e9, worst_single = 0;
            for (uint32_t k = 0; k < 16; ++k) {
                const std::vector<float> a = fr.run(first + k);
                best_single = std::min(best_single, rmse(a, converged));
                worst_single = std::max(worst_single, rmse(a, converged));
                for (size_t i = 0; i < n; ++i) sum[i] += a[i];
            }
            std::vector<float> mean16(n);
            for (size_t i = 0; i < n; ++i) mean16[i] = float(sum[i] / 16.0);
            const double avg = rmse(mean16, converged);
            MESSAGE("method " << method << ", rotation " << rot << ", frames " << first << "..+15: single-frame RMSE "
                              << best_single << " .. " << worst_single << ", mean of 16: " << avg << ", factor "
                              << best_single / avg);
            MESSAGE("  against 64 samples x 16 steps: single frame " << rmse(fr.run(first), many_samples)
                                                               << ", mean of 16 " << rmse(mean16, many_samples));
            CHECK(best_single / avg >= 3.5);  // measured 4.0-4.7 (visibility), 7.1-8.2 (kernel)
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("frame noise at half resolution: the mean over frame indices keeps no pattern of the picked pixels (the upsample's plane fit, the picks swapping corners) and reads closer to full resolution's") {
    // Averaged over frame indices the grid's noise goes, and what the
    // upsample does with the grid's values shows: the picked pixels'
    // checkerboard puts a pixel's four taps on a skewed quad, so a weighted
    // mean reads a soft gradient (the floor's AO towards the wall and the
    // boxes) a little off the pixel, differently at each position in the
    // 4x4 pixels of the checkerboard's period: diagonal stripes. With a
    // moving frame index the upsample fits a plane through its taps instead
    // (plan.cpp). The figure: the mean of (half - full resolution) at each of
    // the 16 positions, over pixels whose 5x5 neighbourhood is one face (no
    // edge for the depth test to decide), RMS about their mean.
    testgl::Fixture fx;
    const int W = 128, H = 96;
    Frames fr(fx, W, H);
    const size_t n = size_t(W) * H;
    auto mean_of_frames = [&](ssao_resolution res) {
        ssao_settings s = hc::make(8, SSAO_BLUR_NONE, SSAO_ROTATION_GRADIENT_NOISE, 1.0f, SSAO_METHOD_VISIBILITY);
        s.step_count = 4;
        s.resolution = res;
        fx.settings(s);
        std::vector<double> mean(n, 0.0);
        const int kFrames = 256;
        for (int k = 1; k <= kFrames; ++k) {
            const std::vector<float> a = fr.run(uint32_t(k));
            for (size_t i = 0; i < n; ++i) mean[i] += a[i] / kFrames;
        }
        return mean;
    };
    const std::vector<double> half = mean_of_frames(SSAO_RESOLUTION_HALF), full = mean_of_frames(SSAO_RESOLUTION_FULL);
    const GBuffer& g = fr.g;
    auto one_face = [&](int x, int y) {
        if (x < 2 || y < 2 || x >= W - 2 || y >= H - 2) return false;
        const size_t i = hc::at(x, y, W);
        if (g.sky(x, y)) return false;
        const glm::dvec3 n0(g.normal[i]), X = g.position[i];
        for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
                const size_t j = hc::at(x + dx, y + dy, W);
                if (g.sky(x + dx, y + dy) || glm::length(glm::dvec3(g.normal[j]) - n0) > 1e-6 ||
                    std::abs(glm::dot(n0, g.position[j] - X)) > 1e-6 * (1.0 + glm::length(X)))
                    return false;
            }
        return true;
    };
    double sum[16] = {}, count[16] = {};
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (!one_face(x, y)) continue;
            const size_t i = hc::at(x, y, W);
            sum[(y & 3) * 4 + (x & 3)] += half[i] - full[i];
            count[(y & 3) * 4 + (x & 3)] += 1.0;
        }
    double means[16], overall = 0;
    for (int k = 0; k < 16; ++k) {
        REQUIRE(count[k] > 300);
        means[k] = sum[k] / count[k];
        overall += means[k] / 16.0;
    }
    double pattern = 0;
    for (double m : means) pattern += (m - overall) * (m - overall) / 16.0;
    pattern = std::sqrt(pattern);
    MESSAGE("half - full over 256 frame indices: mean " << overall << ", pattern of the 4x4 positions (RMS) " << pattern);
    // Every other frame the grid picks the other diagonal corner of each
    // block (common.glsl grid_pixel), so the mean sees twice the pixels: its
    // distance to the full-resolution mean, over every geometry pixel.
    double sq = 0;
    int pixels = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            if (g.sky(x, y)) continue;
            const size_t i = hc::at(x, y, W);
            sq += (half[i] - full[i]) * (half[i] - full[i]);
            ++pixels;
        }
    const double rms = std::sqrt(sq / pixels);
    MESSAGE("half - full over 256 frame indices, every geometry pixel: RMS " << rms);
    // Measured 0.0112 with the swap and 0.0123 with the picks fixed (the
    // frame's swap taken out of constants.cpp).
    CHECK(rms <= 0.0117);
    // Measured 0.00027 with the plane fit and the picks swapping corners,
    // 0.00040 with the plane fit and fixed picks, and 0.00069 with the
    // weighted mean and fixed picks (the frame index's variant bit taken out
    // of the plan).
    CHECK(pattern <= 0.00034);
    CHECK(fx.gl_errors().empty());
}
