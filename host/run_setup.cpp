// run_setup.cpp - see run_setup.h. Moved out of host/main.cpp so that
// ssao-host and ssao-viewer start from the same scene, settings and camera.
#include "run_setup.h"


#include <algorithm>
#include <cfloat>
#include <cmath>
#include <sstream>

namespace run_setup {

namespace {

std::string fmt(double v) {
    std::ostringstream s;
    s.precision(4);
    s << v;
    return s.str();
}

}  // namespace

// Precedence: flags > scene hints > preset > plugin defaults. The radius is
// scene-scaled (scene::ao_radius: the scene's hint, else 0.05 x its diagonal).
ssao_settings build_settings(const ssao_api& api, const cli::Options& o, const scene::Scene& sc, std::string& radius_note) {
    ssao_settings s{};
    s.size = sizeof(ssao_settings);
    if (o.preset) {
        const ssao_status st = api.preset_settings(*o.preset, &s);
        if (st != SSAO_OK) throw Error(std::string("the plugin refused the preset: ") + api.status_string(st));
    }
    const scene::AoHints& h = sc.hints;
    if (const std::string problem = scene::radius_hint_problem(h); !problem.empty()) throw Error(problem);
    if (const auto r = scene::ao_radius(sc)) {
        s.radius = r->radius;
        radius_note = r->source;
    } else {
        radius_note = "plugin default; the scene has no extent";
    }
    if (h.samples) {
        if (!(*h.samples >= 1 && *h.samples <= SSAO_MAX_SAMPLES && *h.samples == std::floor(*h.samples)))
            throw Error("the scene's hint ssao.samples = " + fmt(*h.samples) + " is not a whole number in 1..64");
        s.sample_count = static_cast<uint32_t>(*h.samples);
    }
    if (h.blur) {
        const auto b = cli::parse_blur(*h.blur);
        if (!b) throw Error("the scene's hint ssao.blur = '" + *h.blur + "' is not depth-aware|box|gaussian|none");
        s.blur = *b;
    }
    // Scene units within 32-bit float range: a larger number would become inf.
    const double float_max = FLT_MAX;
    if (h.bias) {
        if (!(*h.bias >= 0.0 && *h.bias <= float_max))
            throw Error("the scene's hint ssao.bias = " + fmt(*h.bias) + " is not a number >= 0 (at most 3.4e38)");
        // 0 (or a positive bias below float's range) is the smallest bias, not the default.
        s.bias = std::max(static_cast<float>(*h.bias), FLT_MIN);
    }
    if (h.power) {
        if (!(*h.power >= FLT_MIN && *h.power <= SSAO_MAX_POWER))  // below: 0 (the default) or a denormal
            throw Error("the scene's hint ssao.power = " + fmt(*h.power) + " is out of range [" + fmt(FLT_MIN) + ", " +
                        fmt(SSAO_MAX_POWER) + "]");
        s.power = static_cast<float>(*h.power);
    }
    if (h.fade_start) {
        if (!(*h.fade_start >= 0.0 && *h.fade_start <= float_max))
            throw Error("the scene's hint ssao.fade_start = " + fmt(*h.fade_start) + " is not a number >= 0 (at most 3.4e38)");
        s.fade_start = static_cast<float>(*h.fade_start);
    }
    if (h.fade_end) {
        if (!(*h.fade_end >= 0.0 && *h.fade_end <= float_max))
            throw Error("the scene's hint ssao.fade_end = " + fmt(*h.fade_end) + " is not a number >= 0 (at most 3.4e38)");
        s.fade_end = static_cast<float>(*h.fade_end);
    }
    if (h.radius_pixels) {
        if (!(*h.radius_pixels >= 0.0 && *h.radius_pixels <= SSAO_MAX_DIMENSION))
            throw Error("the scene's hint ssao.radius_pixels = " + fmt(*h.radius_pixels) + " is out of range [0, 16384]");
        s.radius_pixels = static_cast<float>(*h.radius_pixels);
    }
    // Flags. A zero field means "default" in the ABI, so an explicit 0 for a
    // bias becomes the smallest positive float and strength 0 SSAO_STRENGTH_OFF.
    if (o.samples) s.sample_count = static_cast<uint32_t>(*o.samples);
    if (o.radius) {
        s.radius = *o.radius;
        radius_note = "--radius";
    }
    if (o.bias) s.bias = *o.bias > 0.0f ? *o.bias : FLT_MIN;
    if (o.depth_step_bias) s.depth_step_bias = *o.depth_step_bias > 0.0f ? *o.depth_step_bias : FLT_MIN;
    if (o.power) s.power = *o.power;
    if (o.strength) s.strength = *o.strength > 0.0f ? *o.strength : SSAO_STRENGTH_OFF;
    if (o.kernel) s.kernel_shape = *o.kernel;
    if (o.distribution) s.distribution = *o.distribution;
    if (o.rotation) s.rotation = *o.rotation;
    if (o.seed) s.seed = *o.seed;
    if (o.blur) s.blur = *o.blur;
    if (o.blur_radius) s.blur_radius = static_cast<uint32_t>(*o.blur_radius);
    if (o.blur_sigma) s.blur_sigma = *o.blur_sigma;
    if (o.blur_tolerance) s.blur_depth_tolerance = *o.blur_tolerance;
    if (o.output_format) s.output_format = *o.output_format;
    if (o.resolution) s.resolution = *o.resolution;
    if (o.method) s.method = *o.method;
    if (o.thickness) s.thickness = *o.thickness;
    if (o.steps) s.step_count = static_cast<uint32_t>(*o.steps);
    if (o.max_step_texels) s.max_step_texels = *o.max_step_texels;
    // The fade: a flag replaces its end of the hint's range; --fade-end 0
    // (no fade) drops a hinted start too, so it always turns the fade off.
    if (o.fade_start) s.fade_start = *o.fade_start;
    if (o.fade_end) s.fade_end = *o.fade_end;
    if (o.fade_end && *o.fade_end == 0.0f && !o.fade_start) s.fade_start = 0.0f;
    if (o.radius_pixels) s.radius_pixels = *o.radius_pixels;
    // Hints and flags meet here, so say which range is wrong before the
    // plugin's resolve_settings (which has no context to explain it) refuses it.
    if (s.fade_end == 0.0f && s.fade_start != 0.0f)
        throw Error("the fade start " + fmt(s.fade_start) + " has no fade end (--fade-end or the scene's hint ssao.fade_end)");
    if (s.fade_end != 0.0f && !(s.fade_start < s.fade_end))
        throw Error("fade_end must be greater than fade_start: the fade runs " + fmt(s.fade_start) + " .. " +
                    fmt(s.fade_end) + " (flags --fade-start/--fade-end or the scene's hints)");

    ssao_settings resolved{};
    resolved.size = sizeof(ssao_settings);
    const ssao_status st = api.resolve_settings(&s, &resolved);
    if (st != SSAO_OK)
        throw Error(std::string("the SSAO settings are invalid: ") + api.status_string(st));
    return resolved;
}

camera::Camera build_camera(const cli::Options& o, const scene::Scene& sc, float aspect, camera::Source& source) {
    return camera::initial(sc, aspect, o.cam, o.scene_path.empty(), &source);
}

}  // namespace run_setup
