// preset_text.h - a preset in one line of words ("visibility, 8 directions x
// 4 steps, half resolution, no blur"), from its resolved settings. ssao-host
// --help prints it for each preset, and tests/host/test_presets_doc.cpp checks
// that the header's preset comments and the README's preset table say the same
// for what preset_settings returns: the plugin's table is the one source.
#pragma once

#include <ssao/ssao.h>

#include <optional>
#include <string>

namespace preset_text {

std::string describe(const ssao_settings& resolved);

// The presets in --help's order, and how many.
constexpr ssao_preset kPresetOrder[] = {SSAO_PRESET_LOW, SSAO_PRESET_MEDIUM, SSAO_PRESET_HIGH, SSAO_PRESET_ULTRA,
                                        SSAO_PRESET_CHAPTER};
constexpr int kPresetCount = 5;

// "low", "medium", "high", "ultra", "chapter" (DEFAULT: "medium").
const char* name(ssao_preset preset);

// The preset a --preset NAME means (every tool's list: kPresetOrder's names);
// empty for any other text.
std::optional<ssao_preset> parse(const std::string& name);

// "low|medium|high|ultra|chapter", for messages and help texts.
std::string choices();

}  // namespace preset_text
