// report_text.h - what ssao-host prints about a run, in words: the settings the
// plugin ran with (only those its estimator reads) and the GPU time of each pass.
#pragma once

#include <ssao/ssao.h>

#include <string>

namespace report_text {

// "visibility, 8 directions x 4 steps, half resolution, no blur, thickness 0.287"
// (the preset words of preset_text::describe, then what only this estimator
// reads: thickness for visibility, the kernel's shape for the kernel).
std::string estimator(const ssao_settings& resolved);

// A pass's name: its debug group's ("grid", docs/api.md "Debugger names";
// the estimator's bit is named by `method`, the settings' method), or with
// `brief` the viewer overlay's shorter one ("up").
const char* pass_name(uint32_t kind, uint32_t method, bool brief = false);

// "grid 1.2 ms, visibility 30.1 ms, upsample 13.7 ms, total 45.0 ms": each
// pass under its debug-group name, in the order it ran.
std::string pass_times(const ssao_timings& timings, uint32_t method);

}  // namespace report_text
