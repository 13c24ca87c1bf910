// test_plan.cpp - the frame plan (plugin/plan.h) without GL: which passes run
// for which settings, what each samples and writes, the sizes of the
// intermediates, and the invariants every plan keeps (the last pass writes
// the output, no pass samples its own target, every intermediate is written
// before it is read).
#include "pass_table.h"
#include "plan.h"
#include "plan_test_util.h"
#include "settings.h"

#include <doctest/doctest.h>

#include <set>
#include <string>
#include <vector>

using namespace ssao_impl;
using Source = TexRef::Source;

namespace {

// The kernel method (the plan's cases name its program) at full resolution (and its passes).
ssao_settings resolved(ssao_blur blur, float strength = 0.0f) {
    return plan_test::resolve(plan_test::request(SSAO_METHOD_KERNEL, SSAO_RESOLUTION_FULL, blur, strength));
}

AnalysedInputs inputs(int x, int y, int w, int h, uint32_t host_output = 0) {
    return plan_test::viewport_inputs(x, y, w, h, host_output);
}

std::vector<PassKind> kinds(const FramePlan& p) {
    std::vector<PassKind> k;
    for (int i = 0; i < p.pass_count; ++i) k.push_back(p.passes[i].kind);
    return k;
}

// What must hold for every plan, whatever the settings.
void check_invariants(const FramePlan& p, const AnalysedInputs& in) {
    REQUIRE(p.pass_count >= 1);
    REQUIRE(p.pass_count <= kMaxPasses);
    REQUIRE(p.intermediate_count >= 0);
    REQUIRE(p.intermediate_count <= kMaxIntermediates);
    // The final pass writes the output at the viewport's rectangle of it.
    const Pass& last = p.passes[p.pass_count - 1];
    CHECK(last.target.source == Source::output);
    CHECK_FALSE(last.pack_depth);
    const int ox = in.output_texture ? in.viewport[0] : 0, oy = in.output_texture ? in.viewport[1] : 0;
    CHECK(last.rect.x == ox);
    CHECK(last.rect.y == oy);
    CHECK(last.rect.width == in.viewport[2]);
    CHECK(last.rect.height == in.viewport[3]);
    CHECK(p.owned_output == (in.output_texture == 0));
    CHECK(p.output_origin[0] == ox);
    CHECK(p.output_origin[1] == oy);
    CHECK(p.output_width == in.viewport[2]);
    CHECK(p.output_height == in.viewport[3]);

    std::set<int> written;
    uint32_t bits = 0;
    for (int i = 0; i < p.pass_count; ++i) {
        const Pass& pass = p.passes[i];
        CAPTURE(i);
        bits |= pass_info(pass.kind).bit;
        // Only the last pass writes the output; the others write an
        // intermediate, packed (ao, view z), that a later pass reads.
        if (i + 1 < p.pass_count) {
            REQUIRE(pass.target.source == Source::intermediate);
            CHECK(pass.pack_depth);
            bool read_later = false;
            for (int j = i + 1; j < p.pass_count; ++j)
                for (const TexRef& r : p.passes[j].inputs) read_later = read_later || r == pass.target;
            CHECK(read_later);
        }
        if (pass.target.source == Source::intermediate) {
            REQUIRE(pass.target.index < p.intermediate_count);
            const Intermediate& t = p.intermediates[pass.target.index];
            // The pass's rectangle lies inside its target.
            CHECK(pass.rect.x >= 0);
            CHECK(pass.rect.y >= 0);
            CHECK(pass.rect.x + pass.rect.width <= t.width);
            CHECK(pass.rect.y + pass.rect.height <= t.height);
        }
        if (pass.target2.source != Source::none) {
            // Only the grid pass writes a second target: its normals, beside its view z.
            CHECK(pass.kind == PassKind::grid);
            REQUIRE(pass.target2.source == Source::intermediate);
            REQUIRE(pass.target2.index < p.intermediate_count);
            CHECK(pass.target2 != pass.target);
            const Intermediate& t2 = p.intermediates[pass.target2.index];
            const Intermediate& t1 = p.intermediates[pass.target.index];
            CHECK(t2.width == t1.width);
            CHECK(t2.height == t1.height);
        }
        for (const TexRef& r : pass.inputs) {
            CHECK(r != pass.target);  // never sample what we render into
            if (pass.target2.source != Source::none) CHECK(r != pass.target2);
            CHECK(r.source != Source::output);
            if (r.source == Source::intermediate) {
                REQUIRE(r.index < p.intermediate_count);
                CHECK(written.count(r.index) == 1);  // written by an earlier pass
            }
        }
        if (pass.target.source == Source::intermediate) written.insert(pass.target.index);
        if (pass.target2.source == Source::intermediate) written.insert(pass.target2.index);
        CHECK(std::string(pass_info(pass.kind).debug_group).rfind("ssao: ", 0) == 0);
    }
    CHECK(p.passes_run() == bits);
}

}  // namespace

TEST_CASE("plan: blur off gives one AO pass straight into the output") {
    const AnalysedInputs in = inputs(0, 0, 64, 48);
    const FramePlan p = plan_frame(resolved(SSAO_BLUR_NONE), in);
    check_invariants(p, in);
    REQUIRE(p.pass_count == 1);
    const Pass& ao = p.passes[0];
    CHECK(ao.kind == PassKind::kernel);
    CHECK(program_of(ao.kind) == ProgramId::kernel);
    CHECK(ao.inputs[SSAO_UNIT_DEPTH].source == Source::depth);
    CHECK(ao.inputs[SSAO_UNIT_NORMAL].source == Source::normal);
    CHECK(ao.inputs[SSAO_UNIT_NOISE].source == Source::noise);
    CHECK(ao.inputs[SSAO_UNIT_AO].source == Source::none);
    CHECK(p.intermediate_count == 0);
    CHECK(p.passes_run() == uint32_t(SSAO_PASS_OCCLUSION));
}

TEST_CASE("plan: strength off gives a clear and no sampling, whatever the blur") {
    for (ssao_blur blur : {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_NONE}) {
        CAPTURE(blur);
        for (uint32_t host : {0u, 7u}) {
            CAPTURE(host);
            const AnalysedInputs in = inputs(3, 5, 20, 10, host);
            const FramePlan p = plan_frame(resolved(blur, SSAO_STRENGTH_OFF), in);
            check_invariants(p, in);
            REQUIRE(p.pass_count == 1);
            CHECK(p.passes[0].kind == PassKind::clear);
            CHECK(program_of(p.passes[0].kind) == ProgramId::none);
            for (const TexRef& r : p.passes[0].inputs) CHECK(r.source == Source::none);
            CHECK(p.intermediate_count == 0);
            CHECK(p.passes_run() == uint32_t(SSAO_PASS_CLEAR));
        }
    }
}

TEST_CASE("plan: the box blur is one blur pass, the separable blurs two") {
    const AnalysedInputs in = inputs(0, 0, 32, 32);
    const FramePlan box = plan_frame(resolved(SSAO_BLUR_BOX_4X4), in);
    check_invariants(box, in);
    CHECK(kinds(box) == std::vector<PassKind>{PassKind::kernel, PassKind::blur_x});
    CHECK(box.intermediate_count == 1);
    CHECK(program_of(box.passes[1].kind) == ProgramId::blur);
    CHECK(box.passes[1].inputs[SSAO_UNIT_AO] == TexRef::of(Source::intermediate, 0));
    CHECK(box.passes_run() == uint32_t(SSAO_PASS_OCCLUSION | SSAO_PASS_BLUR_X));

    for (ssao_blur blur : {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_GAUSSIAN}) {
        CAPTURE(blur);
        const FramePlan p = plan_frame(resolved(blur), in);
        check_invariants(p, in);
        // The depth-aware blur tests its taps against the grid's tangent
        // planes: the grid pass (two intermediates) runs first.
        const bool grid = blur == SSAO_BLUR_DEPTH_AWARE;
        const int first = grid ? 1 : 0, ao = grid ? 2 : 0;
        std::vector<PassKind> want{PassKind::kernel, PassKind::blur_x, PassKind::blur_y};
        if (grid) want.insert(want.begin(), PassKind::grid);
        CHECK(kinds(p) == want);
        CHECK(p.intermediate_count == ao + 2);
        CHECK(p.passes[first].target == TexRef::of(Source::intermediate, ao));
        CHECK(p.passes[first + 1].inputs[SSAO_UNIT_AO] == TexRef::of(Source::intermediate, ao));
        CHECK(p.passes[first + 1].target == TexRef::of(Source::intermediate, ao + 1));
        CHECK(p.passes[first + 2].inputs[SSAO_UNIT_AO] == TexRef::of(Source::intermediate, ao + 1));
        CHECK(p.passes[first + 1].direction[0] == 1);
        CHECK(p.passes[first + 1].direction[1] == 0);
        CHECK(p.passes[first + 2].direction[0] == 0);
        CHECK(p.passes[first + 2].direction[1] == 1);
        // The AO and the x pass carry the plane's gradient exactly when there is one.
        for (int i = ao; i < ao + 2; ++i)
            CHECK(p.intermediates[i].format == (grid ? TexFormat::rgba32f : TexFormat::rg32f));
        CHECK(p.passes_run() == uint32_t((grid ? SSAO_PASS_GRID : 0) | SSAO_PASS_OCCLUSION | SSAO_PASS_BLUR_X |
                                         SSAO_PASS_BLUR_Y));
    }
}

TEST_CASE("plan: intermediates are viewport-sized RG32F, odd sizes kept exactly, at any viewport origin") {
    const int sizes[][4] = {{0, 0, 641, 359}, {0, 0, 1, 1}, {7, 3, 641, 359}, {0, 0, 16384, 3}, {2, 9, 33, 17}};
    for (const auto& v : sizes) {
        CAPTURE(v[0]);
        CAPTURE(v[1]);
        CAPTURE(v[2]);
        CAPTURE(v[3]);
        for (uint32_t host : {0u, 9u}) {
            const AnalysedInputs in = inputs(v[0], v[1], v[2], v[3], host);
            const FramePlan p = plan_frame(resolved(SSAO_BLUR_GAUSSIAN), in);
            check_invariants(p, in);
            REQUIRE(p.intermediate_count == 2);
            for (int i = 0; i < p.intermediate_count; ++i) {
                CHECK(p.intermediates[i].width == v[2]);
                CHECK(p.intermediates[i].height == v[3]);
                CHECK(p.intermediates[i].format == TexFormat::rg32f);
            }
            // Passes into an intermediate cover all of it from (0,0).
            for (int i = 0; i + 1 < p.pass_count; ++i) {
                CHECK(p.passes[i].rect.x == 0);
                CHECK(p.passes[i].rect.y == 0);
                CHECK(p.passes[i].rect.width == v[2]);
                CHECK(p.passes[i].rect.height == v[3]);
            }
        }
    }
}

TEST_CASE("plan: the owned output's format follows the settings, a host output is written in place") {
    ssao_settings s = resolved(SSAO_BLUR_NONE);
    CHECK(plan_frame(s, inputs(0, 0, 8, 8)).output_format == TexFormat::r8);
    s.output_format = SSAO_OUTPUT_R16F;
    CHECK(plan_frame(s, inputs(0, 0, 8, 8)).output_format == TexFormat::r16f);
    const AnalysedInputs host = inputs(4, 6, 16, 12, 5);
    const FramePlan p = plan_frame(s, host);
    check_invariants(p, host);
    CHECK_FALSE(p.owned_output);
    CHECK(p.passes[0].rect.x == 4);
    CHECK(p.passes[0].rect.y == 6);
}

TEST_CASE("plan: the same arguments give the same plan (pure)") {
    const AnalysedInputs in = inputs(1, 2, 30, 20);
    const ssao_settings s = resolved(SSAO_BLUR_GAUSSIAN);
    const FramePlan a = plan_frame(s, in), b = plan_frame(s, in);
    REQUIRE(a.pass_count == b.pass_count);
    for (int i = 0; i < a.pass_count; ++i) {
        CHECK(a.passes[i].kind == b.passes[i].kind);
        CHECK(a.passes[i].target == b.passes[i].target);
    }
}

TEST_CASE("pass table: one row per pass, with distinct debug groups, the public bits and the timing figures") {
    std::set<std::string> groups;
    for (int k = 0; k < static_cast<int>(PassKind::count); ++k) {
        const PassInfo& row = pass_info(static_cast<PassKind>(k));
        CAPTURE(row.debug_group);
        CHECK(static_cast<int>(row.kind) == k);
        CHECK(std::string(row.debug_group).rfind("ssao: ", 0) == 0);
        groups.insert(row.debug_group);
        const bool draws = row.program.id != ProgramId::none;
        CHECK(draws == (row.kind != PassKind::clear));
        if (draws) CHECK(std::string(row.program.file_name).find(".frag") != std::string::npos);
    }
    CHECK(groups.size() == static_cast<size_t>(PassKind::count));
    struct Want {
        PassKind kind;
        const char* group;
        uint32_t bit;
        TimingBucket bucket;
        ProgramId program;
        const char* file;
    };
    const Want want[] = {
        {PassKind::clear, "ssao: clear", SSAO_PASS_CLEAR, TimingBucket::ao_ms, ProgramId::none, ""},
        {PassKind::grid, "ssao: grid", SSAO_PASS_GRID, TimingBucket::ao_ms, ProgramId::grid, "grid.frag"},
        {PassKind::kernel, "ssao: kernel", SSAO_PASS_OCCLUSION, TimingBucket::ao_ms, ProgramId::kernel, "kernel.frag"},
        {PassKind::visibility, "ssao: visibility", SSAO_PASS_OCCLUSION, TimingBucket::ao_ms, ProgramId::visibility,
         "visibility.frag"},
        {PassKind::normals_view, "ssao: normals view", SSAO_PASS_NORMALS_VIEW, TimingBucket::ao_ms,
         ProgramId::normals_view, "normals_view.frag"},
        {PassKind::blur_x, "ssao: blur x", SSAO_PASS_BLUR_X, TimingBucket::blur_ms, ProgramId::blur, "blur.frag"},
        {PassKind::blur_y, "ssao: blur y", SSAO_PASS_BLUR_Y, TimingBucket::blur_ms, ProgramId::blur, "blur.frag"},
        {PassKind::upsample, "ssao: upsample", SSAO_PASS_UPSAMPLE, TimingBucket::blur_ms, ProgramId::upsample,
         "upsample.frag"},
    };
    for (const Want& w : want) {
        const PassInfo& row = pass_info(w.kind);
        CAPTURE(w.group);
        CHECK(std::string(row.debug_group) == w.group);
        CHECK(row.bit == w.bit);
        CHECK(row.bucket == w.bucket);
        CHECK(row.program.id == w.program);
        CHECK(std::string(row.program.file_name) == w.file);
        if (w.program != ProgramId::none) CHECK(std::string(program_info(w.program).file_name) == w.file);
    }
    // The names the header promised before the passes were renamed.
    CHECK(uint32_t(SSAO_PASS_AO) == uint32_t(SSAO_PASS_OCCLUSION));
    CHECK(uint32_t(SSAO_PASS_DOWNSAMPLE) == uint32_t(SSAO_PASS_GRID));
}

TEST_CASE("plan: the method picks the estimator's program, the visibility march always reads the grid") {
    const AnalysedInputs in = inputs(0, 0, 64, 48);
    for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF}) {
        CAPTURE(res);
        ssao_settings kernel = resolved(SSAO_BLUR_DEFAULT), visibility = kernel;
        kernel.method = SSAO_METHOD_KERNEL;
        visibility.method = SSAO_METHOD_VISIBILITY;
        kernel.resolution = visibility.resolution = res;
        const FramePlan pk = plan_frame(kernel, in), pv = plan_frame(visibility, in);
        check_invariants(pk, in);
        check_invariants(pv, in);
        // At full resolution the kernel reads the host's textures; the
        // march reads one plane texel per step, so a grid pass comes first.
        const bool kernel_grid = res != SSAO_RESOLUTION_FULL;
        REQUIRE(pv.pass_count == pk.pass_count + (kernel_grid ? 0 : 1));
        REQUIRE(pv.passes[0].kind == PassKind::grid);
        CHECK((pk.passes[0].kind == PassKind::grid) == kernel_grid);
        const int k0 = kernel_grid ? 1 : 0;
        CHECK(program_of(pk.passes[k0].kind) == ProgramId::kernel);
        CHECK(program_of(pv.passes[1].kind) == ProgramId::visibility);
        CHECK((pv.passes[1].variant & variant::grid_input) != 0);
        CHECK(((pk.passes[k0].variant & variant::grid_input) != 0) == kernel_grid);
        for (int i = 2; i < pv.pass_count; ++i)
            CHECK(program_of(pv.passes[i].kind) == program_of(pk.passes[i - 1 + k0].kind));
        CHECK(pv.passes_run() == (pk.passes_run() | SSAO_PASS_GRID));
    }
}

namespace {

ssao_settings at_resolution(ssao_blur blur, ssao_resolution resolution, ssao_method method = SSAO_METHOD_KERNEL) {
    ssao_settings s = resolved(blur);
    s.resolution = resolution;
    s.method = method;
    return s;
}

}  // namespace

TEST_CASE("plan: half resolution of 641x359 - downsample, AO and blur on a 321x180 grid, upsample to every pixel") {
    for (uint32_t host : {0u, 9u}) {
        CAPTURE(host);
        const AnalysedInputs in = inputs(host ? 7 : 0, host ? 3 : 0, 641, 359, host);
        const FramePlan p = plan_frame(at_resolution(SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_HALF), in);
        check_invariants(p, in);
        REQUIRE(kinds(p) == std::vector<PassKind>{PassKind::grid, PassKind::kernel, PassKind::blur_x,
                                                  PassKind::blur_y, PassKind::upsample});
        CHECK(p.passes_run() == uint32_t(SSAO_PASS_GRID | SSAO_PASS_OCCLUSION | SSAO_PASS_BLUR_X | SSAO_PASS_BLUR_Y |
                                         SSAO_PASS_UPSAMPLE));
        // ceil(641/2) x ceil(359/2): the last column and row are blocks of one pixel, not dropped.
        // The grid pass's plane texels and normals (both RGBA32F), the AO, the blur's x pass.
        REQUIRE(p.intermediate_count == 4);
        CHECK(p.intermediates[0].format == TexFormat::rgba32f);
        CHECK(p.intermediates[1].format == TexFormat::rgba32f);
        for (int i = 0; i < p.intermediate_count; ++i) {
            CHECK(p.intermediates[i].width == 321);
            CHECK(p.intermediates[i].height == 180);
        }
        for (int i = 0; i < 4; ++i) {
            CAPTURE(i);
            CHECK(p.passes[i].rect.x == 0);
            CHECK(p.passes[i].rect.y == 0);
            CHECK(p.passes[i].rect.width == 321);
            CHECK(p.passes[i].rect.height == 180);
        }
        const Pass& down = p.passes[0];
        CHECK(program_of(down.kind) == ProgramId::grid);
        CHECK(down.inputs[SSAO_UNIT_DEPTH].source == Source::depth);
        CHECK(down.inputs[SSAO_UNIT_NORMAL].source == Source::normal);
        CHECK(down.scale == 2);
        CHECK(down.target == TexRef::of(Source::intermediate, 0));
        CHECK(down.target2 == TexRef::of(Source::intermediate, 1));
        const Pass& ao = p.passes[1];
        CHECK(ao.scale == 2);
        CHECK(ao.inputs[SSAO_UNIT_DEPTH] == down.target);  // the grid, not the host's depth
        CHECK(ao.inputs[SSAO_UNIT_NORMAL] == down.target2);
        CHECK(ao.inputs[SSAO_UNIT_NOISE].source == Source::noise);
        const Pass& up = p.passes[4];
        CHECK(program_of(up.kind) == ProgramId::upsample);
        CHECK(up.scale == 2);
        CHECK(up.inputs[SSAO_UNIT_DEPTH].source == Source::depth);  // its own full-resolution depth
        CHECK(up.inputs[SSAO_UNIT_AO] == p.passes[3].target);
        CHECK(up.inputs[SSAO_UNIT_NORMAL].source == Source::none);
        // Blurs on the grid weigh taps by depth (a leak there would span blocks).
        CHECK(p.passes[2].depth_aware);
        CHECK(p.passes[3].depth_aware);
    }
}

TEST_CASE("plan: reduced resolution for every blur, both methods, quarter too, at odd and tiny sizes") {
    const struct {
        ssao_blur blur;
        std::vector<PassKind> middle;
    } blurs[] = {{SSAO_BLUR_NONE, {}},
                 {SSAO_BLUR_BOX_4X4, {PassKind::blur_x}},
                 {SSAO_BLUR_GAUSSIAN, {PassKind::blur_x, PassKind::blur_y}},
                 {SSAO_BLUR_DEPTH_AWARE, {PassKind::blur_x, PassKind::blur_y}}};
    const int sizes[][2] = {{641, 359}, {67, 41}, {1, 1}, {2, 1}, {1, 3}, {5, 4}, {16384, 3}};
    for (ssao_resolution res : {SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER}) {
        const int scale = res == SSAO_RESOLUTION_HALF ? 2 : 4;
        for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY}) {
            for (const auto& b : blurs) {
                for (const auto& sz : sizes) {
                    CAPTURE(scale);
                    CAPTURE(method);
                    CAPTURE(b.blur);
                    CAPTURE(sz[0]);
                    CAPTURE(sz[1]);
                    const AnalysedInputs in = inputs(0, 0, sz[0], sz[1]);
                    const FramePlan p = plan_frame(at_resolution(b.blur, res, method), in);
                    check_invariants(p, in);
                    std::vector<PassKind> want{PassKind::grid, method == SSAO_METHOD_VISIBILITY ? PassKind::visibility : PassKind::kernel};
                    want.insert(want.end(), b.middle.begin(), b.middle.end());
                    want.push_back(PassKind::upsample);
                    CHECK(kinds(p) == want);
                    CHECK(program_of(p.passes[1].kind) ==
                          (method == SSAO_METHOD_VISIBILITY ? ProgramId::visibility : ProgramId::kernel));
                    const int lw = (sz[0] + scale - 1) / scale, lh = (sz[1] + scale - 1) / scale;
                    for (int i = 0; i < p.intermediate_count; ++i) {
                        CHECK(p.intermediates[i].width == lw);
                        CHECK(p.intermediates[i].height == lh);
                    }
                    // The grid covers the viewport exactly: no pixel without its block, no empty block.
                    CHECK(lw * scale >= sz[0]);
                    CHECK((lw - 1) * scale < sz[0]);
                    CHECK(lh * scale >= sz[1]);
                    CHECK((lh - 1) * scale < sz[1]);
                    for (int i = 0; i < p.pass_count; ++i) {
                        if (program_of(p.passes[i].kind) != ProgramId::blur) CHECK(p.passes[i].scale == scale);
                        else CHECK(p.passes[i].depth_aware);
                    }
                }
            }
        }
    }
}

TEST_CASE("plan: full resolution plans no upsample and every pass at scale 1, strength off stays one clear at any resolution") {
    const AnalysedInputs in = inputs(0, 0, 64, 48);
    for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_DEPTH_AWARE}) {
        CAPTURE(blur);
        const FramePlan p = plan_frame(at_resolution(blur, SSAO_RESOLUTION_FULL), in);
        CHECK((p.passes_run() & uint32_t(SSAO_PASS_UPSAMPLE)) == 0u);
        // The kernel reads the host's textures directly; the grid pass (at
        // full resolution) only for the depth-aware blur's tangent planes.
        CHECK(((p.passes_run() & uint32_t(SSAO_PASS_GRID)) != 0u) == (blur == SSAO_BLUR_DEPTH_AWARE));
        for (int i = 0; i < p.pass_count; ++i) {
            CHECK(p.passes[i].scale == 1);
            CHECK_FALSE(p.passes[i].depth_aware);  // the blur kind alone decides at full resolution
        }
    }
    for (ssao_resolution res : {SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER}) {
        ssao_settings s = at_resolution(SSAO_BLUR_DEPTH_AWARE, res);
        s.strength = SSAO_STRENGTH_OFF;
        const FramePlan p = plan_frame(s, in);
        check_invariants(p, in);
        CHECK(p.passes_run() == uint32_t(SSAO_PASS_CLEAR));
        CHECK(p.intermediate_count == 0);
    }
}

TEST_CASE("plan: multisampled inputs, normals from depth or the depth-aware blur add the grid pass at full resolution too, with its variants") {
    for (bool ms : {false, true})
        for (bool from_depth : {false, true})
            for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF})
                for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_DEPTH_AWARE}) {
                    CAPTURE(ms);
                    CAPTURE(from_depth);
                    CAPTURE(res);
                    CAPTURE(blur);
                    AnalysedInputs in = inputs(0, 0, 67, 41);
                    in.multisample = ms;
                    in.normals_from_depth = from_depth;
                    const FramePlan p = plan_frame(at_resolution(blur, res), in);
                    check_invariants(p, in);
                    // The depth-aware blur tests its taps against the grid's tangent planes.
                    const bool grid = ms || from_depth || res != SSAO_RESOLUTION_FULL || blur == SSAO_BLUR_DEPTH_AWARE;
                    const Pass& first = p.passes[0];
                    CHECK((first.kind == PassKind::grid) == grid);
                    for (int i = 0; i < p.pass_count; ++i) {
                        const Pass& pass = p.passes[i];
                        CAPTURE(i);
                        // Only the passes that read the host's textures read them multisampled.
                        const bool reads_host = pass.kind == PassKind::grid || pass.kind == PassKind::upsample ||
                                                (pass.kind == PassKind::kernel && !grid);
                        CHECK(((pass.variant & variant::multisample) != 0) == (ms && reads_host));
                        CHECK(((pass.variant & variant::normals_from_depth) != 0) ==
                              (from_depth && pass.kind == PassKind::grid));
                        CHECK(((pass.variant & variant::grid_input) != 0) == (grid && pass.kind == PassKind::kernel));
                    }
                    if (!grid) continue;
                    // No normal texture to read: the grid pass leaves the unit unbound.
                    CHECK((first.inputs[SSAO_UNIT_NORMAL].source == Source::normal) == !from_depth);
                    const int scale = res == SSAO_RESOLUTION_HALF ? 2 : 1;
                    CHECK(first.scale == scale);
                    CHECK(p.intermediates[first.target.index].width == (67 + scale - 1) / scale);
                    CHECK(p.intermediates[first.target.index].format == TexFormat::rgba32f);
                    CHECK(p.intermediates[first.target2.index].format == TexFormat::rgba32f);
                    // The sampling pass reads the plane texels per step and the normals once.
                    for (int i = 0; i < p.pass_count; ++i)
                        if (p.passes[i].kind == PassKind::kernel) {
                            CHECK(p.passes[i].inputs[SSAO_UNIT_DEPTH] == first.target);
                            CHECK(p.passes[i].inputs[SSAO_UNIT_NORMAL] == first.target2);
                        }
                    // At full resolution nothing is upsampled.
                    CHECK(((p.passes_run() & SSAO_PASS_UPSAMPLE) != 0) == (scale > 1));
                }
}
