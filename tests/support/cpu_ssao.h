// cpu_ssao.h - an independent CPU implementation of the sampling passes'
// formulas (shaders/ao.frag, and shaders/visibility.frag for
// SSAO_METHOD_VISIBILITY), written from their description, for comparing against the
// GPU output at sampled pixels. Kernel and noise come from the plugin's own
// generator (that part is unit-tested separately).
#pragma once

#include "analytic_scene.h"

#include <ssao/ssao.h>

namespace cpu {

struct Input {
    const analytic::GBuffer* gbuffer = nullptr;
    float projection[16] = {};
    ssao_clip_range clip = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
    double depth_step = 0.0;  // unorm step of the depth format; 0 = float
    // The shader before hard-case finding F1 fell back to the raw sample when
    // the snapped one lay more than half a radius away; kept switchable so a
    // test can show that this line is what made tilted planes self-occlude.
    bool legacy_snap_guard = false;
};

// AO of pixel (x, y) before any blur, with resolved settings `s`.
float ao(const Input& in, const ssao_settings& s, int x, int y);

}  // namespace cpu
