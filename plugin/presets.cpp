#include "presets.h"

namespace ssao_impl {

namespace {

// Picked from ssao-bench's sweep by the rule in the README ("Presets"; the
// rule is coded in bench/report.cpp and printed to presets.txt): LOW the
// fastest configuration on the front against V_R, MEDIUM the most accurate
// (mean PSNR against V_R over the bundled scenes) within a quarter of the
// textbook pass's CPU time, HIGH and ULTRA the fastest that each gain
// another 1 dB. MEDIUM keeps the upsample's own filtering without a blur
// pass: the latest run's rule adds the blur for a small gain on the standard
// views alone, and the table holds MEDIUM to DEFAULT's median over every case
// (README, "Presets"). Above it the depth-aware blur pays.
constexpr PresetRow kLow{SSAO_METHOD_VISIBILITY, 4, 8, SSAO_DISTRIBUTION_UNIFORM, SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_QUARTER};
constexpr PresetRow kMedium{SSAO_METHOD_VISIBILITY, 8, 4, SSAO_DISTRIBUTION_UNIFORM, SSAO_BLUR_NONE, SSAO_RESOLUTION_HALF};
constexpr PresetRow kHigh{SSAO_METHOD_VISIBILITY, 4, 4, SSAO_DISTRIBUTION_UNIFORM, SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_FULL};
constexpr PresetRow kUltra{SSAO_METHOD_VISIBILITY, 8, 8, SSAO_DISTRIBUTION_UNIFORM, SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_FULL};

// Each method's classic configuration, for a method other than the DEFAULT
// preset's (see defaults_for_method).
constexpr PresetRow kChapterKernel{SSAO_METHOD_KERNEL, 64, 4, SSAO_DISTRIBUTION_ACCELERATING, SSAO_BLUR_BOX_4X4, SSAO_RESOLUTION_FULL};
constexpr PresetRow kPlainVisibility{SSAO_METHOD_VISIBILITY, 8, 8, SSAO_DISTRIBUTION_UNIFORM, SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_FULL};

}  // namespace

const PresetRow& preset_row(ssao_preset preset) {
    switch (preset) {
        case SSAO_PRESET_LOW: return kLow;
        case SSAO_PRESET_HIGH: return kHigh;
        case SSAO_PRESET_ULTRA: return kUltra;
        case SSAO_PRESET_CHAPTER: return kChapterKernel;
        case SSAO_PRESET_DEFAULT:
        case SSAO_PRESET_MEDIUM:
        default: return kMedium;
    }
}

const PresetRow& defaults_for_method(ssao_method method) {
    const PresetRow& def = preset_row(SSAO_PRESET_DEFAULT);
    if (method == def.method) return def;
    return method == SSAO_METHOD_KERNEL ? kChapterKernel : kPlainVisibility;
}

}  // namespace ssao_impl
