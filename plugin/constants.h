// constants.h - the uniform blocks: the per-frame constants derived from the
// settings and the analysed inputs (uploaded only when they change), and the
// kernel with its rotation noise (uploaded when the settings change them).
#pragma once

#include "inputs.h"
#include "uniforms.h"

#include <ssao/ssao.h>

struct ssao_context;

namespace ssao_impl {

// The SsaoFrame block for these settings and inputs (no GL).
SsaoFrame make_frame_block(const ssao_settings& s, const AnalysedInputs& in);

// Uploads `frame` unless it equals the block last uploaded; binds both blocks
// to their binding points.
void upload_frame_block(ssao_context& ctx, const SsaoFrame& frame);

// Uploads the kernel block and the noise texture (on SSAO_UNIT_NOISE) from
// ctx.settings; clears ctx.kernel_dirty. Needs the default unpack state.
void upload_kernel(ssao_context& ctx);

}  // namespace ssao_impl
