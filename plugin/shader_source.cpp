#include "shader_source.h"

#include "pass_table.h"

#include <ssao_shaders_embedded.h>

namespace ssao_impl {

namespace {

// Indexed by bit number (plan.h, namespace variant).
const char* const kVariantNames[] = {
    "GRID_INPUT", "MULTISAMPLE", "NORMALS_FROM_DEPTH", "FADE", "RADIUS_PIXELS", "FRAME_NOISE", "BLUR_WEIGHTS",
    "UPSAMPLE_NEAREST", "UNORM_DEPTH", "STEP_TEXELS", "UPSAMPLE_PLANE_FIT",
};
static_assert(sizeof kVariantNames / sizeof kVariantNames[0] == static_cast<size_t>(variant::kBits),
              "one name per variant bit");

struct Chunk {
    const char* file;
    const char* text;
};

// The files of a shader in source-string order: the constants header, the
// shared code, then `body`, the shader's own file.
std::vector<Chunk> chunks_of(SharedCode shared, const char* body_file, const char* body) {
    std::vector<Chunk> chunks{{"ssao_constants.h", k_ssao_constants_h}};
    if (shared != SharedCode::none) {
        chunks.push_back({"common.glsl", k_common_glsl});
        chunks.push_back({"ao_texture.glsl", k_ao_texture_glsl});
    }
    if (shared == SharedCode::common_and_sampling) chunks.push_back({"sampling.glsl", k_sampling_glsl});
    chunks.push_back({body_file, body});
    return chunks;
}

std::vector<const char*> files_of(const std::vector<Chunk>& chunks) {
    std::vector<const char*> files;
    for (const Chunk& c : chunks) files.push_back(c.file);
    return files;
}

// #version first (GLSL requires it), the variant's defines, then each chunk
// behind `#line 1 N`: its lines count from 1 again under source-string number
// N, so a driver's "N:LINE" names the file and its own line.
std::string assemble(const std::vector<Chunk>& chunks, uint32_t variant) {
    std::string s = "#version 330 core\n";
    for (int bit = 0; bit < variant::kBits; ++bit)
        if (variant & (1u << bit)) s += std::string("#define SSAO_") + kVariantNames[bit] + " 1\n";
    for (size_t i = 0; i < chunks.size(); ++i) {
        s += "#line 1 " + std::to_string(i) + "\n";
        s += chunks[i].text;
        if (s.back() != '\n') s += '\n';
    }
    return s;
}

}  // namespace

const char* variant_name(int bit) { return bit >= 0 && bit < variant::kBits ? kVariantNames[bit] : "?"; }

std::string vertex_source() { return assemble(chunks_of(SharedCode::none, "fullscreen.vert", k_fullscreen_vert), 0); }

std::string fragment_source(ProgramId id, uint32_t variant) {
    const ProgramInfo& info = program_info(id);
    return assemble(chunks_of(info.shared, info.file_name, info.fragment_source), variant);
}

std::vector<const char*> vertex_files() {
    return files_of(chunks_of(SharedCode::none, "fullscreen.vert", k_fullscreen_vert));
}

std::vector<const char*> fragment_files(ProgramId id) {
    const ProgramInfo& info = program_info(id);
    return files_of(chunks_of(info.shared, info.file_name, info.fragment_source));
}

std::string source_string_legend(const std::vector<const char*>& files) {
    std::string s;
    for (size_t i = 0; i < files.size(); ++i) s += (i ? ", " : "") + std::to_string(i) + " = " + files[i];
    return s;
}

std::string compile_error_message(const std::string& name, const std::vector<const char*>& files,
                                  const std::string& log) {
    return "shader " + name + " failed to compile (source strings: " + source_string_legend(files) + "): " + log;
}

}  // namespace ssao_impl
