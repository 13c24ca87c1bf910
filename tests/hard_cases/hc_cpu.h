// hc_cpu.h - a copy of tests/support/cpu_ssao (the AO formula on the CPU, in
// double) with switches for the changes FINDINGS.md proposes, so a proposed
// plugin fix can be shown to remove a failure before the lead applies it.
#pragma once

#include "cpu_ssao.h"

namespace hccpu {

using cpu::Input;

struct Variant {
    bool snap_guard = true;  // ao.frag: `if (distance(sn, s) > 0.5 * radius) sn = s;`
};

float ao(const Input& in, const ssao_settings& s, int x, int y, const Variant& var = {});

}  // namespace hccpu
