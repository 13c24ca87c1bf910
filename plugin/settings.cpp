#include "settings.h"

#include "presets.h"
#include "raw_enum.h"
#include "struct_versions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace ssao_impl {

namespace {

bool finite(float v) { return std::isfinite(v); }

ssao_status fail(std::string& why, ssao_status status, const std::string& what) {
    why = what;
    return status;
}

// A bound as the messages print it (1e6 as 1e+06, 16 as 16).
std::string bound(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", static_cast<double>(v));
    return text;
}

// How many samples, how far, how strong.
ssao_status resolve_amounts(ssao_settings& r, const PresetRow& defaults, std::string& why) {
    if (r.sample_count == 0) r.sample_count = defaults.sample_count;
    if (r.sample_count > SSAO_MAX_SAMPLES)
        return fail(why, SSAO_ERROR_INVALID_VALUE,
                    "sample_count " + std::to_string(r.sample_count) + " is outside 1.." + std::to_string(SSAO_MAX_SAMPLES));

    if (!finite(r.radius) || r.radius < 0.0f)
        return fail(why, SSAO_ERROR_INVALID_VALUE, "radius must be a finite number > 0");
    if (r.radius == 0.0f) r.radius = kDefaultRadius;

    if (!finite(r.depth_step_bias) || r.depth_step_bias < 0.0f || r.depth_step_bias > SSAO_MAX_DEPTH_STEP_BIAS)
        return fail(why, SSAO_ERROR_INVALID_VALUE,
                    "depth_step_bias must be finite and in [0, " + bound(SSAO_MAX_DEPTH_STEP_BIAS) + "]");
    if (r.depth_step_bias == 0.0f) r.depth_step_bias = kDefaultDepthStepBias;

    // A denormal power would reach a GPU's shader as 0, and pow(0, 0) is NaN there.
    if (!finite(r.power) || r.power < 0.0f || r.power > SSAO_MAX_POWER ||
        (r.power != 0.0f && r.power < std::numeric_limits<float>::min()))
        return fail(why, SSAO_ERROR_INVALID_VALUE,
                    "power must be finite and in [" + bound(std::numeric_limits<float>::min()) + ", " +
                        bound(SSAO_MAX_POWER) + "] (a normal float)");
    if (r.power == 0.0f) r.power = kDefaultPower;

    if (!finite(r.strength) || (r.strength != SSAO_STRENGTH_OFF && (r.strength < 0.0f || r.strength > SSAO_MAX_STRENGTH)))
        return fail(why, SSAO_ERROR_INVALID_VALUE, "strength must be in [0, " + bound(SSAO_MAX_STRENGTH) +
                                                       "] (0 = default " + bound(kDefaultStrength) +
                                                       ") or SSAO_STRENGTH_OFF");
    if (r.strength == 0.0f) r.strength = kDefaultStrength;
    return SSAO_OK;
}

// The kernel's shape and spread, and how it turns from pixel to pixel.
ssao_status resolve_kernel(ssao_settings& r, const PresetRow& defaults, std::string& why) {
    if (!raw_enum_at_most(r.kernel_shape, SSAO_KERNEL_SEPARABLE))
        return fail(why, SSAO_ERROR_INVALID_ENUM, "kernel_shape is not an ssao_kernel_shape");
    if (r.kernel_shape == SSAO_KERNEL_DEFAULT) r.kernel_shape = SSAO_KERNEL_HEMISPHERE;

    if (!raw_enum_at_most(r.distribution, SSAO_DISTRIBUTION_UNIFORM))
        return fail(why, SSAO_ERROR_INVALID_ENUM, "distribution is not an ssao_kernel_distribution");
    if (r.distribution == SSAO_DISTRIBUTION_DEFAULT) r.distribution = defaults.distribution;

    if (!raw_enum_at_most(r.rotation, SSAO_ROTATION_GRADIENT_NOISE))
        return fail(why, SSAO_ERROR_INVALID_ENUM, "rotation is not an ssao_rotation");
    // The chapter's kernel keeps its 4x4 tile, which its 4x4 box blur averages
    // out exactly; the march's directions turn by gradient noise, which the
    // depth-aware blur and the upsample average better than the tile's 16
    // random angles (docs/api.md, "Rotation").
    if (r.rotation == SSAO_ROTATION_DEFAULT)
        r.rotation = r.method == SSAO_METHOD_KERNEL ? SSAO_ROTATION_NOISE_4X4 : SSAO_ROTATION_GRADIENT_NOISE;

    if (r.seed == 0) r.seed = kDefaultSeed;
    return SSAO_OK;
}

// The blur and the library's own output texture.
ssao_status resolve_blur_and_output(ssao_settings& r, const PresetRow& defaults, std::string& why) {
    if (!raw_enum_at_most(r.blur, SSAO_BLUR_NONE))
        return fail(why, SSAO_ERROR_INVALID_ENUM, "blur is not an ssao_blur");
    if (r.blur == SSAO_BLUR_DEFAULT) r.blur = defaults.blur;

    if (r.blur_radius == 0) r.blur_radius = kDefaultBlurRadius;
    if (r.blur_radius > SSAO_MAX_BLUR_RADIUS)
        return fail(why, SSAO_ERROR_INVALID_VALUE,
                    "blur_radius " + std::to_string(r.blur_radius) + " is outside 1.." + std::to_string(SSAO_MAX_BLUR_RADIUS));

    if (!finite(r.blur_sigma) || r.blur_sigma < 0.0f || r.blur_sigma > SSAO_MAX_BLUR_SIGMA)
        return fail(why, SSAO_ERROR_INVALID_VALUE,
                    "blur_sigma must be finite and in (0, " + bound(SSAO_MAX_BLUR_SIGMA) + "]");
    if (r.blur_sigma == 0.0f) r.blur_sigma = static_cast<float>(r.blur_radius);

    if (!finite(r.blur_depth_tolerance) || r.blur_depth_tolerance < 0.0f || r.blur_depth_tolerance > 1.0f)
        return fail(why, SSAO_ERROR_INVALID_VALUE, "blur_depth_tolerance must be finite and in (0, 1]");
    if (r.blur_depth_tolerance == 0.0f) r.blur_depth_tolerance = kDefaultBlurTolerance;

    if (!raw_enum_at_most(r.output_format, SSAO_OUTPUT_R16F))
        return fail(why, SSAO_ERROR_INVALID_ENUM, "output_format is not an ssao_output_format");
    if (r.output_format == SSAO_OUTPUT_DEFAULT) r.output_format = SSAO_OUTPUT_R8;
    return SSAO_OK;
}

// What follows from the radius (bias, thickness), the march's steps and the grid.
ssao_status resolve_march(ssao_settings& r, const PresetRow& defaults, std::string& why) {
    if (!finite(r.bias) || r.bias < 0.0f)
        return fail(why, SSAO_ERROR_INVALID_VALUE, "bias must be a finite number >= 0");
    // The derived bias must stay > 0 as the header promises: for a tiny
    // (denormal) radius the product underflows to 0 or to a denormal, which
    // shaders flush to 0, so it is raised to the smallest normal float.
    if (r.bias == 0.0f)
        r.bias = std::max((r.method == SSAO_METHOD_VISIBILITY ? kDefaultVisibilityBiasFraction : kDefaultBiasFraction) *
                              r.radius,
                          std::numeric_limits<float>::min());

    if (!finite(r.thickness) || r.thickness < 0.0f)
        return fail(why, SSAO_ERROR_INVALID_VALUE, "thickness must be a finite number > 0");
    if (r.step_count == 0) r.step_count = defaults.step_count;
    if (r.step_count > SSAO_MAX_STEPS)
        return fail(why, SSAO_ERROR_INVALID_VALUE,
                    "step_count " + std::to_string(r.step_count) + " is outside 1.." + std::to_string(SSAO_MAX_STEPS));
    // Held to a normal, finite float: a tiny radius would derive a denormal
    // (0 in the shader), a radius near FLT_MAX an infinite thickness that
    // the settings, handed back, would refuse.
    if (r.thickness == 0.0f)
        r.thickness = std::clamp(default_thickness(r.radius, r.step_count), std::numeric_limits<float>::min(),
                                 std::numeric_limits<float>::max());
    // A denormal would reach the shader as 0 (flushed), which reads as off.
    if (!finite(r.max_step_texels) || r.max_step_texels < 0.0f || r.max_step_texels > SSAO_MAX_STEP_TEXELS ||
        (r.max_step_texels != 0.0f && r.max_step_texels < std::numeric_limits<float>::min()))
        return fail(why, SSAO_ERROR_INVALID_VALUE,
                    "max_step_texels must be 0 (off) or in [1.2e-38, " + bound(SSAO_MAX_STEP_TEXELS) +
                        "] (a normal float)");

    if (!raw_enum_at_most(r.resolution, SSAO_RESOLUTION_QUARTER))
        return fail(why, SSAO_ERROR_INVALID_ENUM, "resolution is not an ssao_resolution");
    if (r.resolution == SSAO_RESOLUTION_DEFAULT) r.resolution = defaults.resolution;
    return SSAO_OK;
}

// Distance fade, radius in pixels, debug view: off unless set.
ssao_status resolve_extras(ssao_settings& r, const PresetRow&, std::string& why) {
    // Distance fade: off (both zero) or 0 <= fade_start < fade_end < inf.
    if (!finite(r.fade_start) || !finite(r.fade_end) || r.fade_start < 0.0f || r.fade_end < 0.0f)
        return fail(why, SSAO_ERROR_INVALID_VALUE, "fade_start and fade_end must be finite and >= 0");
    if (r.fade_end == 0.0f && r.fade_start != 0.0f)
        return fail(why, SSAO_ERROR_INVALID_VALUE, "fade_start is set but fade_end is 0 (no fade)");
    if (r.fade_end != 0.0f && !(r.fade_start < r.fade_end))
        return fail(why, SSAO_ERROR_INVALID_VALUE, "fade_end must be greater than fade_start");

    if (!finite(r.radius_pixels) || r.radius_pixels < 0.0f || r.radius_pixels > static_cast<float>(SSAO_MAX_DIMENSION))
        return fail(why, SSAO_ERROR_INVALID_VALUE, "radius_pixels must be finite and in [0, " + std::to_string(SSAO_MAX_DIMENSION) + "] (0 = off)");

    if (!raw_enum_at_most(r.debug_view, SSAO_DEBUG_VIEW_BLUR_WEIGHTS))
        return fail(why, SSAO_ERROR_INVALID_ENUM, "debug_view is not an ssao_debug_view");
    return SSAO_OK;
}

}  // namespace

ssao_status resolve_settings(const ssao_settings& caller, ssao_settings& out, std::string& why) {
    if (!is_known_size<ssao_settings>(caller.size))
        return fail(why, SSAO_ERROR_STRUCT_SIZE,
                    "ssao_settings.size is " + std::to_string(caller.size) + ", expected " +
                        std::to_string(sizeof(ssao_settings)) + " (or " + std::to_string(SSAO_SETTINGS_SIZE_1_2) +
                        " for interfaces 1.2 and 1.3, " + std::to_string(SSAO_SETTINGS_SIZE_1_1) + " for 1.1, " +
                        std::to_string(SSAO_SETTINGS_SIZE_1_0) + " for 1.0)");
    ssao_settings r = read_prefix(caller);

    // The method first: the defaults of the fields a preset sets depend on it.
    if (!raw_enum_at_most(r.method, SSAO_METHOD_VISIBILITY))
        return fail(why, SSAO_ERROR_INVALID_ENUM, "method is not an ssao_method");
    if (r.method == SSAO_METHOD_DEFAULT) r.method = preset_row(SSAO_PRESET_DEFAULT).method;
    const PresetRow& defaults = defaults_for_method(r.method);
    // In this order, so a struct with several bad fields names the same one every time.
    for (auto step : {resolve_amounts, resolve_kernel, resolve_blur_and_output, resolve_march, resolve_extras})
        if (const ssao_status st = step(r, defaults, why); st != SSAO_OK) return st;
    out = r;
    return SSAO_OK;
}

ssao_status preset_settings(uint32_t raw_preset, ssao_settings& out, std::string& why) {
    if (raw_preset > SSAO_PRESET_CHAPTER) return fail(why, SSAO_ERROR_INVALID_ENUM, "preset is not an ssao_preset");
    const PresetRow& row = preset_row(static_cast<ssao_preset>(raw_preset));
    // Only the row's fields: every other one stays 0 (its default), so the
    // fields derived from the radius (bias, thickness) follow whatever radius
    // the host sets afterwards instead of the default radius's.
    ssao_settings s{};
    s.size = sizeof(ssao_settings);
    s.method = row.method;
    s.sample_count = row.sample_count;
    s.step_count = row.step_count;
    s.distribution = row.distribution;
    s.blur = row.blur;
    s.resolution = row.resolution;
    out = s;
    return SSAO_OK;
}

}  // namespace ssao_impl
