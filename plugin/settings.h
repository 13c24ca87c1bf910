// settings.h - validation and default resolution of ssao_settings, in one
// place, so the C defaults, the presets and the README table cannot drift.
#pragma once

#include <ssao/ssao.h>

#include <cstddef>
#include <string>

namespace ssao_impl {

// Default values of every field a preset does not set (what a zero field
// resolves to; the others come from the preset table, presets.h).
constexpr float kDefaultRadius = 0.5f;
constexpr float kDefaultBiasFraction = 0.025f;  // of the radius, kernel method
// The visibility method reads occluders through their tangent plane, which is
// exact for planes, so its constant bias only has to absorb interpolated
// normals: a tenth of the kernel's (whose bias shortens every direction).
constexpr float kDefaultVisibilityBiasFraction = 0.0025f;
constexpr float kDefaultDepthStepBias = 2.0f;
constexpr float kDefaultPower = 1.0f;
constexpr float kDefaultStrength = 1.0f;
constexpr uint32_t kDefaultSeed = 1;
constexpr uint32_t kDefaultBlurRadius = 2;
constexpr float kDefaultBlurTolerance = 0.05f;
// The visibility thickness when none is set: R (0.5 + 1.5 / steps), the
// limit's R/2 plus one and a half step lengths. A point test on steps R/N
// apart misses blocked intervals shorter than a step, which a thicker slab
// makes up for; with many steps the march approaches the one-plane read, and
// there R/2 is best. Read off scripts/thickness-sweep.sh (docs/bench/
// thickness.csv: the best T over six scenes and three radii falls from
// 0.75-0.875 R at 4 steps to 0.5 R at 32); over every view, quick runs of
// every case keep 1.5 / steps against 1 and 2 (docs/benchmark.md, "Where the
// last step lands").
constexpr float kThicknessBaseOfRadius = 0.5f;
constexpr float kThicknessStepsOfRadius = 1.5f;
inline float default_thickness(float radius, uint32_t step_count) {
    return radius * (kThicknessBaseOfRadius + kThicknessStepsOfRadius / static_cast<float>(step_count));
}
// max_step_texels defaults to 0 (off): a bound in texels adds steps with the
// radius on screen and so with the resolution, which on ssao-bench's
// standard views cost DEFAULT about 7% for 0.01 dB (docs/benchmark.md, "Step
// length"). The fields' upper bounds are the header's (SSAO_MAX_POWER ...).

// Resolves zero fields to defaults and validates the rest. `in` may be of
// any known version (struct_versions.h): the fields it lacks read as zero. On failure returns
// the status and a sentence in `why`, and leaves `out` untouched.
ssao_status resolve_settings(const ssao_settings& in, ssao_settings& out, std::string& why);

// A preset: the fields of its row, every other field 0 (= default, resolved
// at set_settings/execute). Takes the preset's raw 32 bits (raw_enum.h): any
// value a C caller passes is checked before it is read as an ssao_preset.
ssao_status preset_settings(uint32_t raw_preset, ssao_settings& out, std::string& why);

// Viewport pixels per reduced-grid texel along each axis: 1, 2 or 4 (the
// shaders shift by its logarithm, shaders/common.glsl scale_log2).
inline int resolution_scale(const ssao_settings& resolved) {
    return resolved.resolution == SSAO_RESOLUTION_QUARTER ? 4 : resolved.resolution == SSAO_RESOLUTION_HALF ? 2 : 1;
}

// Strength as a number (SSAO_STRENGTH_OFF -> 0).
inline float effective_strength(const ssao_settings& resolved) {
    return resolved.strength == SSAO_STRENGTH_OFF ? 0.0f : resolved.strength;
}

}  // namespace ssao_impl
