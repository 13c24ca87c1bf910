// settings.h - validation and default resolution of ssao_settings, in one
// place, so the C defaults, the presets and the README table cannot drift.
#pragma once

#include <ssao/ssao.h>

#include <string>

namespace ssao_impl {

// Default values of every field (what a zero field resolves to).
constexpr uint32_t kDefaultSamples = 16;
constexpr float kDefaultRadius = 0.5f;
constexpr float kDefaultBiasFraction = 0.025f;  // of the radius
constexpr float kDefaultDepthStepBias = 2.0f;
constexpr float kDefaultPower = 1.0f;
constexpr float kDefaultStrength = 1.0f;
constexpr uint32_t kDefaultSeed = 1;
constexpr uint32_t kDefaultBlurRadius = 2;
constexpr float kDefaultBlurTolerance = 0.05f;
constexpr float kMaxStrength = 8.0f;
constexpr float kMaxPower = 16.0f;
constexpr float kMaxBlurSigma = 64.0f;

// Resolves zero fields to defaults and validates the rest. On failure returns
// the status and a sentence in `why`, and leaves `out` untouched.
ssao_status resolve_settings(const ssao_settings& in, ssao_settings& out, std::string& why);

// A preset, resolved. Takes the preset's raw 32 bits (raw_enum.h): any value
// a C caller passes is checked before it is read as an ssao_preset.
ssao_status preset_settings(uint32_t raw_preset, ssao_settings& out, std::string& why);

// Strength as a number (SSAO_STRENGTH_OFF -> 0).
inline float effective_strength(const ssao_settings& resolved) {
    return resolved.strength == SSAO_STRENGTH_OFF ? 0.0f : resolved.strength;
}

}  // namespace ssao_impl
