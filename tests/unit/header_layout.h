/* header_layout.h - shared by header_c99.c (compiled as C99) and
 * test_header.cpp: the C side reports sizeof/alignment/offsetof as C sees
 * them, the C++ side compares with its own. */
#ifndef UNIT_HEADER_LAYOUT_H
#define UNIT_HEADER_LAYOUT_H

#include <ssao/ssao.h>

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum unit_type {
    UNIT_ssao_settings,
    UNIT_ssao_inputs,
    UNIT_ssao_output,
    UNIT_ssao_timings,
    UNIT_ssao_frame_info,
    UNIT_ssao_context_desc,
    UNIT_ssao_api,
    UNIT_ssao_status,
    UNIT_ssao_kernel_shape,
    UNIT_ssao_blur,
    UNIT_ssao_preset,
    UNIT_ssao_pass,
    UNIT_TYPE_COUNT
} unit_type;

typedef struct unit_layout {
    size_t size;
    size_t align;
} unit_layout;

/* Every field of every struct of the ABI. */
#define UNIT_FIELD_LIST \
    UNIT_FIELD(ssao_settings, size) UNIT_FIELD(ssao_settings, sample_count) UNIT_FIELD(ssao_settings, radius) \
    UNIT_FIELD(ssao_settings, bias) UNIT_FIELD(ssao_settings, depth_step_bias) UNIT_FIELD(ssao_settings, power) \
    UNIT_FIELD(ssao_settings, strength) UNIT_FIELD(ssao_settings, kernel_shape) \
    UNIT_FIELD(ssao_settings, distribution) UNIT_FIELD(ssao_settings, rotation) UNIT_FIELD(ssao_settings, seed) \
    UNIT_FIELD(ssao_settings, blur) UNIT_FIELD(ssao_settings, blur_radius) UNIT_FIELD(ssao_settings, blur_sigma) \
    UNIT_FIELD(ssao_settings, blur_depth_tolerance) UNIT_FIELD(ssao_settings, output_format) \
    UNIT_FIELD(ssao_settings, method) UNIT_FIELD(ssao_settings, thickness) UNIT_FIELD(ssao_settings, step_count) \
    UNIT_FIELD(ssao_settings, resolution) UNIT_FIELD(ssao_settings, fade_start) UNIT_FIELD(ssao_settings, fade_end) \
    UNIT_FIELD(ssao_settings, radius_pixels) UNIT_FIELD(ssao_settings, debug_view) \
    UNIT_FIELD(ssao_settings, max_step_texels) \
    UNIT_FIELD(ssao_inputs, size) UNIT_FIELD(ssao_inputs, depth_texture) UNIT_FIELD(ssao_inputs, normal_texture) \
    UNIT_FIELD(ssao_inputs, normal_space) UNIT_FIELD(ssao_inputs, normal_packing) \
    UNIT_FIELD(ssao_inputs, projection) UNIT_FIELD(ssao_inputs, view_matrix) UNIT_FIELD(ssao_inputs, clip_range) \
    UNIT_FIELD(ssao_inputs, viewport) UNIT_FIELD(ssao_inputs, output_texture) \
    UNIT_FIELD(ssao_output, size) UNIT_FIELD(ssao_output, texture) UNIT_FIELD(ssao_output, origin) \
    UNIT_FIELD(ssao_output, passes_run) \
    UNIT_FIELD(ssao_timings, size) UNIT_FIELD(ssao_timings, available) UNIT_FIELD(ssao_timings, frame) \
    UNIT_FIELD(ssao_timings, ao_ms) UNIT_FIELD(ssao_timings, blur_ms) UNIT_FIELD(ssao_timings, total_ms) \
    UNIT_FIELD(ssao_timings, pass_count) UNIT_FIELD(ssao_timings, pass_kind) UNIT_FIELD(ssao_timings, reserved) \
    UNIT_FIELD(ssao_timings, pass_ms) \
    UNIT_FIELD(ssao_frame_info, size) UNIT_FIELD(ssao_frame_info, orthographic) \
    UNIT_FIELD(ssao_frame_info, reverse_z) UNIT_FIELD(ssao_frame_info, infinite_far) \
    UNIT_FIELD(ssao_frame_info, depth_bits) UNIT_FIELD(ssao_frame_info, near_distance) \
    UNIT_FIELD(ssao_frame_info, far_distance) \
    UNIT_FIELD(ssao_context_desc, size) UNIT_FIELD(ssao_context_desc, get_proc_address) \
    UNIT_FIELD(ssao_context_desc, get_proc_address_user) UNIT_FIELD(ssao_context_desc, log) \
    UNIT_FIELD(ssao_context_desc, log_user) UNIT_FIELD(ssao_context_desc, settings) \
    UNIT_FIELD(ssao_api, size) UNIT_FIELD(ssao_api, version) UNIT_FIELD(ssao_api, status_string) \
    UNIT_FIELD(ssao_api, resolve_settings) UNIT_FIELD(ssao_api, preset_settings) \
    UNIT_FIELD(ssao_api, create_context) UNIT_FIELD(ssao_api, destroy_context) \
    UNIT_FIELD(ssao_api, set_settings) UNIT_FIELD(ssao_api, get_settings) UNIT_FIELD(ssao_api, execute) \
    UNIT_FIELD(ssao_api, get_timings) UNIT_FIELD(ssao_api, get_frame_info) UNIT_FIELD(ssao_api, last_error)

typedef enum unit_field {
#define UNIT_FIELD(T, F) UNIT_F_##T##_##F,
    UNIT_FIELD_LIST
#undef UNIT_FIELD
    UNIT_FIELD_COUNT
} unit_field;

unit_layout unit_c_layout(unit_type type);
size_t unit_c_offset(unit_field field);
/* A settings struct built in C (returned by value across the language boundary). */
ssao_settings unit_c_make_settings(void);
/* 1 when the header's types and macros behave in C as documented. */
int unit_c_use_types(void);

#ifdef __cplusplus
}
#endif

#endif
