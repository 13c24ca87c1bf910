// uniforms.h - the C++ view of the std140 blocks declared once in
// shaders/ssao_constants.h (which both C++ and GLSL read).
#pragma once

#include <cstdint>

namespace ssao_std140 {
struct mat4 { float m[16]; };
struct vec4 { float v[4]; };
struct ivec4 { int32_t v[4]; };
}  // namespace ssao_std140

#include <ssao_constants.h>

static_assert(sizeof(SsaoFrame) == 3 * 64 + 4 * 16 + 11 * 16, "SsaoFrame must match its std140 layout");
static_assert(sizeof(SsaoKernel) == SSAO_MAX_KERNEL * 16, "SsaoKernel must match its std140 layout");
