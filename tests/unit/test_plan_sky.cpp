// test_plan_sky.cpp - the sky tests of the frame plan (plugin/plan.h
// DepthUse), without GL: which pass writes the grid's sky mask, which passes
// test it or the copy of the host's depth, what each depth target is and how
// large, which passes fill the pixels they skip with the sky's value and
// how, that only a software rasteriser copies the host's depth, and that a
// multisampled depth, a multiply output and the normals views get no test
// they cannot use.
#include "plan.h"
#include "plan_test_util.h"
#include "settings.h"

#include <doctest/doctest.h>

using namespace ssao_impl;
using Source = TexRef::Source;

namespace {

ssao_settings resolved(ssao_method method, ssao_resolution res, ssao_blur blur,
                       ssao_debug_view view = SSAO_DEBUG_VIEW_NONE) {
    return plan_test::resolve(plan_test::request(method, res, blur, 0.0f, view));
}

// The inputs of a viewport as execute hands them to the plan on llvmpipe.
AnalysedInputs software(AnalysedInputs in) {
    in.software_rasterizer = true;
    return in;
}

bool is_depth_format(TexFormat f) {
    return f == TexFormat::d16 || f == TexFormat::d24 || f == TexFormat::d24s8 || f == TexFormat::d32f ||
           f == TexFormat::d32fs8;
}

const Pass* find(const FramePlan& p, PassKind kind) {
    for (int i = 0; i < p.pass_count; ++i)
        if (p.passes[i].kind == kind) return &p.passes[i];
    return nullptr;
}

// What every plan keeps: a depth target exactly where a depth use is, of a
// depth format, covering the pass's rectangle, never sampled and never a
// colour target; the grid's mask written by the grid pass before any pass
// tests it, at the grid's size; the copy at the output's rectangle.
void check_sky_invariants(const FramePlan& p, const AnalysedInputs& in) {
    int mask_written = -1;
    for (int i = 0; i < p.pass_count; ++i) {
        const Pass& pass = p.passes[i];
        CAPTURE(i);
        CHECK((pass.depth == DepthUse::none) == (pass.depth_target.source == Source::none));
        for (int j = 0; j < p.pass_count; ++j) {
            for (const TexRef& r : p.passes[j].inputs)
                if (pass.depth_target.source != Source::none) CHECK(r != pass.depth_target);
            if (pass.depth_target.source != Source::none) {
                CHECK(p.passes[j].target != pass.depth_target);
                CHECK(p.passes[j].target2 != pass.depth_target);
            }
        }
        if (pass.depth == DepthUse::none) continue;
        REQUIRE(pass.depth_target.source == Source::mask);
        REQUIRE(pass.depth_target.index < p.mask_count);
        const Intermediate& d = p.masks[pass.depth_target.index];
        CHECK(is_depth_format(d.format));
        CHECK(pass.rect.x + pass.rect.width <= d.width);
        CHECK(pass.rect.y + pass.rect.height <= d.height);
        switch (pass.depth) {
            case DepthUse::write_grid_mask:
                CHECK(pass.kind == PassKind::grid);
                CHECK(d.format == TexFormat::d16);
                mask_written = i;
                break;
            case DepthUse::grid_mask:
                REQUIRE(mask_written >= 0);
                CHECK(pass.depth_target == p.passes[mask_written].depth_target);
                CHECK(pass.target.source == Source::intermediate);
                CHECK(pass.rect.width == p.passes[mask_written].rect.width);
                CHECK(pass.rect.height == p.passes[mask_written].rect.height);
                break;
            case DepthUse::depth_copy:
                CHECK(in.software_rasterizer);
                CHECK_FALSE(in.multisample);
                CHECK(pass.rect.width == in.viewport[2]);
                CHECK(pass.rect.height == in.viewport[3]);
                CHECK(pass.rect.x == p.output_origin[0]);
                CHECK(pass.rect.y == p.output_origin[1]);
                break;
            case DepthUse::none: break;
        }
    }
    // The grid pass writes its mask only where a later pass tests it.
    if (mask_written >= 0) {
        bool tested = false;
        for (int i = mask_written + 1; i < p.pass_count; ++i) tested = tested || p.passes[i].depth == DepthUse::grid_mask;
        CHECK(tested);
    }
    CHECK(p.viewport.x == in.viewport[0]);
    CHECK(p.viewport.y == in.viewport[1]);
    CHECK(p.viewport.width == in.viewport[2]);
    CHECK(p.viewport.height == in.viewport[3]);
    CHECK(p.sky_depth == in.proj.sky_depth);
}

}  // namespace

TEST_CASE("sky tests: the default plan skips the sky on the grid and in the upsample") {
    const AnalysedInputs in = software(plan_test::viewport_inputs(0, 0, 64, 48));
    const FramePlan p = plan_frame(plan_test::resolve(ssao_settings{}), in);
    check_sky_invariants(p, in);
    REQUIRE(p.pass_count == 3);
    const Pass& grid = p.passes[0];
    const Pass& ao = p.passes[1];
    const Pass& up = p.passes[2];
    REQUIRE(grid.kind == PassKind::grid);
    REQUIRE(ao.kind == PassKind::visibility);
    REQUIRE(up.kind == PassKind::upsample);
    CHECK(grid.depth == DepthUse::write_grid_mask);
    CHECK_FALSE(grid.fills_sky());
    CHECK(ao.depth == DepthUse::grid_mask);
    CHECK(ao.fills_sky());
    CHECK(ao.pack_depth);  // filled with (1, SKY_Z, 0, 0), what visibility.frag writes at the sky
    CHECK(up.depth == DepthUse::depth_copy);
    CHECK(up.fills_sky());
    const Intermediate& mask = p.masks[grid.depth_target.index];
    CHECK(mask.width == 32);
    CHECK(mask.height == 24);
    const Intermediate& copy = p.masks[up.depth_target.index];
    CHECK(copy.format == TexFormat::d32f);  // the host's format: a blit copies depth only between matching ones
    CHECK(copy.width == 64);
    CHECK(copy.height == 48);
}

TEST_CASE("sky tests: every resolution, blur and method, each pass tested against what it can use") {
    for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY})
        for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER})
            for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN}) {
                CAPTURE(method);
                CAPTURE(res);
                CAPTURE(blur);
              for (bool software_rasterizer : {true, false}) {
                CAPTURE(software_rasterizer);
                AnalysedInputs in = plan_test::viewport_inputs(0, 0, 61, 37);
                in.software_rasterizer = software_rasterizer;
                const FramePlan p = plan_frame(resolved(method, res, blur), in);
                check_sky_invariants(p, in);
                const bool grid = find(p, PassKind::grid) != nullptr;
                for (int i = 0; i < p.pass_count; ++i) {
                    const Pass& pass = p.passes[i];
                    CAPTURE(i);
                    if (pass.kind == PassKind::grid) continue;
                    // Every pass after the host's depth is known is tested: a
                    // pass on the grid against the grid's mask; on a software
                    // rasteriser the output's writer, and without a grid the
                    // full-resolution passes (at the output's rectangle,
                    // origin 0 here), against the copy; on a GPU those not at all.
                    if (pass.target.source == Source::output || !grid)
                        CHECK(pass.depth == (software_rasterizer ? DepthUse::depth_copy : DepthUse::none));
                    else
                        CHECK(pass.depth == DepthUse::grid_mask);
                }
                if (!software_rasterizer) CHECK(p.mask_count <= 1);  // the grid's mask alone
                // A software rasteriser clears (a memset there), a GPU draws the fill.
                CHECK(p.sky_fill == (software_rasterizer ? SkyFill::clear : SkyFill::draw));
              }
            }
}

TEST_CASE("sky tests: the copy lies at the host's output rectangle and has the host's depth format") {
    struct Case {
        DepthFormat depth;
        TexFormat want;
    };
    auto fmt = [](int bits, bool is_float, bool stencil) {
        DepthFormat d = plan_test::depth_format(bits, is_float);
        d.has_stencil = stencil;
        return d;
    };
    const Case cases[] = {{fmt(16, false, false), TexFormat::d16}, {fmt(24, false, false), TexFormat::d24},
                          {fmt(24, false, true), TexFormat::d24s8}, {fmt(32, true, false), TexFormat::d32f},
                          {fmt(32, true, true), TexFormat::d32fs8}};
    for (const Case& c : cases) {
        CAPTURE(static_cast<int>(c.want));
        // A viewport at (5, 7) of the host's textures, written into the host's output there.
        const AnalysedInputs in = software(plan_test::viewport_inputs(5, 7, 40, 30, 9, c.depth));
        const FramePlan p = plan_frame(plan_test::resolve(ssao_settings{}), in);
        check_sky_invariants(p, in);
        const Pass* up = find(p, PassKind::upsample);
        REQUIRE(up != nullptr);
        REQUIRE(up->depth == DepthUse::depth_copy);
        const Intermediate& copy = p.masks[up->depth_target.index];
        CHECK(copy.format == c.want);
        CHECK(copy.width == 45);
        CHECK(copy.height == 37);
        CHECK(up->rect.x == 5);
        CHECK(up->rect.y == 7);
        // The library's own output: the copy at its origin.
        const AnalysedInputs own = software(plan_test::viewport_inputs(5, 7, 40, 30, 0, c.depth));
        const FramePlan q = plan_frame(plan_test::resolve(ssao_settings{}), own);
        check_sky_invariants(q, own);
        const Pass* up2 = find(q, PassKind::upsample);
        REQUIRE(up2 != nullptr);
        CHECK(up2->rect.x == 0);
        CHECK(q.masks[up2->depth_target.index].width == 40);
        CHECK(q.viewport.x == 5);  // copied from the viewport's rectangle of the host's depth
    }
}

TEST_CASE("sky tests: reverse-Z tests against a sky at depth 0") {
    AnalysedInputs in = software(plan_test::viewport_inputs(0, 0, 64, 48));
    in.proj.reverse_z = true;
    in.proj.sky_depth = 0.0f;
    const FramePlan p = plan_frame(plan_test::resolve(ssao_settings{}), in);
    check_sky_invariants(p, in);
    CHECK(p.sky_depth == 0.0f);
}

TEST_CASE("sky tests: multisampled depth is never copied, the grid's mask still serves the grid") {
    AnalysedInputs in = software(plan_test::viewport_inputs(0, 0, 64, 48));
    in.multisample = true;
    in.samples = 4;
    const FramePlan p = plan_frame(plan_test::resolve(ssao_settings{}), in);
    check_sky_invariants(p, in);
    const Pass* ao = find(p, PassKind::visibility);
    const Pass* up = find(p, PassKind::upsample);
    REQUIRE(ao != nullptr);
    REQUIRE(up != nullptr);
    CHECK(ao->depth == DepthUse::grid_mask);
    CHECK(up->depth == DepthUse::none);
    CHECK_FALSE(up->fills_sky());
}

TEST_CASE("sky tests: a multiply output is tested but not filled (a multiply by 1 changes nothing)") {
    AnalysedInputs in = software(plan_test::viewport_inputs(0, 0, 64, 48, 3));
    in.multiply_output = true;
    const FramePlan p = plan_frame(plan_test::resolve(ssao_settings{}), in);
    check_sky_invariants(p, in);
    const Pass* up = find(p, PassKind::upsample);
    REQUIRE(up != nullptr);
    CHECK(up->multiply);
    CHECK(up->depth == DepthUse::depth_copy);
    CHECK_FALSE(up->fills_sky());
}

TEST_CASE("sky tests: the normals views and the clear pass use no depth") {
    const AnalysedInputs in = software(plan_test::viewport_inputs(0, 0, 64, 48));
    for (ssao_debug_view view : {SSAO_DEBUG_VIEW_NORMALS, SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS}) {
        const FramePlan p = plan_frame(resolved(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_HALF, SSAO_BLUR_NONE, view), in);
        check_sky_invariants(p, in);
        for (int i = 0; i < p.pass_count; ++i) CHECK(p.passes[i].depth == DepthUse::none);
        CHECK(p.mask_count == 0);
    }
    ssao_settings off = plan_test::request(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_HALF, SSAO_BLUR_NONE);
    off.strength = SSAO_STRENGTH_OFF;
    const FramePlan p = plan_frame(plan_test::resolve(off), in);
    REQUIRE(p.pass_count == 1);
    CHECK(p.passes[0].kind == PassKind::clear);
    CHECK(p.passes[0].depth == DepthUse::none);
    CHECK(p.mask_count == 0);
}

TEST_CASE("sky tests: the debug views RAW_AO and BLUR_WEIGHTS keep them (the sky is 1 in both)") {
    const AnalysedInputs in = software(plan_test::viewport_inputs(0, 0, 64, 48));
    for (ssao_debug_view view : {SSAO_DEBUG_VIEW_RAW_AO, SSAO_DEBUG_VIEW_BLUR_WEIGHTS}) {
        const FramePlan p =
            plan_frame(resolved(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_HALF, SSAO_BLUR_DEPTH_AWARE, view), in);
        check_sky_invariants(p, in);
        const Pass* up = find(p, PassKind::upsample);
        REQUIRE(up != nullptr);
        CHECK(up->depth == DepthUse::depth_copy);
    }
}

TEST_CASE("sky tests: on a GPU nothing copies the host's depth, the grid's mask still serves the grid") {
    const AnalysedInputs in = plan_test::viewport_inputs(5, 7, 40, 30, 9);
    const FramePlan p = plan_frame(plan_test::resolve(ssao_settings{}), in);
    check_sky_invariants(p, in);
    REQUIRE(p.pass_count == 3);
    CHECK(p.passes[0].depth == DepthUse::write_grid_mask);
    CHECK(p.passes[1].depth == DepthUse::grid_mask);
    CHECK(p.passes[1].fills_sky());
    CHECK(p.passes[2].kind == PassKind::upsample);
    CHECK(p.passes[2].depth == DepthUse::none);
    CHECK_FALSE(p.passes[2].fills_sky());
    CHECK(p.mask_count == 1);
    CHECK(p.sky_fill == SkyFill::draw);
}
