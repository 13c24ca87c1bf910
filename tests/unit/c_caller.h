// c_caller.h - ABI calls made from C (c_caller.c), with raw enum values.
#pragma once

#include <ssao/ssao.h>

#ifdef __cplusplus
extern "C" {
#endif

// api->preset_settings with the preset's raw 32 bits, passed from C.
ssao_status unit_c_preset_raw(const ssao_api* api, uint32_t raw, ssao_settings* out);

// api->status_string with the status's raw 32 bits, passed from C.
const char* unit_c_status_string_raw(const ssao_api* api, uint32_t raw);

#ifdef __cplusplus
}
#endif
