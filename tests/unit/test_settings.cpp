// test_settings.cpp - resolution and validation of ssao_settings and the
// presets (plugin/settings.h), against the field documentation in ssao.h.
#include "presets.h"
#include "settings.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

using ssao_impl::preset_settings;
using ssao_impl::resolve_settings;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

ssao_settings zeroed() {
    ssao_settings s;
    std::memset(&s, 0, sizeof s);
    s.size = sizeof s;
    return s;
}

// An `out` full of a recognisable pattern, to see whether a call touched it.
ssao_settings sentinel() {
    ssao_settings s;
    std::memset(&s, 0xA5, sizeof s);
    s.size = sizeof s;
    return s;
}

bool same(const ssao_settings& a, const ssao_settings& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Writes an arbitrary 32-bit value into an enum field without an
// out-of-range enum conversion (which C++17 leaves undefined).
template <typename E>
void set_raw(E& field, int32_t value) {
    static_assert(sizeof(E) == sizeof(int32_t), "enum fields are 4 bytes");
    std::memcpy(&field, &value, sizeof value);
}

ssao_settings resolve_ok(const ssao_settings& in) {
    ssao_settings out = sentinel();
    std::string why;
    const ssao_status st = resolve_settings(in, out, why);
    CAPTURE(why);
    REQUIRE(st == SSAO_OK);
    return out;
}

struct BadCase {
    const char* what;
    std::function<void(ssao_settings&)> edit;
    ssao_status expected;
};

}  // namespace

TEST_CASE("settings: a zeroed struct resolves to the documented defaults: the DEFAULT preset") {
    const ssao_settings r = resolve_ok(zeroed());
    const ssao_impl::PresetRow& def = ssao_impl::preset_row(SSAO_PRESET_DEFAULT);
    CHECK(r.size == sizeof(ssao_settings));
    CHECK(r.method == def.method);
    CHECK(r.sample_count == def.sample_count);
    CHECK(r.step_count == def.step_count);
    CHECK(r.distribution == def.distribution);
    CHECK(r.blur == def.blur);
    ssao_settings preset{};
    std::string why;
    REQUIRE(preset_settings(SSAO_PRESET_DEFAULT, preset, why) == SSAO_OK);
    CHECK(same(r, resolve_ok(preset)));
    CHECK(r.radius == 0.5f);
    CHECK(r.bias == doctest::Approx((def.method == SSAO_METHOD_VISIBILITY ? 0.0025 : 0.025) * 0.5));
    CHECK(r.depth_step_bias == 2.0f);
    CHECK(r.power == 1.0f);
    CHECK(r.strength == 1.0f);
    CHECK(r.kernel_shape == SSAO_KERNEL_HEMISPHERE);
    CHECK(r.rotation == (def.method == SSAO_METHOD_KERNEL ? SSAO_ROTATION_NOISE_4X4 : SSAO_ROTATION_GRADIENT_NOISE));
    CHECK(r.seed == 1u);
    CHECK(r.blur_radius == 2u);
    CHECK(r.blur_sigma == 2.0f);
    CHECK(r.blur_depth_tolerance == doctest::Approx(0.05));
    CHECK(r.output_format == SSAO_OUTPUT_R8);
    CHECK(r.resolution == def.resolution);
    CHECK(r.resolution != SSAO_RESOLUTION_DEFAULT);  // resolved, never the zero that means default
    CHECK(r.max_step_texels == 0.0f);  // off
}

TEST_CASE("settings: resolution keeps each named value and maps it to its grid scale") {
    const struct {
        ssao_resolution value;
        int scale;
    } cases[] = {{SSAO_RESOLUTION_FULL, 1}, {SSAO_RESOLUTION_HALF, 2}, {SSAO_RESOLUTION_QUARTER, 4}};
    for (const auto& c : cases) {
        CAPTURE(int(c.value));
        ssao_settings in = zeroed();
        in.resolution = c.value;
        const ssao_settings r = resolve_ok(in);
        CHECK(r.resolution == c.value);
        CHECK(ssao_impl::resolution_scale(r) == c.scale);
    }
    // The default is the DEFAULT preset's resolution.
    const ssao_resolution def = ssao_impl::preset_row(SSAO_PRESET_DEFAULT).resolution;
    CHECK(ssao_impl::resolution_scale(resolve_ok(zeroed())) ==
          (def == SSAO_RESOLUTION_QUARTER ? 4 : def == SSAO_RESOLUTION_HALF ? 2 : 1));
}

TEST_CASE("settings: setting only the kernel method gives the chapter's configuration") {
    ssao_settings in = zeroed();
    in.method = SSAO_METHOD_KERNEL;
    const ssao_settings r = resolve_ok(in);
    if (ssao_impl::preset_row(SSAO_PRESET_DEFAULT).method != SSAO_METHOD_KERNEL) {
        CHECK(r.sample_count == 64u);
        CHECK(r.distribution == SSAO_DISTRIBUTION_ACCELERATING);
        CHECK(r.blur == SSAO_BLUR_BOX_4X4);
    }
    CHECK(r.kernel_shape == SSAO_KERNEL_HEMISPHERE);
    CHECK(r.rotation == SSAO_ROTATION_NOISE_4X4);  // the chapter's tile, which its 4x4 box averages out
    CHECK(r.bias == doctest::Approx(0.025 * 0.5));
}

TEST_CASE("settings: derived defaults follow the fields they derive from") {
    ssao_settings in = zeroed();
    in.method = SSAO_METHOD_KERNEL;
    in.radius = 2.0f;
    in.blur_radius = 5;
    const ssao_settings r = resolve_ok(in);
    CHECK(r.radius == 2.0f);
    CHECK(r.bias == doctest::Approx(0.025 * 2.0));  // 0.025 * radius
    CHECK(r.blur_radius == 5u);
    CHECK(r.blur_sigma == 5.0f);  // = blur_radius
    CHECK(r.thickness == doctest::Approx(2.0 * (0.5 + 1.5 / r.step_count)));  // radius (0.5 + 1.5 / steps)

    // Explicit values are kept as given.
    in = zeroed();
    in.sample_count = 64;
    in.radius = 0.25f;
    in.bias = 0.5f;
    in.depth_step_bias = 7.0f;
    in.power = 16.0f;
    in.strength = 8.0f;
    in.kernel_shape = SSAO_KERNEL_SPHERE;
    in.distribution = SSAO_DISTRIBUTION_UNIFORM;
    in.rotation = SSAO_ROTATION_NONE;
    in.seed = 0xffffffffu;
    in.blur = SSAO_BLUR_NONE;
    in.blur_radius = 16;
    in.blur_sigma = 64.0f;
    in.blur_depth_tolerance = 1.0f;
    in.output_format = SSAO_OUTPUT_R16F;
    in.method = SSAO_METHOD_VISIBILITY;
    in.thickness = 3.0f;
    in.step_count = SSAO_MAX_STEPS;
    in.resolution = SSAO_RESOLUTION_QUARTER;
    in.max_step_texels = 1e6f;
    CHECK(same(resolve_ok(in), in));

    // The smallest accepted values.
    in = zeroed();
    in.sample_count = 1;
    in.blur_radius = 1;
    in.radius = 1e-6f;
    in.power = 1e-6f;
    in.blur_sigma = 1e-6f;
    in.blur_depth_tolerance = 1e-6f;
    const ssao_settings small = resolve_ok(in);
    CHECK(small.sample_count == 1u);
    CHECK(small.blur_radius == 1u);
    CHECK(small.radius == 1e-6f);
    CHECK(small.power == 1e-6f);
    CHECK(small.blur_sigma == 1e-6f);
    CHECK(small.blur_depth_tolerance == 1e-6f);
}

TEST_CASE("settings: the derived bias stays a normal float > 0 for a tiny radius") {
    // 0.025 x a denormal radius underflowed to bias 0 before, against the header's "bias > 0".
    for (float radius : {1e-45f, 1e-40f, std::numeric_limits<float>::min(), 1e-37f}) {
        CAPTURE(radius);
        ssao_settings in = zeroed();
        in.radius = radius;
        const ssao_settings out = resolve_ok(in);
        CHECK(out.radius == radius);
        CHECK(out.bias >= std::numeric_limits<float>::min());
        CHECK(std::isnormal(out.bias));
    }
    ssao_settings in = zeroed();
    in.method = SSAO_METHOD_KERNEL;
    in.radius = 2.0f;
    CHECK(resolve_ok(in).bias == doctest::Approx(0.05f));  // ordinary radii keep 0.025 x radius
}

TEST_CASE("settings: a radius near FLT_MAX derives a finite thickness, and the result resolves again") {
    for (uint32_t steps : {1u, 4u}) {
        CAPTURE(steps);
        ssao_settings in = zeroed();
        in.radius = std::numeric_limits<float>::max();
        in.step_count = steps;
        const ssao_settings out = resolve_ok(in);
        CHECK(std::isfinite(out.thickness));
        CHECK(out.thickness > 0.0f);
        CHECK(same(resolve_ok(out), out));
    }
}

TEST_CASE("settings: the header's bounds are the accepted maxima") {
    const auto above = [](float v) { return std::nextafter(v, std::numeric_limits<float>::infinity()); };
    ssao_settings in = zeroed();
    in.power = SSAO_MAX_POWER;
    in.strength = SSAO_MAX_STRENGTH;
    in.blur_sigma = SSAO_MAX_BLUR_SIGMA;
    in.depth_step_bias = SSAO_MAX_DEPTH_STEP_BIAS;
    in.max_step_texels = SSAO_MAX_STEP_TEXELS;
    const ssao_settings out = resolve_ok(in);
    CHECK(out.power == 16.0f);  // the documented numbers
    CHECK(out.strength == 8.0f);
    CHECK(out.blur_sigma == 64.0f);
    CHECK(out.depth_step_bias == 1e6f);
    CHECK(out.max_step_texels == 1e6f);
    const std::pair<const char*, float ssao_settings::*> fields[] = {
        {"power", &ssao_settings::power},
        {"strength", &ssao_settings::strength},
        {"blur_sigma", &ssao_settings::blur_sigma},
        {"depth_step_bias", &ssao_settings::depth_step_bias},
        {"max_step_texels", &ssao_settings::max_step_texels},
    };
    for (const auto& entry : fields) {
        const std::string name = entry.first;  // a plain variable: CAPTURE's lambda cannot take a structured binding
        const auto field = entry.second;
        CAPTURE(name);
        ssao_settings bad = in;
        bad.*field = above(in.*field);
        ssao_settings untouched = zeroed();
        std::string why;
        CHECK(ssao_impl::resolve_settings(bad, untouched, why) == SSAO_ERROR_INVALID_VALUE);
        CHECK(why.find(name) != std::string::npos);
    }
}

TEST_CASE("settings: SSAO_STRENGTH_OFF is accepted and stays off") {
    ssao_settings in = zeroed();
    in.strength = SSAO_STRENGTH_OFF;
    const ssao_settings r = resolve_ok(in);
    CHECK(r.strength == SSAO_STRENGTH_OFF);
    CHECK(ssao_impl::effective_strength(r) == 0.0f);
    const ssao_settings rr = resolve_ok(r);
    CHECK(rr.strength == SSAO_STRENGTH_OFF);
    CHECK(same(r, rr));
}

TEST_CASE("settings: resolve is idempotent") {
    std::mt19937 rng(1234);
    auto pick = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    auto real = [&](float lo, float hi) {
        // A quarter of the draws leave the field zero (= default).
        return pick(0, 3) == 0 ? 0.0f : std::uniform_real_distribution<float>(lo, hi)(rng);
    };
    for (int trial = 0; trial < 2000; ++trial) {
        ssao_settings in = zeroed();
        in.sample_count = static_cast<uint32_t>(pick(0, 64));
        in.radius = real(1e-3f, 10.0f);
        in.bias = real(0.0f, 1.0f);
        in.depth_step_bias = real(0.0f, 10.0f);
        in.power = real(1e-3f, 16.0f);
        in.strength = pick(0, 4) == 0 ? SSAO_STRENGTH_OFF : real(0.0f, 8.0f);
        set_raw(in.kernel_shape, pick(0, 3));
        set_raw(in.distribution, pick(0, 2));
        set_raw(in.rotation, pick(0, 4));
        in.seed = static_cast<uint32_t>(pick(0, 1 << 30));
        set_raw(in.blur, pick(0, 4));
        in.blur_radius = static_cast<uint32_t>(pick(0, 16));
        in.blur_sigma = real(1e-3f, 64.0f);
        in.blur_depth_tolerance = real(1e-3f, 1.0f);
        set_raw(in.output_format, pick(0, 2));
        in.max_step_texels = real(0.25f, 1e6f);
        CAPTURE(trial);
        const ssao_settings once = resolve_ok(in);
        const ssao_settings twice = resolve_ok(once);
        CHECK(same(once, twice));
        // Resolved settings hold no zero that means "default".
        CHECK(once.sample_count != 0u);
        CHECK(once.radius > 0.0f);
        CHECK(once.bias > 0.0f);
        CHECK(once.depth_step_bias > 0.0f);
        CHECK(once.power > 0.0f);
        CHECK(once.strength != 0.0f);
        CHECK(once.kernel_shape != SSAO_KERNEL_DEFAULT);
        CHECK(once.distribution != SSAO_DISTRIBUTION_DEFAULT);
        CHECK(once.rotation != SSAO_ROTATION_DEFAULT);
        CHECK(once.seed != 0u);
        CHECK(once.blur != SSAO_BLUR_DEFAULT);
        CHECK(once.blur_radius != 0u);
        CHECK(once.blur_sigma > 0.0f);
        CHECK(once.blur_depth_tolerance > 0.0f);
        CHECK(once.output_format != SSAO_OUTPUT_DEFAULT);
        CHECK(once.max_step_texels == in.max_step_texels);  // 0 = off stays 0, like fade_end
    }
    const ssao_settings z = resolve_ok(zeroed());
    CHECK(same(resolve_ok(z), z));
}

TEST_CASE("settings: every invalid field gives its documented status and leaves out untouched") {
    std::vector<BadCase> cases = {
        {"sample_count 65", [](ssao_settings& s) { s.sample_count = 65; }, SSAO_ERROR_INVALID_VALUE},
        {"sample_count 1000", [](ssao_settings& s) { s.sample_count = 1000; }, SSAO_ERROR_INVALID_VALUE},
        {"sample_count max", [](ssao_settings& s) { s.sample_count = 0xffffffffu; }, SSAO_ERROR_INVALID_VALUE},
        {"radius -1", [](ssao_settings& s) { s.radius = -1.0f; }, SSAO_ERROR_INVALID_VALUE},
        {"radius NaN", [](ssao_settings& s) { s.radius = kNaN; }, SSAO_ERROR_INVALID_VALUE},
        {"radius inf", [](ssao_settings& s) { s.radius = kInf; }, SSAO_ERROR_INVALID_VALUE},
        {"radius -inf", [](ssao_settings& s) { s.radius = -kInf; }, SSAO_ERROR_INVALID_VALUE},
        {"bias -0.1", [](ssao_settings& s) { s.bias = -0.1f; }, SSAO_ERROR_INVALID_VALUE},
        {"bias NaN", [](ssao_settings& s) { s.bias = kNaN; }, SSAO_ERROR_INVALID_VALUE},
        {"bias inf", [](ssao_settings& s) { s.bias = kInf; }, SSAO_ERROR_INVALID_VALUE},
        {"depth_step_bias -1", [](ssao_settings& s) { s.depth_step_bias = -1.0f; }, SSAO_ERROR_INVALID_VALUE},
        {"depth_step_bias NaN", [](ssao_settings& s) { s.depth_step_bias = kNaN; }, SSAO_ERROR_INVALID_VALUE},
        {"depth_step_bias inf", [](ssao_settings& s) { s.depth_step_bias = kInf; }, SSAO_ERROR_INVALID_VALUE},
        {"power -1", [](ssao_settings& s) { s.power = -1.0f; }, SSAO_ERROR_INVALID_VALUE},
        {"power 16.5", [](ssao_settings& s) { s.power = 16.5f; }, SSAO_ERROR_INVALID_VALUE},
        {"power NaN", [](ssao_settings& s) { s.power = kNaN; }, SSAO_ERROR_INVALID_VALUE},
        {"power inf", [](ssao_settings& s) { s.power = kInf; }, SSAO_ERROR_INVALID_VALUE},
        {"power denormal", [](ssao_settings& s) { s.power = 1e-40f; }, SSAO_ERROR_INVALID_VALUE},
        {"strength -0.5", [](ssao_settings& s) { s.strength = -0.5f; }, SSAO_ERROR_INVALID_VALUE},
        {"strength -2", [](ssao_settings& s) { s.strength = -2.0f; }, SSAO_ERROR_INVALID_VALUE},
        {"strength 8.5", [](ssao_settings& s) { s.strength = 8.5f; }, SSAO_ERROR_INVALID_VALUE},
        {"strength NaN", [](ssao_settings& s) { s.strength = kNaN; }, SSAO_ERROR_INVALID_VALUE},
        {"strength inf", [](ssao_settings& s) { s.strength = kInf; }, SSAO_ERROR_INVALID_VALUE},
        {"kernel_shape 4", [](ssao_settings& s) { set_raw(s.kernel_shape, 4); }, SSAO_ERROR_INVALID_ENUM},
        {"kernel_shape -1", [](ssao_settings& s) { set_raw(s.kernel_shape, -1); }, SSAO_ERROR_INVALID_ENUM},
        {"distribution 3", [](ssao_settings& s) { set_raw(s.distribution, 3); }, SSAO_ERROR_INVALID_ENUM},
        {"distribution -1", [](ssao_settings& s) { set_raw(s.distribution, -1); }, SSAO_ERROR_INVALID_ENUM},
        {"rotation 5", [](ssao_settings& s) { set_raw(s.rotation, 5); }, SSAO_ERROR_INVALID_ENUM},
        {"rotation -1", [](ssao_settings& s) { set_raw(s.rotation, -1); }, SSAO_ERROR_INVALID_ENUM},
        {"blur 5", [](ssao_settings& s) { set_raw(s.blur, 5); }, SSAO_ERROR_INVALID_ENUM},
        {"blur -1", [](ssao_settings& s) { set_raw(s.blur, -1); }, SSAO_ERROR_INVALID_ENUM},
        {"blur 0x7fffffff", [](ssao_settings& s) { set_raw(s.blur, 0x7fffffff); }, SSAO_ERROR_INVALID_ENUM},
        {"blur_radius 17", [](ssao_settings& s) { s.blur_radius = 17; }, SSAO_ERROR_INVALID_VALUE},
        {"blur_radius max", [](ssao_settings& s) { s.blur_radius = 0xffffffffu; }, SSAO_ERROR_INVALID_VALUE},
        {"blur_sigma -1", [](ssao_settings& s) { s.blur_sigma = -1.0f; }, SSAO_ERROR_INVALID_VALUE},
        {"blur_sigma 64.5", [](ssao_settings& s) { s.blur_sigma = 64.5f; }, SSAO_ERROR_INVALID_VALUE},
        {"blur_sigma NaN", [](ssao_settings& s) { s.blur_sigma = kNaN; }, SSAO_ERROR_INVALID_VALUE},
        {"blur_sigma inf", [](ssao_settings& s) { s.blur_sigma = kInf; }, SSAO_ERROR_INVALID_VALUE},
        {"blur_depth_tolerance -0.1", [](ssao_settings& s) { s.blur_depth_tolerance = -0.1f; },
         SSAO_ERROR_INVALID_VALUE},
        {"blur_depth_tolerance 1.5", [](ssao_settings& s) { s.blur_depth_tolerance = 1.5f; },
         SSAO_ERROR_INVALID_VALUE},
        {"blur_depth_tolerance NaN", [](ssao_settings& s) { s.blur_depth_tolerance = kNaN; },
         SSAO_ERROR_INVALID_VALUE},
        {"blur_depth_tolerance inf", [](ssao_settings& s) { s.blur_depth_tolerance = kInf; },
         SSAO_ERROR_INVALID_VALUE},
        {"output_format 3", [](ssao_settings& s) { set_raw(s.output_format, 3); }, SSAO_ERROR_INVALID_ENUM},
        {"output_format -1", [](ssao_settings& s) { set_raw(s.output_format, -1); }, SSAO_ERROR_INVALID_ENUM},
        {"method 3", [](ssao_settings& s) { set_raw(s.method, 3); }, SSAO_ERROR_INVALID_ENUM},
        {"method -1", [](ssao_settings& s) { set_raw(s.method, -1); }, SSAO_ERROR_INVALID_ENUM},
        {"thickness -1", [](ssao_settings& s) { s.thickness = -1.0f; }, SSAO_ERROR_INVALID_VALUE},
        {"thickness NaN", [](ssao_settings& s) { s.thickness = kNaN; }, SSAO_ERROR_INVALID_VALUE},
        {"thickness inf", [](ssao_settings& s) { s.thickness = kInf; }, SSAO_ERROR_INVALID_VALUE},
        {"step_count 33", [](ssao_settings& s) { s.step_count = 33; }, SSAO_ERROR_INVALID_VALUE},
        {"step_count max", [](ssao_settings& s) { s.step_count = 0xffffffffu; }, SSAO_ERROR_INVALID_VALUE},
        {"max_step_texels -1", [](ssao_settings& s) { s.max_step_texels = -1.0f; }, SSAO_ERROR_INVALID_VALUE},
        {"max_step_texels 1e7", [](ssao_settings& s) { s.max_step_texels = 1e7f; }, SSAO_ERROR_INVALID_VALUE},
        {"max_step_texels denormal", [](ssao_settings& s) { s.max_step_texels = 1e-40f; }, SSAO_ERROR_INVALID_VALUE},
        {"max_step_texels NaN", [](ssao_settings& s) { s.max_step_texels = kNaN; }, SSAO_ERROR_INVALID_VALUE},
        {"max_step_texels inf", [](ssao_settings& s) { s.max_step_texels = kInf; }, SSAO_ERROR_INVALID_VALUE},
        {"resolution 4", [](ssao_settings& s) { set_raw(s.resolution, 4); }, SSAO_ERROR_INVALID_ENUM},
        {"resolution -1", [](ssao_settings& s) { set_raw(s.resolution, -1); }, SSAO_ERROR_INVALID_ENUM},
        {"resolution max enum", [](ssao_settings& s) { set_raw(s.resolution, 0x7fffffff); },
         SSAO_ERROR_INVALID_ENUM},
        {"size 0", [](ssao_settings& s) { s.size = 0; }, SSAO_ERROR_STRUCT_SIZE},
        {"size - 2", [](ssao_settings& s) { s.size = sizeof(ssao_settings) - 2; }, SSAO_ERROR_STRUCT_SIZE},
        {"size + 4", [](ssao_settings& s) { s.size = sizeof(ssao_settings) + 4; }, SSAO_ERROR_STRUCT_SIZE},
    };
    for (const BadCase& c : cases) {
        const std::string what_ = c.what;
        CAPTURE(what_);
        // On a zeroed struct and on an otherwise fully specified one.
        for (int base = 0; base < 2; ++base) {
            ssao_settings in = base == 0 ? zeroed() : resolve_ok(zeroed());
            c.edit(in);
            ssao_settings out = sentinel();
            const ssao_settings before = out;
            std::string why;
            CHECK(resolve_settings(in, out, why) == c.expected);
            CHECK(same(out, before));
            CHECK_FALSE(why.empty());
        }
    }
}

TEST_CASE("settings: the message of a rejected field names the field") {
    ssao_settings in = zeroed();
    in.radius = kNaN;
    ssao_settings out = sentinel();
    std::string why;
    REQUIRE(resolve_settings(in, out, why) == SSAO_ERROR_INVALID_VALUE);
    CHECK(why.find("radius") != std::string::npos);
    in = zeroed();
    set_raw(in.blur, 9);
    why.clear();
    REQUIRE(resolve_settings(in, out, why) == SSAO_ERROR_INVALID_ENUM);
    CHECK(why.find("blur") != std::string::npos);
    in = zeroed();
    in.max_step_texels = kNaN;
    why.clear();
    REQUIRE(resolve_settings(in, out, why) == SSAO_ERROR_INVALID_VALUE);
    CHECK(why.find("max_step_texels") != std::string::npos);
}

TEST_CASE("settings: resolving in place works") {
    ssao_settings s = zeroed();
    s.method = SSAO_METHOD_KERNEL;
    s.sample_count = 16;
    s.radius = 3.0f;
    std::string why;
    REQUIRE(resolve_settings(s, s, why) == SSAO_OK);
    CHECK(s.radius == 3.0f);
    CHECK(s.sample_count == 16u);
    CHECK(s.bias == doctest::Approx(0.075));
}

TEST_CASE("settings: every preset resolves to the documented table") {
    const ssao_preset presets[] = {SSAO_PRESET_DEFAULT, SSAO_PRESET_LOW, SSAO_PRESET_MEDIUM, SSAO_PRESET_HIGH,
                                   SSAO_PRESET_ULTRA};
    ssao_settings got[5];
    for (int i = 0; i < 5; ++i) {
        CAPTURE(i);
        ssao_settings out = sentinel();
        std::string why;
        REQUIRE(preset_settings(presets[i], out, why) == SSAO_OK);
        CHECK(out.size == sizeof(ssao_settings));
        // Not resolved: what the radius derives stays 0 until the radius is known.
        CHECK(out.radius == 0.0f);
        CHECK(out.bias == 0.0f);
        CHECK(out.thickness == 0.0f);
        got[i] = resolve_ok(out);
    }
    const ssao_settings& def = got[0];
    const ssao_settings& low = got[1];
    const ssao_settings& medium = got[2];
    const ssao_settings& high = got[3];
    const ssao_settings& ultra = got[4];
    CHECK(same(def, medium));  // DEFAULT = MEDIUM
    // Each preset is its row of the table (plugin/presets.cpp), nothing else.
    const ssao_preset named[] = {SSAO_PRESET_LOW, SSAO_PRESET_MEDIUM, SSAO_PRESET_HIGH, SSAO_PRESET_ULTRA};
    for (int i = 0; i < 4; ++i) {
        CAPTURE(i);
        const ssao_impl::PresetRow& row = ssao_impl::preset_row(named[i]);
        const ssao_settings& p = got[i + 1];
        CHECK(p.method == row.method);
        CHECK(p.sample_count == row.sample_count);
        CHECK(p.step_count == row.step_count);
        CHECK(p.distribution == row.distribution);
        CHECK(p.blur == row.blur);
        CHECK(p.resolution == row.resolution);
    }
    // Cost grows from LOW to ULTRA: more samples (times steps) at each level.
    // Samples (times steps) per pixel sampled, times the pixels sampled (16 per 16 at full resolution).
    auto work = [](const ssao_settings& p) {
        const uint32_t pixels = p.resolution == SSAO_RESOLUTION_QUARTER ? 1u : p.resolution == SSAO_RESOLUTION_HALF ? 4u : 16u;
        return p.sample_count * (p.method == SSAO_METHOD_VISIBILITY ? p.step_count : 1u) * pixels;
    };
    CHECK(work(low) <= work(medium) * 4u);
    CHECK(work(medium) < work(high));
    CHECK(work(high) < work(ultra));
    // Presets change only the cost and accuracy fields; the rest stay defaults.
    const ssao_settings zero = resolve_ok(zeroed());
    for (const ssao_settings* p : {&low, &medium, &high, &ultra}) {
        CHECK(p->strength == 1.0f);
        CHECK(p->radius == zero.radius);
        CHECK(p->bias == doctest::Approx((p->method == SSAO_METHOD_VISIBILITY ? 0.0025 : 0.025) * zero.radius));
        CHECK(p->kernel_shape == zero.kernel_shape);
        CHECK(p->rotation == zero.rotation);
    }
}

TEST_CASE("settings: a preset plus a radius derives bias and thickness from that radius, as zeroed settings do") {
    const ssao_preset presets[] = {SSAO_PRESET_DEFAULT, SSAO_PRESET_LOW,   SSAO_PRESET_MEDIUM,
                                   SSAO_PRESET_HIGH,    SSAO_PRESET_ULTRA, SSAO_PRESET_CHAPTER};
    for (ssao_preset p : presets) {
        for (float radius : {0.05f, 1.0f, 40.0f}) {
            CAPTURE(int(p));
            CAPTURE(radius);
            ssao_settings taken{};
            std::string why;
            REQUIRE(preset_settings(p, taken, why) == SSAO_OK);
            taken.radius = radius;
            // The same row's fields on zeroed settings, and the same radius.
            const ssao_impl::PresetRow& row = ssao_impl::preset_row(p);
            ssao_settings by_hand = zeroed();
            by_hand.method = row.method;
            by_hand.sample_count = row.sample_count;
            by_hand.step_count = row.step_count;
            by_hand.distribution = row.distribution;
            by_hand.blur = row.blur;
            by_hand.resolution = row.resolution;
            by_hand.radius = radius;
            const ssao_settings a = resolve_ok(taken), b = resolve_ok(by_hand);
            CHECK(same(a, b));
            CHECK(a.bias == b.bias);
            CHECK(a.thickness == b.thickness);
            // The thickness follows the radius and the row's step count: R (0.5 + 1.5 / steps).
            CHECK(a.thickness == doctest::Approx(radius * (0.5 + 1.5 / row.step_count)));
        }
    }
}

TEST_CASE("settings: the derived thickness follows the step count the settings resolve to, a set one is kept") {
    for (uint32_t steps : {0u, 1u, 4u, 8u, 16u, 32u}) {
        CAPTURE(steps);
        ssao_settings in = zeroed();
        in.radius = 2.0f;
        in.step_count = steps;
        const ssao_settings r = resolve_ok(in);
        const uint32_t resolved = steps == 0 ? ssao_impl::preset_row(SSAO_PRESET_DEFAULT).step_count : steps;
        CHECK(r.step_count == resolved);
        CHECK(r.thickness == doctest::Approx(2.0 * (0.5 + 1.5 / resolved)));
        in.thickness = 0.3f;
        CHECK(resolve_ok(in).thickness == 0.3f);
    }
    // 4 steps (DEFAULT) give 0.875 R; many steps tend to the depth-only limit's R/2.
    ssao_settings four = zeroed();
    four.radius = 1.0f;
    CHECK(resolve_ok(four).thickness == doctest::Approx(0.875));
}

TEST_CASE("settings: an unknown preset is INVALID_ENUM and leaves out untouched") {
    for (int32_t raw : {6, 7, 100, -1, 0x7fffffff}) {
        CAPTURE(raw);
        ssao_settings out = sentinel();
        const ssao_settings before = out;
        std::string why;
        // The raw bits, as a C caller's ssao_preset argument arrives.
        CHECK(preset_settings(static_cast<uint32_t>(raw), out, why) == SSAO_ERROR_INVALID_ENUM);
        CHECK(same(out, before));
        CHECK_FALSE(why.empty());
    }
}
