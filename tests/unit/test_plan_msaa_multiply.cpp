// test_plan_msaa_multiply.cpp - the frame plan (plugin/plan.h) for the
// MSAA inputs and MULTIPLY output mode, without GL: which passes read the
// host's multisampled textures (variant MULTISAMPLE, the sample index), which
// pass blends into the output, and that strength off in multiply mode runs
// nothing.
#include "plan.h"
#include "plan_test_util.h"
#include "settings.h"

#include <doctest/doctest.h>

#include <string>

using namespace ssao_impl;
using Source = TexRef::Source;

namespace {

ssao_settings resolved(ssao_method method, ssao_resolution res, ssao_blur blur, float strength = 0.0f) {
    return plan_test::resolve(plan_test::request(method, res, blur, strength));
}

// The host's textures 1 and 2 in, its texture 3 out (the depth format left unknown).
AnalysedInputs host_output_inputs() {
    AnalysedInputs in = plan_test::viewport_inputs(0, 0, 64, 48, 3, DepthFormat{});
    in.depth_texture = 1;
    in.normal_texture = 2;
    return in;
}

bool reads_host(const Pass& p) {
    for (const TexRef& r : p.inputs)
        if (r.source == Source::depth || r.source == Source::normal) return true;
    return false;
}

}  // namespace

TEST_CASE("MSAA inputs: only the passes that read the host's textures are MULTISAMPLE, with the sample index") {
    for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER})
        for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4}) {
            CAPTURE(res);
            CAPTURE(blur);
            AnalysedInputs in = host_output_inputs();
            in.multisample = true;
            in.samples = 4;
            in.sample_index = 3;
            const FramePlan plan = plan_frame(resolved(SSAO_METHOD_VISIBILITY, res, blur), in);
            REQUIRE(plan.pass_count >= 2);
            CHECK(plan.passes[0].kind == PassKind::grid);  // the grid pass, even at full resolution
            for (int i = 0; i < plan.pass_count; ++i) {
                const Pass& p = plan.passes[i];
                CAPTURE(i);
                const bool ms = (p.variant & variant::multisample) != 0;
                CHECK(ms == reads_host(p));
                if (ms) CHECK(p.sample_index == 3);
                CHECK(!p.multiply);
            }
        }
}

TEST_CASE("MULTIPLY: exactly the pass that writes the output blends, whatever the pass sequence") {
    for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY})
        for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF})
            for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN}) {
                CAPTURE(method);
                CAPTURE(res);
                CAPTURE(blur);
                AnalysedInputs in = host_output_inputs();
                in.multiply_output = true;
                const FramePlan plan = plan_frame(resolved(method, res, blur), in);
                int blending = 0;
                for (int i = 0; i < plan.pass_count; ++i) {
                    const Pass& p = plan.passes[i];
                    CHECK(p.multiply == (p.target.source == Source::output));
                    blending += p.multiply;
                }
                CHECK(blending == 1);
                CHECK(plan.passes[plan.pass_count - 1].multiply);
                // Overwrite mode: the same passes, none blending.
                in.multiply_output = false;
                const FramePlan over = plan_frame(resolved(method, res, blur), in);
                CHECK(over.pass_count == plan.pass_count);
                for (int i = 0; i < over.pass_count; ++i) CHECK(!over.passes[i].multiply);
            }
}

TEST_CASE("MULTIPLY with strength off runs no pass (multiplying by 1), overwrite clears to 1") {
    AnalysedInputs in = host_output_inputs();
    in.multiply_output = true;
    const FramePlan plan =
        plan_frame(resolved(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_HALF, SSAO_BLUR_NONE, SSAO_STRENGTH_OFF), in);
    CHECK(plan.pass_count == 0);
    CHECK(plan.passes_run() == 0u);
    CHECK(plan.intermediate_count == 0);
    CHECK(!plan.owned_output);
    in.multiply_output = false;
    const FramePlan over =
        plan_frame(resolved(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_HALF, SSAO_BLUR_NONE, SSAO_STRENGTH_OFF), in);
    CHECK(over.passes_run() == static_cast<uint32_t>(SSAO_PASS_CLEAR));
}
