#include "preset_text.h"

namespace preset_text {

namespace {

const char* blur_words(ssao_blur b) {
    switch (b) {
        case SSAO_BLUR_DEPTH_AWARE: return "depth-aware blur";
        case SSAO_BLUR_BOX_4X4: return "4x4 box blur";
        case SSAO_BLUR_GAUSSIAN: return "gaussian blur";
        case SSAO_BLUR_NONE: return "no blur";
        default: return "default blur";
    }
}

const char* resolution_words(ssao_resolution r) {
    switch (r) {
        case SSAO_RESOLUTION_HALF: return "half resolution";
        case SSAO_RESOLUTION_QUARTER: return "quarter resolution";
        default: return "full resolution";
    }
}

}  // namespace

std::string describe(const ssao_settings& s) {
    std::string d;
    if (s.method == SSAO_METHOD_VISIBILITY)
        d = "visibility, " + std::to_string(s.sample_count) + " directions x " + std::to_string(s.step_count) + " steps";
    else
        d = "kernel, " + std::to_string(s.sample_count) +
            (s.distribution == SSAO_DISTRIBUTION_ACCELERATING ? " accelerating" : " uniform") + " samples";
    return d + ", " + resolution_words(s.resolution) + ", " + blur_words(s.blur);
}

const char* name(ssao_preset p) {
    switch (p) {
        case SSAO_PRESET_LOW: return "low";
        case SSAO_PRESET_HIGH: return "high";
        case SSAO_PRESET_ULTRA: return "ultra";
        case SSAO_PRESET_CHAPTER: return "chapter";
        default: return "medium";
    }
}

std::optional<ssao_preset> parse(const std::string& text) {
    for (const ssao_preset p : kPresetOrder)
        if (text == name(p)) return p;
    return std::nullopt;
}

std::string choices() {
    std::string list;
    for (const ssao_preset p : kPresetOrder) list += std::string(list.empty() ? "" : "|") + name(p);
    return list;
}

}  // namespace preset_text
