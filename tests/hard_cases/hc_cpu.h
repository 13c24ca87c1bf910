// hc_cpu.h - a copy of tests/support/cpu_ssao (the AO formula on the CPU, in
// double) with switches for the changes FINDINGS.md proposes, so a proposed
// plugin fix can be shown to remove a failure before the lead applies it.
#pragma once

#include "cpu_ssao.h"

namespace hccpu {

using cpu::Input;

struct Variant {
    // ao.frag before b112e72: `if (distance(sn, s) > 0.5 * radius) sn = s;`
    // (finding F1). Off by default, as the shader is now.
    bool snap_guard = false;
    // Finding F5 (proposed): the float depth step in the [-1,1] clip range is
    // at least half an ulp of NDC z.
    bool ndc_ulp = false;
};

float ao(const Input& in, const ssao_settings& s, int x, int y, const Variant& var = {});

}  // namespace hccpu
