// test_shader_source.cpp - how the shaders are put together
// (plugin/shader_source.h): each file of an assembled shader behind its own
// `#line 1 N`, so that a driver's "N:LINE" is line LINE of file N; the error
// message that names the files; every declaration in one file only; and the
// frame block's std140 layout as the driver lays it out against the C++
// struct's (plugin/uniforms.h).
#include <doctest/doctest.h>

#include "egl_context.h"
#include "plan.h"
#include "shader_build.h"
#include "shader_source.h"
#include "uniforms.h"

#include <ssao_shaders_embedded.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace ssao_impl;

namespace {

const ProgramId kFragmentPrograms[] = {ProgramId::kernel,         ProgramId::visibility, ProgramId::blur,
                                       ProgramId::grid, ProgramId::upsample,   ProgramId::normals_view};

// The text of a shader file as the plugin embeds it.
std::string embedded(const std::string& file) {
    const std::map<std::string, const char*> texts = {
        {"ssao_constants.h", k_ssao_constants_h}, {"common.glsl", k_common_glsl},
        {"ao_texture.glsl", k_ao_texture_glsl},   {"sampling.glsl", k_sampling_glsl},
        {"fullscreen.vert", k_fullscreen_vert},   {"kernel.frag", k_kernel_frag},
        {"visibility.frag", k_visibility_frag},   {"blur.frag", k_blur_frag},
        {"grid.frag", k_grid_frag},               {"upsample.frag", k_upsample_frag},
        {"normals_view.frag", k_normals_view_frag}};
    const auto it = texts.find(file);
    return it == texts.end() ? std::string("(not embedded: ") + file + ")" : it->second;
}

struct Segment {
    int source = -1;  // the N of the `#line 1 N` in front of it
    std::string text;
};

// The assembled source cut at its `#line 1 N` lines: what comes before the
// first (the #version and #define lines), then one segment per directive.
std::vector<Segment> split_at_line_directives(const std::string& source, std::string& head) {
    std::vector<Segment> segments;
    const std::string directive = "#line 1 ";
    size_t at = source.find(directive);
    head = source.substr(0, at);
    while (at != std::string::npos) {
        const size_t eol = source.find('\n', at);
        Segment s;
        s.source = std::stoi(source.substr(at + directive.size(), eol - at - directive.size()));
        const size_t next = source.find("\n" + directive, eol);
        s.text = source.substr(eol + 1, next == std::string::npos ? std::string::npos : next + 1 - (eol + 1));
        segments.push_back(s);
        at = next == std::string::npos ? next : next + 1;
    }
    return segments;
}

// The (source-string number, line) a driver reports for the line of
// `source` that starts at `pos`: the last `#line L N` before it sets line L
// on the line after the directive.
std::pair<int, int> driver_position(const std::string& source, size_t pos) {
    const size_t at = source.rfind("\n#line ", pos);
    if (at == std::string::npos) return {-1, -1};
    int line = 0, number = 0;
    std::istringstream(source.substr(at + 7, source.find('\n', at + 1) - at - 7)) >> line >> number;
    const size_t first = source.find('\n', at + 1) + 1;
    return {number, line + static_cast<int>(std::count(source.begin() + first, source.begin() + pos, '\n'))};
}

// Line number (from 1) of the line of `text` that starts at `pos`.
int line_of(const std::string& text, size_t pos) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + pos, '\n'));
}

int index_of(const std::vector<const char*>& files, const std::string& file) {
    for (size_t i = 0; i < files.size(); ++i)
        if (file == files[i]) return static_cast<int>(i);
    return -1;
}

// The driver's log of `source`, "" when it compiles.
std::string compile_log(GladGLContext& gl, GLenum type, const std::string& source) {
    GLuint shader = 0;
    const std::string log = shader_build::compile_log(gl, type, source, shader);
    gl.DeleteShader(shader);
    return log;
}

std::unique_ptr<eglctx::Context> gl_context() {
    eglctx::Options options;
    options.major = 3;
    options.minor = 3;
    std::string error;
    auto egl = eglctx::Context::create(options, error);
    REQUIRE_MESSAGE(egl, "no EGL context: " << error);
    return egl;
}

}  // namespace

TEST_CASE("shader source: each file follows its own #line 1 N, N its index in the file list, its text unchanged") {
    const uint32_t all_bits = (1u << variant::kBits) - 1u;
    struct Shader {
        std::string source;
        std::vector<const char*> files;
    };
    std::vector<Shader> shaders{{vertex_source(), vertex_files()}};
    for (ProgramId id : kFragmentPrograms) {
        shaders.push_back({fragment_source(id, 0), fragment_files(id)});
        shaders.push_back({fragment_source(id, all_bits), fragment_files(id)});
    }
    for (const Shader& shader : shaders) {
        CAPTURE(shader.files.back());
        std::string head;
        const std::vector<Segment> segments = split_at_line_directives(shader.source, head);
        // Before the first file: only #version and the variant's defines.
        CHECK(head.rfind("#version 330 core\n", 0) == 0);
        std::istringstream lines(head);
        for (std::string line; std::getline(lines, line);)
            CHECK((line.rfind("#version ", 0) == 0 || line.rfind("#define SSAO_", 0) == 0));
        REQUIRE(segments.size() == shader.files.size());
        CHECK(std::string(shader.files.front()) == "ssao_constants.h");
        for (size_t i = 0; i < segments.size(); ++i) {
            CAPTURE(shader.files[i]);
            CHECK(segments[i].source == static_cast<int>(i));
            std::string text = embedded(shader.files[i]);
            if (text.empty() || text.back() != '\n') text += '\n';
            CHECK(segments[i].text == text);
        }
    }
    // The shared files each program is built on.
    const std::vector<std::string> sampling = {"ssao_constants.h", "common.glsl", "ao_texture.glsl", "sampling.glsl",
                                               "kernel.frag"};
    const std::vector<const char*> kernel = fragment_files(ProgramId::kernel);
    CHECK(std::vector<std::string>(kernel.begin(), kernel.end()) == sampling);
    const std::vector<const char*> blur = fragment_files(ProgramId::blur);
    CHECK(std::vector<std::string>(blur.begin(), blur.end()) ==
          std::vector<std::string>{"ssao_constants.h", "common.glsl", "ao_texture.glsl", "blur.frag"});
    const std::vector<const char*> vert = vertex_files();
    CHECK(std::vector<std::string>(vert.begin(), vert.end()) ==
          std::vector<std::string>{"ssao_constants.h", "fullscreen.vert"});
}

TEST_CASE("shader source: a known line of kernel.frag and of common.glsl keeps its file's line number") {
    const std::string source = fragment_source(ProgramId::kernel, 0);
    const std::vector<const char*> files = fragment_files(ProgramId::kernel);
    const struct {
        const char* file;
        const char* line;
    } known[] = {{"kernel.frag", "    float ao = pow(clamp(1.0 - consts.strength * o, 0.0, 1.0), consts.power);\n"},
                 {"common.glsl", "float ndc_z_of(float d) {"},
                 {"sampling.glsl", "bool load_surface(out Surface sf) {\n"},
                 {"ssao_constants.h", "SSAO_BLOCK(SsaoFrame) {\n"}};
    for (const auto& k : known) {
        CAPTURE(k.file);
        const std::string text = embedded(k.file);
        const size_t in_file = text.find(std::string("\n") + k.line);
        const size_t in_source = source.find(std::string("\n") + k.line);
        REQUIRE(in_file != std::string::npos);
        REQUIRE(in_source != std::string::npos);
        const std::pair<int, int> at = driver_position(source, in_source + 1);
        CHECK(at.first == index_of(files, k.file));
        CHECK(at.second == line_of(text, in_file + 1));
    }
}

TEST_CASE("shader source: the driver's log names the source string and the line of the file that holds the error") {
    auto egl = gl_context();
    const std::vector<const char*> files = fragment_files(ProgramId::visibility);
    // Syntax errors: Mesa reports them with the source-string number of the
    // token. (Errors it finds later, such as an undeclared name or a wrong
    // type, it reports as source string 0, on the right line.)
    const struct {
        const char* file;
        const char* line;    // a line of that file...
        const char* broken;  // ...and what it becomes
    } cases[] = {{"visibility.frag", "    int steps = consts.step_count;\n", "    int steps = consts.step_count; @\n"},
                 {"common.glsl", "bool is_sky(float d) { return d == consts.sky_depth; }\n",
                  "bool is_sky(float d) { return d == consts.sky_depth; @ }\n"},
                 {"sampling.glsl", "    sf.radius = consts.radius;\n", "    sf.radius = consts.radius; @\n"},
                 {"ao_texture.glsl", "uniform bool u_pack_depth;", "uniform bool u_pack_depth; @"}};
    for (const auto& c : cases) {
        CAPTURE(c.file);
        std::string source = fragment_source(ProgramId::visibility, 0);
        const size_t at = source.find(c.line);
        REQUIRE(at != std::string::npos);
        source.replace(at, std::string(c.line).size(), c.broken);
        const std::string text = embedded(c.file);
        const int line = line_of(text, text.find(c.line));
        const std::string log = compile_log(egl->gl(), GL_FRAGMENT_SHADER, source);
        CAPTURE(log);
        // Mesa writes "N:LINE(COLUMN): error: ...", NVIDIA "N(LINE) : error C0000: ...".
        const std::string n = std::to_string(index_of(files, c.file)), l = std::to_string(line);
        CHECK((log.find(n + ":" + l + "(") != std::string::npos || log.find(n + "(" + l + ")") != std::string::npos));
        CHECK(log.find("error") != std::string::npos);
    }
}

TEST_CASE("shader source: the compile error names the file of every source-string number") {
    CHECK(source_string_legend({}) == "");
    CHECK(source_string_legend({"ssao_constants.h", "fullscreen.vert"}) == "0 = ssao_constants.h, 1 = fullscreen.vert");
    CHECK(source_string_legend(fragment_files(ProgramId::blur)) ==
          "0 = ssao_constants.h, 1 = common.glsl, 2 = ao_texture.glsl, 3 = blur.frag");
    CHECK(compile_error_message("kernel.frag +FADE", fragment_files(ProgramId::kernel),
                                "4:12(3): error: `no_such_name' undeclared\n") ==
          "shader kernel.frag +FADE failed to compile (source strings: 0 = ssao_constants.h, 1 = common.glsl, "
          "2 = ao_texture.glsl, 3 = sampling.glsl, 4 = kernel.frag): 4:12(3): error: `no_such_name' undeclared\n");
}

// Every uniform, output, constant and function at file scope of shaders/ is
// declared in one file: no pass repeats what a shared file (or another pass)
// has. main() is every pass's own; #ifdef alternatives inside one file count once.
TEST_CASE("shader source: no file declares a uniform, output, constant or function another file has") {
    const std::regex declaration(
        "^(?:uniform\\s+\\w+\\s+(\\w+)"
        "|(?:layout\\([^)]*\\)\\s*)?out\\s+\\w+\\s+(\\w+)"
        "|const\\s+\\w+\\s+(\\w+)\\s*="
        "|(?:void|bool|int|uint|float|[iu]?vec[234]|mat[234])\\s+(\\w+)\\s*\\()");
    std::map<std::string, std::set<std::string>> files_of_name;
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(SSAO_SHADER_DIR)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".glsl" && ext != ".frag" && ext != ".vert") continue;
        ++files;
        std::ifstream in(entry.path());
        for (std::string line; std::getline(in, line);) {
            std::smatch m;
            if (!std::regex_search(line, m, declaration)) continue;
            for (size_t g = 1; g < m.size(); ++g)
                if (m[g].matched && m[g].str() != "main") files_of_name[m[g].str()].insert(entry.path().filename());
        }
    }
    CHECK(files >= 10);
    // The parse finds what it should: one of each kind, each in its file.
    CHECK(files_of_name["u_ao_tex"] == std::set<std::string>{"ao_texture.glsl"});
    CHECK(files_of_name["o_ao"] == std::set<std::string>{"ao_texture.glsl"});
    CHECK(files_of_name["SKY_Z"] == std::set<std::string>{"common.glsl"});
    CHECK(files_of_name["result"] == std::set<std::string>{"ao_texture.glsl"});
    CHECK(files_of_name["texel_surface"] == std::set<std::string>{"common.glsl"});
    for (const auto& entry : files_of_name) {
        const std::string& name = entry.first;  // not a structured binding: clang 14's CAPTURE cannot capture one
        CAPTURE(name);
        CHECK(entry.second.size() == 1);
    }
}

// The driver's std140 offsets of every SsaoFrame member against the C++
// struct's: the static_asserts of plugin/uniforms.h check the C++ side
// against the numbers written there, this checks GLSL's side too.
TEST_CASE("shader source: every SsaoFrame and SsaoKernel member sits at the same offset in GLSL as in C++") {
#define MEMBER(block, name) {#block "." #name, offsetof(block, name)}
    const std::map<std::string, size_t> cpp = {
        MEMBER(SsaoFrame, proj), MEMBER(SsaoFrame, inv_proj), MEMBER(SsaoFrame, normal_to_view),
        MEMBER(SsaoFrame, viewport_origin), MEMBER(SsaoFrame, viewport_size), MEMBER(SsaoFrame, sample_count),
        MEMBER(SsaoFrame, step_count), MEMBER(SsaoFrame, seed), MEMBER(SsaoFrame, rotation),
        MEMBER(SsaoFrame, normal_space), MEMBER(SsaoFrame, normal_packing), MEMBER(SsaoFrame, blur_radius),
        MEMBER(SsaoFrame, blur_kind), MEMBER(SsaoFrame, orthographic), MEMBER(SsaoFrame, frame_pick_swap),
        MEMBER(SsaoFrame, ndc_per_depth), MEMBER(SsaoFrame, sky_depth), MEMBER(SsaoFrame, unorm_depth_step),
        MEMBER(SsaoFrame, radius), MEMBER(SsaoFrame, bias), MEMBER(SsaoFrame, depth_step_bias),
        MEMBER(SsaoFrame, strength), MEMBER(SsaoFrame, power), MEMBER(SsaoFrame, thickness),
        MEMBER(SsaoFrame, blur_sigma), MEMBER(SsaoFrame, blur_depth_tolerance), MEMBER(SsaoFrame, fade_start),
        MEMBER(SsaoFrame, fade_end), MEMBER(SsaoFrame, radius_pixels), MEMBER(SsaoFrame, frame_rotation),
        MEMBER(SsaoFrame, frame_step_offset), MEMBER(SsaoFrame, max_step_texels), MEMBER(SsaoFrame, view_mul_z),
        MEMBER(SsaoFrame, view_mul_1), MEMBER(SsaoFrame, view_add_z), MEMBER(SsaoFrame, view_add_1),
        MEMBER(SsaoFrame, clip_w_z), MEMBER(SsaoFrame, clip_w_1), MEMBER(SsaoFrame, clip_z_z),
        MEMBER(SsaoFrame, clip_z_1), MEMBER(SsaoFrame, inv_det), MEMBER(SsaoFrame, pad1), MEMBER(SsaoFrame, pad2),
        MEMBER(SsaoFrame, pad3), {"SsaoKernel.vectors[0]", offsetof(SsaoKernel, vectors)}};
#undef MEMBER
    auto egl = gl_context();
    GladGLContext& gl = egl->gl();
    // The visibility pass reads both blocks; std140 keeps every member active.
    GLuint program = 0;
    REQUIRE(shader_build::link_pass_program(gl, ProgramId::visibility, 0, program) == "");
    std::map<std::string, size_t> glsl;
    size_t members = 0;
    for (const auto& block_size : {std::pair<const char*, size_t>{"SsaoFrame", sizeof(SsaoFrame)},
                                   std::pair<const char*, size_t>{"SsaoKernel", sizeof(SsaoKernel)}}) {
        const char* block = block_size.first;  // not a structured binding: clang 14's CAPTURE cannot capture one
        const size_t size = block_size.second;
        CAPTURE(block);
        const GLuint index = gl.GetUniformBlockIndex(program, block);
        REQUIRE(index != GL_INVALID_INDEX);
        GLint data_size = 0, count = 0;
        gl.GetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_DATA_SIZE, &data_size);
        gl.GetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_ACTIVE_UNIFORMS, &count);
        CHECK(static_cast<size_t>(data_size) == size);
        std::vector<GLint> indices(static_cast<size_t>(count));
        gl.GetActiveUniformBlockiv(program, index, GL_UNIFORM_BLOCK_ACTIVE_UNIFORM_INDICES, indices.data());
        for (GLint i : indices) {
            const GLuint u = static_cast<GLuint>(i);
            char name[256] = {};
            gl.GetActiveUniformName(program, u, sizeof name, nullptr, name);
            GLint offset = -1;
            gl.GetActiveUniformsiv(program, 1, &u, GL_UNIFORM_OFFSET, &offset);
            glsl[name] = static_cast<size_t>(offset);
            ++members;
        }
    }
    gl.DeleteProgram(program);
    CHECK(members == cpp.size());  // every member of the blocks is in the table above
    CHECK(glsl == cpp);
}
