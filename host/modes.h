// modes.h - the reference demo's SSAO modes, keys E R T Y U: one table for
// ssao-host's mode sheet (modes.png) and ssao-viewer's keys.
#pragma once

#include <ssao/ssao.h>

namespace modes {

struct Mode {
    char letter;       // the demo's key
    const char* name;  // what the mode shows
    bool ssao;         // false: the picture is lit without AO
    ssao_rotation rotation;
    ssao_kernel_distribution distribution;
    ssao_kernel_shape kernel;
};

inline constexpr Mode kModes[5] = {
    {'E', "no SSAO", false, SSAO_ROTATION_NONE, SSAO_DISTRIBUTION_UNIFORM, SSAO_KERNEL_SPHERE},
    {'R', "no rotation", true, SSAO_ROTATION_NONE, SSAO_DISTRIBUTION_UNIFORM, SSAO_KERNEL_SPHERE},
    {'T', "random rotation", true, SSAO_ROTATION_NOISE_4X4, SSAO_DISTRIBUTION_UNIFORM, SSAO_KERNEL_SPHERE},
    {'Y', "concentrated kernel", true, SSAO_ROTATION_NOISE_4X4, SSAO_DISTRIBUTION_ACCELERATING, SSAO_KERNEL_SPHERE},
    {'U', "hemisphere", true, SSAO_ROTATION_NOISE_4X4, SSAO_DISTRIBUTION_ACCELERATING, SSAO_KERNEL_HEMISPHERE},
};

// The mode of a key letter (upper case), or nullptr.
inline const Mode* find(char letter) {
    for (const Mode& m : kModes)
        if (m.letter == letter) return &m;
    return nullptr;
}

// Sets the kernel fields the mode chooses; every other field is left as it is.
inline void apply(const Mode& m, ssao_settings& s) {
    s.rotation = m.rotation;
    s.distribution = m.distribution;
    s.kernel_shape = m.kernel;
}

}  // namespace modes
