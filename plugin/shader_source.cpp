#include "shader_source.h"

#include "pass_table.h"

#include <ssao_shaders_embedded.h>

namespace ssao_impl {

namespace {

// Indexed by bit number (plan.h, namespace variant).
const char* const kVariantNames[] = {
    "GRID_INPUT", "MULTISAMPLE", "NORMALS_FROM_DEPTH", "FADE", "RADIUS_PIXELS", "FRAME_NOISE", "BLUR_WEIGHTS",
    "UPSAMPLE_NEAREST",
};
static_assert(sizeof kVariantNames / sizeof kVariantNames[0] == static_cast<size_t>(variant::kBits),
              "one name per variant bit");

std::string assemble(const char* body, SharedCode shared, uint32_t variant) {
    std::string s = "#version 330 core\n";
    for (int bit = 0; bit < variant::kBits; ++bit)
        if (variant & (1u << bit)) s += std::string("#define SSAO_") + kVariantNames[bit] + " 1\n";
    s += k_ssao_constants_h;
    s += "\n";
    if (shared != SharedCode::none) s += k_common_glsl;
    if (shared == SharedCode::common_and_sampling) s += k_sampling_glsl;
    s += "\n#line 1\n";
    s += body;
    return s;
}

}  // namespace

const char* variant_name(int bit) { return bit >= 0 && bit < variant::kBits ? kVariantNames[bit] : "?"; }

std::string vertex_source() { return assemble(k_fullscreen_vert, SharedCode::none, 0); }

std::string fragment_source(ProgramId id, uint32_t variant) {
    const ProgramInfo& info = program_info(id);
    return assemble(info.fragment_source, info.shared, variant);
}

}  // namespace ssao_impl
