// constants.h - the uniform blocks: the per-frame constants derived from the
// settings and the analysed inputs (uploaded only when they change), and the
// kernel with its rotation noise (uploaded when the settings change them).
#pragma once

#include "inputs.h"
#include "gl_state_guard.h"
#include "uniforms.h"

#include <ssao/ssao.h>

#include <cstdint>

struct ssao_context;

namespace ssao_impl {

// The SsaoFrame block for these settings and inputs (no GL).
SsaoFrame make_frame_block(const ssao_settings& s, const AnalysedInputs& in);

// Uploads `frame` unless it equals the block last uploaded.
void upload_frame_block(ssao_context& ctx, const SsaoFrame& frame);

// The settings the kernel block and the noise texture are made from: they
// are uploaded again only when this changes.
struct KernelKey {
    uint32_t sample_count = 0, kernel_shape = 0, distribution = 0, seed = 0, method = 0;
    bool operator==(const KernelKey& o) const {
        return sample_count == o.sample_count && kernel_shape == o.kernel_shape && distribution == o.distribution &&
               seed == o.seed && method == o.method;
    }
    bool operator!=(const KernelKey& o) const { return !(*this == o); }
};
KernelKey kernel_key(const ssao_settings& s);

// Uploads the kernel block and the noise texture (on SSAO_UNIT_NOISE) for
// ctx.settings unless they were made for the same KernelKey; an upload sets
// the default unpack state (saving the host's in `guard`) first.
void update_kernel(ssao_context& ctx, GlStateGuard& guard);

}  // namespace ssao_impl
