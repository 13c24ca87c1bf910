/* c_caller.c - calls through the ABI as a C program does. In C an enum
 * argument may hold any value of its 32-bit type (0xffffffff included), which
 * C++ code cannot produce without undefined behaviour; the library must take
 * it and answer SSAO_ERROR_INVALID_ENUM. */
#include <ssao/ssao.h>

#include "c_caller.h"

ssao_status unit_c_preset_raw(const ssao_api* api, uint32_t raw, ssao_settings* out) {
    return api->preset_settings((ssao_preset)raw, out);
}

const char* unit_c_status_string_raw(const ssao_api* api, uint32_t raw) {
    return api->status_string((ssao_status)raw);
}
