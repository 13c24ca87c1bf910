// test_plan_fade.cpp - fade, radius in pixels and the frame index in the frame plan (no GL):
// the sampling pass gets the FADE, RADIUS_PIXELS and FRAME_NOISE variant bits
// only when asked for (fade_end > 0, radius_pixels > 0, frame_index != 0),
// no other pass gets the first two, and no pass is added, so a frame without
// them runs exactly today's programs; a nonzero frame index also gives every
// other pass that maps grid texels to their picked pixels (grid, blurs,
// upsample) FRAME_NOISE, whose picks swap corners every other frame, and the
// upsample (below full resolution) UPSAMPLE_PLANE_FIT; STEP_TEXELS and UNORM_DEPTH
// follow their settings and inputs; and frame_noise_offsets walks the R2
// sequence.
#include "kernel.h"
#include "pass_table.h"
#include "plan.h"
#include "plan_test_util.h"
#include "settings.h"

#include <doctest/doctest.h>

#include <cmath>
#include <string>

using namespace ssao_impl;

namespace {

constexpr uint32_t kFeatureBits = variant::fade | variant::radius_pixels | variant::frame_noise;

ssao_settings resolved(float fade_start, float fade_end, float radius_pixels, ssao_resolution res) {
    ssao_settings in = plan_test::request(SSAO_METHOD_DEFAULT, res, SSAO_BLUR_DEFAULT);
    in.fade_start = fade_start;
    in.fade_end = fade_end;
    in.radius_pixels = radius_pixels;
    return plan_test::resolve(in);
}

AnalysedInputs inputs(uint32_t frame_index) {
    AnalysedInputs in = plan_test::viewport_inputs(0, 0, 64, 48);
    in.frame_index = frame_index;
    return in;
}

// The feature bits of the plan's passes: the sampling pass's, and those of all others.
struct Bits {
    uint32_t ao = 0, others = 0;
    int passes = 0;
};
Bits bits_of(const FramePlan& p) {
    Bits b;
    b.passes = p.pass_count;
    for (int i = 0; i < p.pass_count; ++i)
        (pass_info(p.passes[i].kind).bit == SSAO_PASS_OCCLUSION ? b.ao : b.others) |= p.passes[i].variant & kFeatureBits;
    return b;
}

}  // namespace

TEST_CASE("plan: fade, radius in pixels and frame noise are sampling-pass variants, set only when asked for") {
    for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER}) {
        CAPTURE(res);
        const Bits off = bits_of(plan_frame(resolved(0, 0, 0, res), inputs(0)));
        CHECK(off.ao == 0u);
        CHECK(off.others == 0u);
        const Bits fade = bits_of(plan_frame(resolved(10, 20, 0, res), inputs(0)));
        CHECK(fade.ao == variant::fade);
        const Bits from_camera = bits_of(plan_frame(resolved(0, 20, 0, res), inputs(0)));
        CHECK(from_camera.ao == variant::fade);
        const Bits px = bits_of(plan_frame(resolved(0, 0, 24, res), inputs(0)));
        CHECK(px.ao == variant::radius_pixels);
        const Bits noise = bits_of(plan_frame(resolved(0, 0, 0, res), inputs(7)));
        CHECK(noise.ao == variant::frame_noise);
        const Bits all = bits_of(plan_frame(resolved(1, 2, 3, res), inputs(0xffffffffu)));
        CHECK(all.ao == kFeatureBits);
        for (const Bits& b : {fade, from_camera, px}) CHECK(b.others == 0u);  // no other pass compiles them
        // A moving frame index swaps the grid's picks: the other passes that
        // map grid texels to pixels must agree with the sampling pass on them.
        for (const Bits& b : {noise, all}) CHECK(b.others == variant::frame_noise);
        for (const Bits& b : {fade, from_camera, px, noise, all}) CHECK(b.passes == off.passes);  // none is added
        for (uint32_t frame : {0u, 7u}) {
            ssao_settings blurred = resolved(0, 0, 0, res);
            blurred.blur = SSAO_BLUR_DEPTH_AWARE;
            const FramePlan p = plan_frame(blurred, inputs(frame));
            for (int i = 0; i < p.pass_count; ++i) {
                const PassKind k = p.passes[i].kind;
                const bool maps_grid = k == PassKind::grid || k == PassKind::visibility || k == PassKind::kernel ||
                                       k == PassKind::blur_x || k == PassKind::blur_y || k == PassKind::upsample;
                CAPTURE(frame);
                CAPTURE(i);
                CHECK(((p.passes[i].variant & variant::frame_noise) != 0) == (maps_grid && frame != 0));
            }
        }
    }
    // Strength 0 samples nothing: no sampling pass, no variant.
    ssao_settings zero = resolved(1, 2, 3, SSAO_RESOLUTION_FULL);
    zero.strength = SSAO_STRENGTH_OFF;
    const Bits cleared = bits_of(plan_frame(zero, inputs(5)));
    CHECK(cleared.ao == 0u);
    CHECK(cleared.others == 0u);
}

TEST_CASE("frame noise offsets: frame 0 is no offset, frame n is fract(n / g, n / g^2) of the R2 sequence, evenly spread") {
    CHECK(frame_noise_offsets(0) == glm::dvec2(0.0));
    const double a1 = 0.7548776662466927, a2 = 0.5698402909980532;  // 1/g, 1/g^2, g = 1.3247179572...
    for (uint32_t n : {1u, 2u, 3u, 100u, 65536u}) {
        CAPTURE(n);
        const glm::dvec2 o = frame_noise_offsets(n);
        // 32-bit fixed point: off by at most n * 2^-33 from the real sequence.
        const double tol = (n + 1.0) * std::ldexp(1.0, -32);
        CHECK(std::abs(o.x - (n * a1 - std::floor(n * a1))) <= tol);
        CHECK(std::abs(o.y - (n * a2 - std::floor(n * a2))) <= tol);
    }
    // Any 16 consecutive frames (also across the uint32 wrap) put 2..6 of
    // their 16 offsets in each quarter of [0,1), per coordinate (ideal: 4).
    for (uint32_t first : {1u, 17u, 12345u, 4294967290u}) {
        CAPTURE(first);
        int x[4] = {0, 0, 0, 0}, y[4] = {0, 0, 0, 0};
        for (uint32_t k = 0; k < 16; ++k) {
            const glm::dvec2 o = frame_noise_offsets(first + k);
            REQUIRE(o.x >= 0.0);
            REQUIRE(o.x < 1.0);
            REQUIRE(o.y >= 0.0);
            REQUIRE(o.y < 1.0);
            ++x[int(o.x * 4)];
            ++y[int(o.y * 4)];
        }
        for (int q = 0; q < 4; ++q) {
            CHECK(x[q] >= 2);
            CHECK(x[q] <= 6);
            CHECK(y[q] >= 2);
            CHECK(y[q] <= 6);
        }
    }
}

TEST_CASE("plan: max_step_texels > 0 makes STEP_TEXELS a variant of the visibility pass only, 0 (off) never does") {
    for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY})
        for (float texels : {0.0f, 4.0f}) {
            CAPTURE(method);
            CAPTURE(texels);
            ssao_settings r = plan_test::request(method, SSAO_RESOLUTION_HALF, SSAO_BLUR_DEFAULT);
            r.max_step_texels = texels;
            const ssao_settings s = plan_test::resolve(r);
            const FramePlan p = plan_frame(s, plan_test::viewport_inputs(0, 0, 64, 48, 0));
            for (int i = 0; i < p.pass_count; ++i) {
                const bool ao = pass_info(p.passes[i].kind).bit == SSAO_PASS_OCCLUSION;
                CHECK(((p.passes[i].variant & variant::step_texels) != 0) ==
                      (ao && method == SSAO_METHOD_VISIBILITY && texels > 0.0f));
            }
        }
}

TEST_CASE("plan: a unorm depth (D16, D24) makes UNORM_DEPTH a sampling-pass variant, a float depth never does") {
    for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY})
        for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER}) {
            CAPTURE(method);
            CAPTURE(res);
            const ssao_settings s = plan_test::resolve(plan_test::request(method, res, SSAO_BLUR_DEFAULT));
            for (const int bits : {16, 24, 32}) {
                const bool is_float = bits == 32;  // D16, D24 unorm; D32F
                CAPTURE(bits);
                const FramePlan p =
                    plan_frame(s, plan_test::viewport_inputs(0, 0, 64, 48, 0, plan_test::depth_format(bits, is_float)));
                int sampling = 0;
                for (int i = 0; i < p.pass_count; ++i) {
                    const bool ao = pass_info(p.passes[i].kind).bit == SSAO_PASS_OCCLUSION;
                    sampling += ao;
                    CHECK(((p.passes[i].variant & variant::unorm_depth) != 0) == (ao && !is_float));
                }
                CHECK(sampling == 1);
            }
        }
}

TEST_CASE("plan: a moving frame index gives the upsample its plane fit (UPSAMPLE_PLANE_FIT), and no other pass, RAW_AO keeps the nearest texel") {
    for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY})
        for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER})
            for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE})
                for (uint32_t frame : {0u, 1u, 0xffffffffu}) {
                    CAPTURE(method);
                    CAPTURE(res);
                    CAPTURE(blur);
                    CAPTURE(frame);
                    const FramePlan p = plan_frame(plan_test::resolve(plan_test::request(method, res, blur)), inputs(frame));
                    int upsamples = 0;
                    for (int i = 0; i < p.pass_count; ++i) {
                        const bool fit = (p.passes[i].variant & variant::upsample_plane_fit) != 0;
                        if (p.passes[i].kind != PassKind::upsample) {
                            CHECK_FALSE(fit);
                            continue;
                        }
                        ++upsamples;
                        CHECK(fit == (frame != 0));
                    }
                    CHECK(upsamples == (res == SSAO_RESOLUTION_FULL ? 0 : 1));
                    // The raw view shows the grid's own texels, never a fit of them.
                    const FramePlan raw = plan_frame(
                        plan_test::resolve(plan_test::request(method, res, blur, 0.0f, SSAO_DEBUG_VIEW_RAW_AO)),
                        inputs(frame));
                    for (int i = 0; i < raw.pass_count; ++i)
                        if (raw.passes[i].kind == PassKind::upsample) {
                            CHECK((raw.passes[i].variant & variant::upsample_nearest) != 0);
                            CHECK((raw.passes[i].variant & variant::upsample_plane_fit) == 0);
                        }
                }
}
