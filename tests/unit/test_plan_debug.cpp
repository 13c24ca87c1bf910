// test_plan_debug.cpp - the frame plan (plugin/plan.h) of the debug views
// RAW_AO and BLUR_WEIGHTS (settings.debug_view), without GL: RAW_AO is the
// plan of blur NONE, BLUR_WEIGHTS is the plan of the AO with the blurs in
// their BLUR_WEIGHTS variant (a clear when there is no blur), and below full
// resolution both upsample without depth weights. A view that is off sets no
// variant bit of its own (free when off).
#include "pass_table.h"
#include "plan.h"
#include "plan_test_util.h"
#include "settings.h"

#include <doctest/doctest.h>

#include <string>

using namespace ssao_impl;
using Source = TexRef::Source;

namespace {

ssao_settings resolved(ssao_blur blur, ssao_resolution res, ssao_debug_view view, float strength = 0.0f) {
    return plan_test::resolve(plan_test::request(SSAO_METHOD_KERNEL, res, blur, strength, view));
}

AnalysedInputs inputs(int w, int h, uint32_t host_output = 0) { return plan_test::viewport_inputs(3, 2, w, h, host_output); }

// Same passes (kind, program, inputs, target, rectangle, packing, scale,
// direction, depth awareness), variant bits aside.
void check_same_passes(const FramePlan& a, const FramePlan& b) {
    REQUIRE(a.pass_count == b.pass_count);
    CHECK(a.intermediate_count == b.intermediate_count);
    for (int i = 0; i < a.pass_count; ++i) {
        CAPTURE(i);
        const Pass &p = a.passes[i], &q = b.passes[i];
        CHECK(p.kind == q.kind);
        CHECK(program_of(p.kind) == program_of(q.kind));
        for (int u = 0; u < SSAO_UNITS_USED; ++u) CHECK(p.inputs[u] == q.inputs[u]);
        CHECK(p.target == q.target);
        CHECK(p.rect.x == q.rect.x);
        CHECK(p.rect.y == q.rect.y);
        CHECK(p.rect.width == q.rect.width);
        CHECK(p.rect.height == q.rect.height);
        CHECK(p.pack_depth == q.pack_depth);
        CHECK(p.scale == q.scale);
        CHECK(p.direction[0] == q.direction[0]);
        CHECK(p.direction[1] == q.direction[1]);
        CHECK(p.depth_aware == q.depth_aware);
    }
    CHECK(a.owned_output == b.owned_output);
    CHECK(a.output_format == b.output_format);
}

constexpr uint32_t kDebugBits = variant::blur_weights | variant::upsample_nearest;

const ssao_blur kBlurs[] = {SSAO_BLUR_NONE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_DEPTH_AWARE};
const ssao_resolution kResolutions[] = {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER};

}  // namespace

TEST_CASE("plan debug: view NONE sets no debug variant bit in any plan") {
    for (ssao_blur blur : kBlurs)
        for (ssao_resolution res : kResolutions) {
            CAPTURE(blur);
            CAPTURE(res);
            const FramePlan p = plan_frame(resolved(blur, res, SSAO_DEBUG_VIEW_NONE), inputs(67, 41));
            for (int i = 0; i < p.pass_count; ++i) CHECK((p.passes[i].variant & kDebugBits) == 0u);
        }
}

TEST_CASE("plan debug: RAW_AO is the plan of blur NONE, upsampled from the pixel's own grid texel") {
    for (ssao_blur blur : kBlurs)
        for (ssao_resolution res : kResolutions)
            for (uint32_t host : {0u, 9u}) {
                CAPTURE(blur);
                CAPTURE(res);
                CAPTURE(host);
                const AnalysedInputs in = inputs(67, 41, host);
                const FramePlan raw = plan_frame(resolved(blur, res, SSAO_DEBUG_VIEW_RAW_AO), in);
                const FramePlan unblurred = plan_frame(resolved(SSAO_BLUR_NONE, res, SSAO_DEBUG_VIEW_NONE), in);
                check_same_passes(raw, unblurred);
                CHECK((raw.passes_run() & (SSAO_PASS_BLUR_X | SSAO_PASS_BLUR_Y)) == 0u);
                for (int i = 0; i < raw.pass_count; ++i) {
                    const Pass& p = raw.passes[i];
                    CAPTURE(i);
                    // Only the upsample changes: no depth weights.
                    const uint32_t extra = p.kind == PassKind::upsample ? variant::upsample_nearest : 0u;
                    CHECK(p.variant == (unblurred.passes[i].variant | extra));
                }
                // At full resolution the AO pass writes the output: the view is the blur-NONE output.
                if (res == SSAO_RESOLUTION_FULL) {
                    REQUIRE(raw.pass_count == 1);
                    CHECK(raw.passes[0].target.source == Source::output);
                    CHECK(raw.passes[0].variant == 0u);
                }
            }
}

TEST_CASE("plan debug: BLUR_WEIGHTS runs the AO's passes with the blurs in their weights variant") {
    for (ssao_blur blur : kBlurs)
        for (ssao_resolution res : kResolutions) {
            CAPTURE(blur);
            CAPTURE(res);
            const AnalysedInputs in = inputs(67, 41);
            const FramePlan w = plan_frame(resolved(blur, res, SSAO_DEBUG_VIEW_BLUR_WEIGHTS), in);
            if (blur == SSAO_BLUR_NONE) {
                // No blur, nothing weighed: the output is cleared to 1 and nothing samples.
                REQUIRE(w.pass_count == 1);
                CHECK(w.passes[0].kind == PassKind::clear);
                CHECK(program_of(w.passes[0].kind) == ProgramId::none);
                CHECK(w.passes[0].target.source == Source::output);
                CHECK(w.passes[0].rect.width == 67);
                CHECK(w.passes[0].rect.height == 41);
                CHECK(w.intermediate_count == 0);
                continue;
            }
            const FramePlan ao = plan_frame(resolved(blur, res, SSAO_DEBUG_VIEW_NONE), in);
            check_same_passes(w, ao);
            int blurs = 0;
            for (int i = 0; i < w.pass_count; ++i) {
                const Pass& p = w.passes[i];
                CAPTURE(i);
                const bool is_blur = p.kind == PassKind::blur_x || p.kind == PassKind::blur_y;
                blurs += is_blur;
                const uint32_t extra = is_blur ? variant::blur_weights
                                       : p.kind == PassKind::upsample ? variant::upsample_nearest
                                                                      : 0u;
                CHECK(p.variant == (ao.passes[i].variant | extra));
            }
            CHECK(blurs == (blur == SSAO_BLUR_BOX_4X4 ? 1 : 2));
        }
}

TEST_CASE("plan debug: strength off still clears to 1 with either view") {
    for (ssao_debug_view view : {SSAO_DEBUG_VIEW_RAW_AO, SSAO_DEBUG_VIEW_BLUR_WEIGHTS}) {
        CAPTURE(view);
        const FramePlan p =
            plan_frame(resolved(SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_HALF, view, SSAO_STRENGTH_OFF), inputs(20, 10));
        REQUIRE(p.pass_count == 1);
        CHECK(p.passes[0].kind == PassKind::clear);
    }
}

TEST_CASE("plan debug: the views keep the output format asked for") {
    for (ssao_debug_view view : {SSAO_DEBUG_VIEW_RAW_AO, SSAO_DEBUG_VIEW_BLUR_WEIGHTS})
        for (ssao_output_format f : {SSAO_OUTPUT_R8, SSAO_OUTPUT_R16F}) {
            CAPTURE(view);
            CAPTURE(f);
            ssao_settings s = resolved(SSAO_BLUR_GAUSSIAN, SSAO_RESOLUTION_FULL, view);
            s.output_format = f;
            const FramePlan p = plan_frame(s, inputs(16, 16));
            CHECK(p.output_format == (f == SSAO_OUTPUT_R16F ? TexFormat::r16f : TexFormat::r8));
        }
}
