// presets.h - the preset table: the one source of truth for what each
// ssao_preset sets and, through the DEFAULT row, for what a zeroed
// ssao_settings resolves to (a user who sets nothing gets the DEFAULT preset).
// The header's preset comments, the README's preset table and ssao-host's
// --help are tested against it (tests/host/test_presets_doc.cpp); the rows
// were picked by ssao-bench's stated rule (README, "Presets").
#pragma once

#include <ssao/ssao.h>

#include <cstdint>

namespace ssao_impl {

// The fields a preset sets; every other field keeps its default.
struct PresetRow {
    ssao_method method;
    uint32_t sample_count;                  // kernel samples or visibility directions
    uint32_t step_count;                    // visibility: steps per direction (kernel: unused)
    ssao_kernel_distribution distribution;  // kernel only
    ssao_blur blur;
    ssao_resolution resolution;             // where the AO is sampled (full, half, quarter)
};

// The row of a valid preset; DEFAULT is MEDIUM.
const PresetRow& preset_row(ssao_preset preset);

// Where a zero field of those a preset sets comes from, once the method is
// known: the DEFAULT preset's row when the method is the DEFAULT preset's,
// else the method's own classic configuration (the kernel's is the
// LearnOpenGL chapter's: 64 accelerating samples and the 4x4 box blur), so
// that setting only the method gives that method at its textbook best.
const PresetRow& defaults_for_method(ssao_method resolved_method);

}  // namespace ssao_impl
