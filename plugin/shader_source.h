// shader_source.h - the GLSL text of every pass program and compiled variant:
// the program's embedded fragment shader (its row in pass_table.cpp), the
// shared code in front of it, and the `#define SSAO_<NAME>` lines of a
// variant (plan.h, namespace variant). No GL here: tests compile every variant
// of every program from these strings (tests/unit/test_shader_variants.cpp).
#pragma once

#include "plan.h"

#include <cstdint>
#include <string>
#include <vector>

namespace ssao_impl {

// The shared GLSL a shader is built on, after the constants header (which
// every shader has): `common` is common.glsl and ao_texture.glsl, what every
// fragment pass uses; `common_and_sampling` adds sampling.glsl, for the passes
// that read normals. Each declaration lives in one of these files, so no pass
// declares what another chunk has.
enum class SharedCode { none, common, common_and_sampling };

// The define a variant bit turns on, without its SSAO_ prefix ("GRID_INPUT", ...).
const char* variant_name(int bit);

// The full-screen triangle's vertex shader.
std::string vertex_source();

// #version, the variant's defines, the constants header, the shared code and
// the pass's own code. Each file starts with `#line 1 N`, N its index in
// vertex_files() / fragment_files(): a driver's "N:LINE" is line LINE of file N.
// (Mesa keeps N for syntax errors only; the errors it finds later it reports
// as "0:LINE", LINE still the line of the file that holds the error.)
std::string fragment_source(ProgramId id, uint32_t variant);

// The file of each source-string number of vertex_source() and of
// fragment_source(id, ...), in order.
std::vector<const char*> vertex_files();
std::vector<const char*> fragment_files(ProgramId id);

// "0 = ssao_constants.h, 1 = common.glsl, ...": which file each source-string
// number of a driver's log stands for.
std::string source_string_legend(const std::vector<const char*>& files);

// The error of shader `name` that failed to compile with the driver's `log`,
// naming the files of its source-string numbers (files).
std::string compile_error_message(const std::string& name, const std::vector<const char*>& files,
                                  const std::string& log);

}  // namespace ssao_impl
