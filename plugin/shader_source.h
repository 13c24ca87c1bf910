// shader_source.h - the GLSL text of every pass program and compiled variant:
// the program's embedded fragment shader (its row in pass_table.cpp), the
// shared code in front of it, and the `#define SSAO_<NAME>` lines of a
// variant (plan.h, namespace variant). No GL here: tests compile every variant
// of every program from these strings (tests/unit/test_shader_variants.cpp).
#pragma once

#include "plan.h"

#include <cstdint>
#include <string>

namespace ssao_impl {

// The shared GLSL a fragment shader is built on, after the constants header.
enum class SharedCode { none, common, common_and_sampling };

// The define a variant bit turns on, without its SSAO_ prefix ("GRID_INPUT", ...).
const char* variant_name(int bit);

// The full-screen triangle's vertex shader.
std::string vertex_source();

// #version, the variant's defines, the constants header, the shared code and
// the pass's own code.
std::string fragment_source(ProgramId id, uint32_t variant);

}  // namespace ssao_impl
