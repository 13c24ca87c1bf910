/* header_c99.c - <ssao/ssao.h> compiled as strict C99 with -Wall -Wextra
 * -Wpedantic -Werror. Reports the struct layout as C sees it, so the C++ side
 * can check that both languages agree (test_header.cpp). */
#include <ssao/ssao.h>

#include <stddef.h>

#include "header_layout.h"

/* Note: the header's own example, `ssao_api api = { sizeof(ssao_api) };`,
 * trips -Wmissing-field-initializers (-Wextra) in C; designated initializers
 * (C99) do not. */

/* Use every typedef the header declares, so a C-only problem in any of them
 * breaks this build. */
static ssao_status SSAO_CALL unused_get_api(uint32_t v, ssao_api* api) {
    (void)v;
    (void)api;
    return SSAO_OK;
}
static ssao_gl_proc SSAO_CALL unused_get_proc(void* user, const char* name) {
    (void)user;
    (void)name;
    return NULL;
}
static void SSAO_CALL unused_log(void* user, ssao_log_level level, const char* message) {
    (void)user;
    (void)level;
    (void)message;
}

ssao_settings unit_c_make_settings(void) {
    ssao_settings s = {.size = sizeof(ssao_settings)};
    s.sample_count = 32;
    s.radius = 1.5f;
    s.strength = SSAO_STRENGTH_OFF;
    s.kernel_shape = SSAO_KERNEL_SEPARABLE;
    s.distribution = SSAO_DISTRIBUTION_UNIFORM;
    s.rotation = SSAO_ROTATION_HASH;
    s.seed = 7u;
    s.blur = SSAO_BLUR_GAUSSIAN;
    s.blur_radius = SSAO_MAX_BLUR_RADIUS;
    s.output_format = SSAO_OUTPUT_R16F;
    return s;
}

int unit_c_use_types(void) {
    PFN_ssao_get_api get_api = unused_get_api;
    ssao_api api = {.size = sizeof(ssao_api)};
    ssao_context_desc desc = {.size = sizeof(ssao_context_desc)};
    ssao_inputs in = {.size = sizeof(ssao_inputs)};
    ssao_output out = {.size = sizeof(ssao_output)};
    ssao_timings t = {.size = sizeof(ssao_timings)};
    ssao_frame_info fi = {.size = sizeof(ssao_frame_info)};
    ssao_context* ctx = NULL;
    ssao_settings s = unit_c_make_settings();
    ssao_preset preset = SSAO_PRESET_ULTRA;
    ssao_pass pass = SSAO_PASS_CLEAR;
    desc.get_proc_address = unused_get_proc;
    desc.log = unused_log;
    desc.settings = &s;
    in.normal_space = SSAO_NORMAL_SPACE_WORLD;
    in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
    in.clip_range = SSAO_CLIP_ZERO_TO_ONE;
    in.projection[15] = 1.0f;
    in.viewport[2] = SSAO_MAX_DIMENSION;
    (void)ctx;
    (void)preset;
    (void)pass;
    (void)out;
    (void)t;
    (void)fi;
    return get_api(SSAO_API_VERSION, &api) == SSAO_OK && desc.settings->seed == 7u &&
           SSAO_VERSION_MAJOR(SSAO_API_VERSION) == 1u && SSAO_VERSION_MINOR(SSAO_API_VERSION) == 4u &&
           in.viewport[2] == 16384 && (int)SSAO_ERROR_INTERNAL == 15;
}

/* Alignment as offsetof(after a char), portable C99. */
#define UNIT_ALIGN_STRUCT(T) struct unit_align_##T { char c; T t; };
UNIT_ALIGN_STRUCT(ssao_settings)
UNIT_ALIGN_STRUCT(ssao_inputs)
UNIT_ALIGN_STRUCT(ssao_output)
UNIT_ALIGN_STRUCT(ssao_timings)
UNIT_ALIGN_STRUCT(ssao_frame_info)
UNIT_ALIGN_STRUCT(ssao_context_desc)
UNIT_ALIGN_STRUCT(ssao_api)
UNIT_ALIGN_STRUCT(ssao_status)
UNIT_ALIGN_STRUCT(ssao_kernel_shape)
UNIT_ALIGN_STRUCT(ssao_blur)
UNIT_ALIGN_STRUCT(ssao_preset)
UNIT_ALIGN_STRUCT(ssao_pass)

#define UNIT_LAYOUT(T) \
    case UNIT_##T: l.size = sizeof(T); l.align = offsetof(struct unit_align_##T, t); break

unit_layout unit_c_layout(unit_type type) {
    unit_layout l = {0, 0};
    switch (type) {
        UNIT_LAYOUT(ssao_settings);
        UNIT_LAYOUT(ssao_inputs);
        UNIT_LAYOUT(ssao_output);
        UNIT_LAYOUT(ssao_timings);
        UNIT_LAYOUT(ssao_frame_info);
        UNIT_LAYOUT(ssao_context_desc);
        UNIT_LAYOUT(ssao_api);
        UNIT_LAYOUT(ssao_status);
        UNIT_LAYOUT(ssao_kernel_shape);
        UNIT_LAYOUT(ssao_blur);
        UNIT_LAYOUT(ssao_preset);
        UNIT_LAYOUT(ssao_pass);
        case UNIT_TYPE_COUNT: break;
    }
    return l;
}

size_t unit_c_offset(unit_field field) {
    switch (field) {
#define UNIT_FIELD(T, F) case UNIT_F_##T##_##F: return offsetof(T, F);
        UNIT_FIELD_LIST
#undef UNIT_FIELD
        case UNIT_FIELD_COUNT: break;
    }
    return (size_t)-1;
}
