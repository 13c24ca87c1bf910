// test_header.cpp - <ssao/ssao.h> from C++ (compiled with the project's
// -Wall -Wextra -Wpedantic -Wshadow -Werror) agrees with the same header
// compiled as strict C99 (header_c99.c): every struct has the same size and
// alignment and every field the same offset, and a struct built in C reads
// back field by field in C++.
#include <ssao/ssao.h>

#include "header_layout.h"

#include <doctest/doctest.h>

#include <cstddef>
#include <cstring>
#include <string>
#include <type_traits>

namespace {

// The function-pointer typedefs match the declarations they describe.
static_assert(std::is_same<decltype(&ssao_get_api), PFN_ssao_get_api>::value,
              "PFN_ssao_get_api does not match ssao_get_api");
static_assert(std::is_same<decltype(ssao_api::status_string), const char* (*)(ssao_status)>::value, "");
static_assert(std::is_same<decltype(ssao_context_desc::get_proc_address), ssao_get_proc_address_fn>::value, "");
static_assert(std::is_same<decltype(ssao_context_desc::log), ssao_log_fn>::value, "");
static_assert(std::is_standard_layout<ssao_settings>::value && std::is_trivially_copyable<ssao_settings>::value, "");
static_assert(std::is_standard_layout<ssao_inputs>::value && std::is_trivially_copyable<ssao_inputs>::value, "");
static_assert(std::is_standard_layout<ssao_api>::value && std::is_trivially_copyable<ssao_api>::value, "");
static_assert(SSAO_API_VERSION == 0x00010004u, "");  // 1.4: max_step_texels
static_assert(SSAO_MAKE_VERSION(3, 7) == 0x00030007u, "");
static_assert(SSAO_VERSION_MAJOR(SSAO_MAKE_VERSION(3, 7)) == 3u && SSAO_VERSION_MINOR(SSAO_MAKE_VERSION(3, 7)) == 7u, "");

// Every struct begins with its uint32_t size.
static_assert(offsetof(ssao_settings, size) == 0 && offsetof(ssao_inputs, size) == 0 &&
                  offsetof(ssao_output, size) == 0 && offsetof(ssao_timings, size) == 0 &&
                  offsetof(ssao_frame_info, size) == 0 && offsetof(ssao_context_desc, size) == 0 &&
                  offsetof(ssao_api, size) == 0,
              "");

// Append-only: ssao_timings 1.0 (40 bytes) is a prefix of 1.1, field for field.
static_assert(offsetof(ssao_timings, available) == 4 && offsetof(ssao_timings, frame) == 8 &&
                  offsetof(ssao_timings, ao_ms) == 16 && offsetof(ssao_timings, blur_ms) == 24 &&
                  offsetof(ssao_timings, total_ms) == 32 && offsetof(ssao_timings, pass_count) == 40,
              "the 1.0 fields of ssao_timings moved");
static_assert(offsetof(ssao_timings, pass_ms) % 8 == 0 && sizeof(ssao_timings) == 40 + 4 + 4 * SSAO_MAX_PASSES + 4 +
                                                                                     8 * SSAO_MAX_PASSES,
              "ssao_timings 1.1 has padding");

unit_layout cxx_layout(unit_type t) {
    switch (t) {
#define L(T) case UNIT_##T: return unit_layout{sizeof(T), alignof(T)};
        L(ssao_settings) L(ssao_inputs) L(ssao_output) L(ssao_timings) L(ssao_frame_info) L(ssao_context_desc)
        L(ssao_api) L(ssao_status) L(ssao_kernel_shape) L(ssao_blur) L(ssao_preset) L(ssao_pass)
#undef L
        case UNIT_TYPE_COUNT: break;
    }
    return unit_layout{0, 0};
}

size_t cxx_offset(unit_field f) {
    switch (f) {
#define UNIT_FIELD(T, F) case UNIT_F_##T##_##F: return offsetof(T, F);
        UNIT_FIELD_LIST
#undef UNIT_FIELD
        case UNIT_FIELD_COUNT: break;
    }
    return static_cast<size_t>(-1);
}

const char* const kTypeNames[] = {"ssao_settings", "ssao_inputs", "ssao_output", "ssao_timings",
                                  "ssao_frame_info", "ssao_context_desc", "ssao_api", "ssao_status",
                                  "ssao_kernel_shape", "ssao_blur", "ssao_preset", "ssao_pass"};
static_assert(sizeof(kTypeNames) / sizeof(kTypeNames[0]) == UNIT_TYPE_COUNT, "");

const char* const kFieldNames[] = {
#define UNIT_FIELD(T, F) #T "." #F,
    UNIT_FIELD_LIST
#undef UNIT_FIELD
};

}  // namespace

TEST_CASE("header: C99 and C++ see the same size and alignment of every ABI type") {
    for (int i = 0; i < UNIT_TYPE_COUNT; ++i) {
        const unit_type t = static_cast<unit_type>(i);
        const std::string what_ = kTypeNames[i];
        CAPTURE(what_);
        const unit_layout c = unit_c_layout(t);
        const unit_layout cxx = cxx_layout(t);
        CHECK(c.size > 0);
        CHECK(c.size == cxx.size);
        CHECK(c.align == cxx.align);
    }
    // Enums are int-sized in both languages (the shader UBO and the ABI rely on 4 bytes).
    CHECK(unit_c_layout(UNIT_ssao_status).size == 4);
    CHECK(unit_c_layout(UNIT_ssao_blur).size == 4);
}

TEST_CASE("header: C99 and C++ see the same offset of every struct field") {
    for (int i = 0; i < UNIT_FIELD_COUNT; ++i) {
        const unit_field f = static_cast<unit_field>(i);
        const std::string what_ = kFieldNames[i];
        CAPTURE(what_);
        CHECK(unit_c_offset(f) == cxx_offset(f));
    }
}

TEST_CASE("header: a settings struct built in C reads back unchanged in C++") {
    const ssao_settings s = unit_c_make_settings();
    CHECK(s.size == sizeof(ssao_settings));
    CHECK(s.sample_count == 32u);
    CHECK(s.radius == 1.5f);
    CHECK(s.bias == 0.0f);
    CHECK(s.strength == SSAO_STRENGTH_OFF);
    CHECK(s.kernel_shape == SSAO_KERNEL_SEPARABLE);
    CHECK(s.distribution == SSAO_DISTRIBUTION_UNIFORM);
    CHECK(s.rotation == SSAO_ROTATION_HASH);
    CHECK(s.seed == 7u);
    CHECK(s.blur == SSAO_BLUR_GAUSSIAN);
    CHECK(s.blur_radius == 16u);
    CHECK(s.blur_sigma == 0.0f);
    CHECK(s.blur_depth_tolerance == 0.0f);
    CHECK(s.output_format == SSAO_OUTPUT_R16F);
    CHECK(unit_c_use_types() == 1);

    // The same struct built in C++.
    ssao_settings cxx{};
    cxx.size = sizeof(ssao_settings);
    cxx.sample_count = 32;
    cxx.radius = 1.5f;
    cxx.strength = SSAO_STRENGTH_OFF;
    cxx.kernel_shape = SSAO_KERNEL_SEPARABLE;
    cxx.distribution = SSAO_DISTRIBUTION_UNIFORM;
    cxx.rotation = SSAO_ROTATION_HASH;
    cxx.seed = 7u;
    cxx.blur = SSAO_BLUR_GAUSSIAN;
    cxx.blur_radius = SSAO_MAX_BLUR_RADIUS;
    cxx.output_format = SSAO_OUTPUT_R16F;
    CHECK(std::memcmp(&cxx, &s, sizeof s) == 0);
}
