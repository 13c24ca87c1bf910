// sweep.h - the configurations the benchmark measures.
#pragma once

#include <ssao/ssao.h>

#include <string>
#include <vector>

namespace bench {

// What a configuration is, for the reports and the plot.
enum class Family {
    kernel,      // method KERNEL: the chapter's point kernel (volume estimate)
    visibility,  // method VISIBILITY: ray-marched cosine-weighted directions
    preset,      // a preset as this library ships it (ssao_api::preset_settings)
    preset_1_0,  // a preset as interface 1.0 shipped it (the baseline the issue compares against)
};

struct Config {
    std::string name;
    Family family = Family::kernel;
    ssao_settings s{};           // radius 0: the scene's radius; < 0: that multiple of it
    ssao_preset preset = SSAO_PRESET_DEFAULT;  // family preset
    float thickness_of_radius = 0;             // > 0: thickness = this x radius (0: the library's default)
};

// The base-size sweep: kernel and visibility grids, thickness and rotation
// variants, and the 1.0 presets. Shipped presets are added from the ABI.
std::vector<Config> sweep();

// The shipped presets, named "preset low" .. "preset ultra" (settings filled by
// the caller from preset_settings).
std::vector<Config> shipped_presets();

const char* family_name(Family f);
const char* blur_name(ssao_blur b);
// A short name of a resolved configuration ("visibility 8x4, depth-aware blur").
std::string describe(const ssao_settings& s);

}  // namespace bench
