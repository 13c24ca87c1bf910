// test_plan_normals_view.cpp - the frame plan of the normal debug views
// (ssao_settings.debug_view NORMALS / RECONSTRUCTED_NORMALS):
// the grid pass at full resolution then the view pass into the output,
// whatever the resolution, blur or strength; the owned output is RGBA8.
#include "pass_table.h"
#include "plan.h"
#include "plan_test_util.h"
#include "settings.h"

#include <doctest/doctest.h>

#include <string>

using namespace ssao_impl;
using Source = TexRef::Source;

namespace {

ssao_settings resolved_view(ssao_debug_view view, ssao_resolution res, ssao_blur blur, float strength) {
    return plan_test::resolve(plan_test::request(SSAO_METHOD_DEFAULT, res, blur, strength, view));
}

AnalysedInputs viewport(int x, int y, int w, int h, uint32_t host_output) {
    return plan_test::viewport_inputs(x, y, w, h, host_output, plan_test::depth_format(24, false));
}

}  // namespace

TEST_CASE("plan: the normal views run the full-resolution grid pass and the view pass, nothing else") {
    for (ssao_debug_view view : {SSAO_DEBUG_VIEW_NORMALS, SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS})
        for (bool from_depth : {false, true})
            for (uint32_t host_output : {0u, 7u})
                for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_QUARTER})
                    for (float strength : {0.0f, SSAO_STRENGTH_OFF}) {
                        CAPTURE(view);
                        CAPTURE(from_depth);
                        CAPTURE(host_output);
                        CAPTURE(res);
                        CAPTURE(strength);
                        AnalysedInputs in = viewport(3, 2, 67, 41, host_output);
                        in.normals_from_depth = from_depth;
                        const FramePlan p = plan_frame(resolved_view(view, res, SSAO_BLUR_DEPTH_AWARE, strength), in);
                        REQUIRE(p.pass_count == 2);
                        const Pass& grid = p.passes[0];
                        const Pass& out = p.passes[1];
                        CHECK(grid.kind == PassKind::grid);
                        CHECK(grid.scale == 1);
                        CHECK(grid.target.source == Source::intermediate);
                        CHECK(p.intermediates[grid.target.index].width == 67);
                        CHECK(p.intermediates[grid.target.index].height == 41);
                        CHECK(p.intermediates[grid.target.index].format == TexFormat::rgba32f);
                        CHECK(p.intermediates[grid.target2.index].format == TexFormat::rgba32f);
                        const bool rebuild = from_depth || view == SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS;
                        CHECK(((grid.variant & variant::normals_from_depth) != 0) == rebuild);
                        CHECK((grid.inputs[SSAO_UNIT_NORMAL].source == Source::normal) == !rebuild);
                        CHECK(program_of(out.kind) == ProgramId::normals_view);
                        CHECK(out.variant == variant::grid_input);
                        CHECK(out.inputs[SSAO_UNIT_DEPTH] == grid.target);
                        CHECK(out.inputs[SSAO_UNIT_NORMAL] == grid.target2);
                        CHECK(out.target.source == Source::output);
                        CHECK(out.rect.x == (host_output ? 3 : 0));
                        CHECK(out.rect.y == (host_output ? 2 : 0));
                        CHECK(out.rect.width == 67);
                        CHECK(out.rect.height == 41);
                        CHECK(out.kind == PassKind::normals_view);
                        CHECK(p.passes_run() == (SSAO_PASS_GRID | SSAO_PASS_NORMALS_VIEW));
                        CHECK(p.output_format == TexFormat::rgba8);
                    }
}

TEST_CASE("plan: other debug views and none keep the output format asked for") {
    const AnalysedInputs in = viewport(0, 0, 16, 16, 0);
    for (ssao_debug_view view : {SSAO_DEBUG_VIEW_NONE, SSAO_DEBUG_VIEW_RAW_AO, SSAO_DEBUG_VIEW_BLUR_WEIGHTS}) {
        CAPTURE(view);
        ssao_settings s = resolved_view(view, SSAO_RESOLUTION_FULL, SSAO_BLUR_NONE, 0.0f);
        s.output_format = SSAO_OUTPUT_R16F;
        const FramePlan p = plan_frame(s, in);
        CHECK(p.output_format == TexFormat::r16f);
        for (int i = 0; i < p.pass_count; ++i) CHECK(program_of(p.passes[i].kind) != ProgramId::normals_view);
    }
}
