// pass_table.cpp - the rows of pass_table.h.
#include "pass_table.h"

#include <ssao_shaders_embedded.h>

namespace ssao_impl {

namespace {

constexpr ProgramInfo kNoProgram{ProgramId::none, nullptr, SharedCode::none, "", "", 0};
constexpr ProgramInfo kGrid{ProgramId::grid, k_grid_frag, SharedCode::common_and_sampling, "grid.frag",
                            "ssao: grid program", 0};
constexpr ProgramInfo kKernel{ProgramId::kernel, k_kernel_frag, SharedCode::common_and_sampling, "kernel.frag",
                              "ssao: kernel program", 0};
constexpr ProgramInfo kVisibility{ProgramId::visibility, k_visibility_frag, SharedCode::common_and_sampling,
                                  "visibility.frag", "ssao: visibility program", variant::grid_input};
constexpr ProgramInfo kNormalsView{ProgramId::normals_view, k_normals_view_frag, SharedCode::common_and_sampling,
                                   "normals_view.frag", "ssao: normals view program", variant::grid_input};
constexpr ProgramInfo kBlur{ProgramId::blur, k_blur_frag, SharedCode::common, "blur.frag", "ssao: blur program", 0};
constexpr ProgramInfo kUpsample{ProgramId::upsample, k_upsample_frag, SharedCode::common, "upsample.frag",
                                "ssao: upsample program", 0};
// No pass of its own: drawn inside each pass that fills the sky (runner.cpp).
constexpr ProgramInfo kSkyFill{ProgramId::sky_fill, k_sky_fill_frag, SharedCode::common, "sky_fill.frag",
                               "ssao: sky fill program", 0};

// In PassKind order.
constexpr PassInfo kPasses[] = {
    {PassKind::clear, "ssao: clear", SSAO_PASS_CLEAR, TimingBucket::ao_ms, kNoProgram},
    {PassKind::grid, "ssao: grid", SSAO_PASS_GRID, TimingBucket::ao_ms, kGrid},
    {PassKind::kernel, "ssao: kernel", SSAO_PASS_OCCLUSION, TimingBucket::ao_ms, kKernel},
    {PassKind::visibility, "ssao: visibility", SSAO_PASS_OCCLUSION, TimingBucket::ao_ms, kVisibility},
    {PassKind::normals_view, "ssao: normals view", SSAO_PASS_NORMALS_VIEW, TimingBucket::ao_ms, kNormalsView},
    {PassKind::blur_x, "ssao: blur x", SSAO_PASS_BLUR_X, TimingBucket::blur_ms, kBlur},
    {PassKind::blur_y, "ssao: blur y", SSAO_PASS_BLUR_Y, TimingBucket::blur_ms, kBlur},
    {PassKind::upsample, "ssao: upsample", SSAO_PASS_UPSAMPLE, TimingBucket::blur_ms, kUpsample},
};
static_assert(sizeof kPasses / sizeof kPasses[0] == static_cast<size_t>(PassKind::count), "one row per PassKind");

constexpr bool rows_in_kind_order() {
    for (size_t i = 0; i < sizeof kPasses / sizeof kPasses[0]; ++i)
        if (static_cast<size_t>(kPasses[i].kind) != i) return false;
    return true;
}
static_assert(rows_in_kind_order(), "kPasses is indexed by PassKind");

}  // namespace

const PassInfo& pass_info(PassKind kind) {
    const size_t i = static_cast<size_t>(kind);
    return i < sizeof kPasses / sizeof kPasses[0] ? kPasses[i] : kPasses[0];
}

const ProgramInfo& program_info(ProgramId id) {
    if (id == ProgramId::sky_fill) return kSkyFill;
    for (const PassInfo& p : kPasses)
        if (p.program.id == id) return p.program;
    return kPasses[0].program;  // not reached: every other program has a pass
}

}  // namespace ssao_impl
