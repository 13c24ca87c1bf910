#include "sweep.h"

namespace bench {

namespace {

ssao_settings zeroed() {
    ssao_settings s{};
    s.size = sizeof s;
    return s;
}

Config kernel(uint32_t samples, ssao_blur blur, ssao_kernel_distribution d = SSAO_DISTRIBUTION_UNIFORM) {
    Config c;
    c.family = Family::kernel;
    c.s = zeroed();
    c.s.method = SSAO_METHOD_KERNEL;
    c.s.resolution = SSAO_RESOLUTION_FULL;  // explicit: the default follows the DEFAULT preset
    c.s.sample_count = samples;
    c.s.distribution = d;
    c.s.blur = blur;
    c.name = describe(c.s);
    return c;
}

Config visibility(uint32_t directions, uint32_t steps, ssao_blur blur,
                  ssao_resolution res = SSAO_RESOLUTION_FULL) {
    Config c;
    c.family = Family::visibility;
    c.s = zeroed();
    c.s.method = SSAO_METHOD_VISIBILITY;
    c.s.sample_count = directions;
    c.s.step_count = steps;
    c.s.blur = blur;
    c.s.resolution = res;
    c.name = describe(c.s);
    return c;
}

}  // namespace

const char* family_name(Family f) {
    switch (f) {
        case Family::kernel: return "kernel";
        case Family::visibility: return "visibility";
        case Family::preset: return "preset";
        case Family::preset_1_0: return "preset 1.0";
    }
    return "?";
}

const char* blur_name(ssao_blur b) {
    switch (b) {
        case SSAO_BLUR_DEPTH_AWARE: return "depth-aware";
        case SSAO_BLUR_BOX_4X4: return "box";
        case SSAO_BLUR_GAUSSIAN: return "gaussian";
        case SSAO_BLUR_NONE: return "none";
        default: return "default";
    }
}

std::string describe(const ssao_settings& s) {
    std::string d;
    if (s.method == SSAO_METHOD_VISIBILITY)
        d = "visibility " + std::to_string(s.sample_count) + "x" + std::to_string(s.step_count);
    else
        d = std::string("kernel ") + std::to_string(s.sample_count) +
            (s.distribution == SSAO_DISTRIBUTION_ACCELERATING ? " accelerating" : " uniform") +
            (s.kernel_shape == SSAO_KERNEL_SPHERE ? " sphere" : s.kernel_shape == SSAO_KERNEL_SEPARABLE ? " separable" : "");
    if (s.resolution == SSAO_RESOLUTION_HALF) d += ", half res";
    if (s.resolution == SSAO_RESOLUTION_QUARTER) d += ", quarter res";
    d += std::string(", blur ") + blur_name(s.blur);
    if (s.rotation == SSAO_ROTATION_HASH) d += ", hash rotation";
    if (s.rotation == SSAO_ROTATION_NOISE_4X4) d += ", 4x4 noise rotation";
    return d;
}

std::vector<Config> sweep() {
    std::vector<Config> c;
    const ssao_blur blurs[] = {SSAO_BLUR_NONE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_DEPTH_AWARE};
    for (uint32_t n : {4u, 16u, 64u})
        for (ssao_blur b : blurs) c.push_back(kernel(n, b));
    // The chapter's configuration as a setting of ours (docs/api.md, "Settings": the chapter's configuration).
    Config chapter = kernel(64, SSAO_BLUR_BOX_4X4, SSAO_DISTRIBUTION_ACCELERATING);
    c.push_back(chapter);

    for (uint32_t d : {2u, 4u, 8u})
        for (uint32_t steps : {4u, 8u, 16u})
            for (ssao_blur b : blurs) c.push_back(visibility(d, steps, b));
    // More directions at full resolution, blurred: the top of the accuracy range.
    for (uint32_t steps : {4u, 8u}) c.push_back(visibility(16, steps, SSAO_BLUR_DEPTH_AWARE));
    // Below full resolution: a quarter (or a sixteenth) of the pixels sampled.
    for (uint32_t d : {2u, 4u, 8u, 16u})
        for (uint32_t steps : {4u, 8u, 16u})
            for (ssao_blur b : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE})
                c.push_back(visibility(d, steps, b, SSAO_RESOLUTION_HALF));
    for (uint32_t d : {4u, 8u, 16u}) c.push_back(visibility(d, 8, SSAO_BLUR_DEPTH_AWARE, SSAO_RESOLUTION_QUARTER));
    for (uint32_t n : {16u, 64u}) {
        Config k = kernel(n, SSAO_BLUR_DEPTH_AWARE);
        k.s.resolution = SSAO_RESOLUTION_HALF;
        k.name = describe(k.s);
        c.push_back(k);
    }
    c.push_back(visibility(32, 16, SSAO_BLUR_NONE));
    c.push_back(visibility(64, 32, SSAO_BLUR_NONE));  // converged: what the estimator tends to
    // Thickness: the one knob the limit says matters most (the default at 8
    // steps is 0.6875 R, settings.h default_thickness).
    for (float t : {0.25f, 0.5f, 1e30f}) {
        Config v = visibility(8, 8, SSAO_BLUR_DEPTH_AWARE);
        v.thickness_of_radius = t;
        v.name += t > 1e29f ? ", thickness inf" : ", thickness " + std::to_string(t).substr(0, 4) + "R";
        c.push_back(v);
    }
    // The other rotations against the default gradient noise, at full
    // resolution (below it the 4x4 tile is gradient noise too).
    for (ssao_rotation r : {SSAO_ROTATION_HASH, SSAO_ROTATION_NOISE_4X4}) {
        Config turned = visibility(8, 8, SSAO_BLUR_DEPTH_AWARE);
        turned.s.rotation = r;
        turned.name = describe(turned.s);
        c.push_back(turned);
    }

    // The presets as interface 1.0 shipped them (plugin/settings.cpp before
    // the visibility estimator): the baseline "never worse than" compares to.
    struct Old {
        const char* name;
        uint32_t samples;
        ssao_kernel_distribution d;
        ssao_blur blur;
    };
    const Old old[] = {{"1.0 preset low", 4, SSAO_DISTRIBUTION_ACCELERATING, SSAO_BLUR_NONE},
                       {"1.0 preset medium", 4, SSAO_DISTRIBUTION_UNIFORM, SSAO_BLUR_BOX_4X4},
                       {"1.0 preset high", 16, SSAO_DISTRIBUTION_UNIFORM, SSAO_BLUR_BOX_4X4},
                       {"1.0 preset ultra", 64, SSAO_DISTRIBUTION_UNIFORM, SSAO_BLUR_DEPTH_AWARE}};
    for (const Old& o : old) {
        Config k = kernel(o.samples, o.blur, o.d);
        k.family = Family::preset_1_0;
        k.name = o.name;
        c.push_back(k);
    }
    return c;
}

std::vector<Config> shipped_presets() {
    std::vector<Config> c;
    const struct {
        ssao_preset p;
        const char* name;
    } presets[] = {{SSAO_PRESET_LOW, "preset low"},
                   {SSAO_PRESET_MEDIUM, "preset medium (= default)"},
                   {SSAO_PRESET_HIGH, "preset high"},
                   {SSAO_PRESET_ULTRA, "preset ultra"}};
    for (const auto& p : presets) {
        Config k;
        k.family = Family::preset;
        k.preset = p.p;
        k.name = p.name;
        c.push_back(k);
    }
    return c;
}

}  // namespace bench
