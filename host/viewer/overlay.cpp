#include "overlay.h"

#include "cli.h"
#include "debug_view_text.h"
#include "gl_util.h"
#include "modes.h"
#include "report_text.h"

#include <stb/stb_easy_font.h>

#include <algorithm>
#include <cstdarg>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <optional>

namespace viewer {

namespace {

const char* kVertex = R"glsl(#version 330 core
layout(location = 0) in vec2 a_position;   // font pixels, y down from the top left
layout(location = 1) in vec4 a_color;
uniform vec2 u_size;                       // framebuffer pixels
uniform float u_scale;
out vec4 v_color;
void main() {
    vec2 p = a_position * u_scale / u_size;
    gl_Position = vec4(p.x * 2.0 - 1.0, 1.0 - p.y * 2.0, 0.0, 1.0);
    v_color = a_color;
}
)glsl";

const char* kFragment = R"glsl(#version 330 core
in vec4 v_color;
out vec4 o_color;
void main() { o_color = v_color; }
)glsl";

// stb_easy_font's vertex.
struct Vertex {
    float x, y, z;
    uint8_t color[4];
};

const char* preset_name(const std::optional<ssao_preset>& p) {
    if (!p) return "plugin defaults";
    switch (*p) {
        case SSAO_PRESET_LOW: return "LOW";
        case SSAO_PRESET_MEDIUM: return "MEDIUM";
        case SSAO_PRESET_HIGH: return "HIGH";
        case SSAO_PRESET_ULTRA: return "ULTRA";
        case SSAO_PRESET_CHAPTER: return "CHAPTER";
        default: return "DEFAULT";
    }
}

std::string printf_string(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string printf_string(const char* format, ...) {
    char buffer[256];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    return buffer;
}

const char* resolution_name(ssao_resolution r) {
    switch (r) {
        case SSAO_RESOLUTION_HALF: return "half";
        case SSAO_RESOLUTION_QUARTER: return "quarter";
        default: return "full";
    }
}

// The GPU milliseconds of the newest timed frame, pass by pass.
std::string gpu_line(const ssao_timings& t, uint32_t method) {
    std::string line = printf_string("GPU ms (frame %llu):", static_cast<unsigned long long>(t.frame));
    if (t.pass_count > 0 && t.pass_count <= SSAO_MAX_PASSES) {
        for (uint32_t i = 0; i < t.pass_count; ++i)
            line += printf_string(" %s %.3f ", report_text::pass_name(t.pass_kind[i], method, true), t.pass_ms[i]);
        return line + printf_string(" total %.3f", t.total_ms);
    }
    // No per-pass times: the two summary figures.
    return line + printf_string(" %s %.3f  blur %.3f  total %.3f", report_text::pass_name(SSAO_PASS_OCCLUSION, method, true), t.ao_ms, t.blur_ms, t.total_ms);
}

constexpr int kMargin = 2;   // font pixels around the text on its dark band

// `line` broken at its double spaces into pieces no wider than `max_pixels`
// (a group wider on its own stays whole); continuations start with two spaces.
std::vector<std::string> wrap(const std::string& line, int max_pixels, int scale) {
    std::vector<std::string> groups;
    for (size_t at = 0;;) {
        const size_t gap = line.find("  ", at);
        groups.push_back(line.substr(at, gap == std::string::npos ? std::string::npos : gap - at));
        if (gap == std::string::npos) break;
        at = line.find_first_not_of(' ', gap);
        if (at == std::string::npos) break;
    }
    std::vector<std::string> out;
    std::string current;
    for (const std::string& g : groups) {
        if (current.empty()) {
            current = out.empty() ? g : "  " + g;
        } else if (overlay_width(current + "  " + g, scale) <= max_pixels) {
            current += "  " + g;
        } else {
            out.push_back(current);
            current = "  " + g;
        }
    }
    out.push_back(current);
    return out;
}

// The overlay's lines before they are fitted to the window.
std::vector<std::string> unwrapped_lines(const State& s, const ssao_timings& t, int width, int height) {
    std::vector<std::string> lines;
    const modes::Mode* mode = s.mode ? modes::find(s.mode) : nullptr;
    // A debug view (X) replaces the picture whichever of V's views is chosen.
    const std::string view = debug_view_shown(s) ? std::string("debug ") + debug_view_text::name(s.settings.debug_view)
                             : s.view == View::Lit ? "lit"
                                                   : "AO only";
    lines.push_back(printf_string("ssao-viewer %dx%d  mode %s  preset %s  view %s", width, height,
                                  mode ? (std::string(1, mode->letter) + " " + mode->name).c_str() : "-",
                                  preset_name(s.preset), view.c_str()));
    const ssao_settings& c = s.settings;
    if (!s.ssao) {
        lines.push_back("SSAO off (lit without AO)");
    } else {
        lines.push_back(printf_string("samples %u  radius %.3g  bias %.3g  strength %.3g  power %.3g", c.sample_count,
                                      double(c.radius), double(c.bias),
                                      c.strength == SSAO_STRENGTH_OFF ? 0.0 : double(c.strength), double(c.power)));
        std::string sampling = printf_string("kernel %s  distribution %s  rotation %s", cli::name(c.kernel_shape),
                                             cli::name(c.distribution), cli::name(c.rotation));
        sampling += printf_string("  resolution %s", resolution_name(c.resolution));
        lines.push_back(sampling);
        if (c.method == SSAO_METHOD_VISIBILITY)
            lines.push_back(printf_string("blur %s (radius %u)  estimator visibility (%u steps, thickness %.3g)",
                                          cli::name(c.blur), c.blur_radius, c.step_count, double(c.thickness)));
        else
            lines.push_back(printf_string("blur %s (radius %u)  estimator kernel", cli::name(c.blur), c.blur_radius));
        if (t.available)
            lines.push_back(gpu_line(t, c.method));
        else
            lines.push_back("GPU ms: waiting for the first timed frame");
    }
    if (!s.notice.empty()) lines.push_back(s.notice);
    lines.push_back("WASD QZ move  IJKL turn  ERTYU modes  1-4 presets  0 defaults");
    lines.push_back("B blur  M estimator  H resolution  V view  X debug view  C start view  O overlay  F12 screenshot  Esc quit");
    return lines;
}

}  // namespace

int overlay_scale(int width, int height) { return std::max(1, std::min(width, height) / 360); }

int overlay_width(const std::string& line, int scale) {
    std::vector<char> chars(line.begin(), line.end());
    chars.push_back('\0');
    return (stb_easy_font_width(chars.data()) + 2 * kMargin) * std::max(scale, 1);
}

std::vector<std::string> overlay_lines(const State& s, const ssao_timings& t, int width, int height) {
    std::vector<std::string> lines = unwrapped_lines(s, t, width, height);
    std::vector<std::string> fitted;
    // The band keeps a margin from the window's right edge as from its left.
    const int scale = overlay_scale(width, height);
    for (const std::string& line : lines)
        for (std::string& piece : wrap(line, width - kMargin * scale, scale)) fitted.push_back(std::move(piece));
    return fitted;
}

Overlay::Overlay(GladGLContext& gl) : gl_(gl) {
    try {
        program_ = gl_util::make_program(gl, "overlay", kVertex, kFragment);
        gl.GenVertexArrays(1, &vao_);
        gl.GenBuffers(1, &vertices_);
        gl.GenBuffers(1, &indices_);
        gl.BindVertexArray(vao_);
        gl.BindBuffer(GL_ARRAY_BUFFER, vertices_);
        gl.EnableVertexAttribArray(0);
        gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
        gl.EnableVertexAttribArray(1);
        gl.VertexAttribPointer(1, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                               reinterpret_cast<const void*>(offsetof(Vertex, color)));
        gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_);
        gl.BindVertexArray(0);
        gl.BindBuffer(GL_ARRAY_BUFFER, 0);
        gl_util::check(gl, "overlay setup");
    } catch (...) {
        release();
        throw;
    }
}

Overlay::~Overlay() { release(); }

void Overlay::release() {
    if (indices_) gl_.DeleteBuffers(1, &indices_);
    if (vertices_) gl_.DeleteBuffers(1, &vertices_);
    if (vao_) gl_.DeleteVertexArrays(1, &vao_);
    if (program_) gl_.DeleteProgram(program_);
    indices_ = vertices_ = vao_ = program_ = 0;
}

void Overlay::draw(const std::vector<std::string>& lines, int width, int height, int scale) {
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    std::vector<char> chars(text.begin(), text.end());
    chars.push_back('\0');

    // A dark band behind the text first, then the text's quads.
    const float margin = static_cast<float>(kMargin);
    const float w = static_cast<float>(stb_easy_font_width(chars.data())) + 2.0f * margin;
    const float h = static_cast<float>(stb_easy_font_height(chars.data())) + 2.0f * margin;
    std::vector<Vertex> quads = {{0, 0, 0, {0, 0, 0, 160}}, {w, 0, 0, {0, 0, 0, 160}},
                                 {w, h, 0, {0, 0, 0, 160}}, {0, h, 0, {0, 0, 0, 160}}};
    std::vector<Vertex> glyphs(chars.size() * 300 / sizeof(Vertex) + 64);   // ~270 bytes a character
    unsigned char color[4] = {255, 255, 160, 255};
    const int glyph_quads = stb_easy_font_print(margin, margin, chars.data(), color, glyphs.data(),
                                                static_cast<int>(glyphs.size() * sizeof(Vertex)));
    quads.insert(quads.end(), glyphs.begin(), glyphs.begin() + 4 * glyph_quads);
    const size_t quad_count = quads.size() / 4;

    auto& gl = gl_;
    gl.BindVertexArray(vao_);
    if (quad_count > index_capacity_) {
        std::vector<GLuint> index(quad_count * 6);
        for (size_t q = 0; q < quad_count; ++q) {
            const GLuint b = static_cast<GLuint>(q * 4);
            const GLuint six[6] = {b, b + 1, b + 2, b, b + 2, b + 3};
            std::copy_n(six, 6, index.begin() + static_cast<ptrdiff_t>(q * 6));
        }
        gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(index.size() * sizeof(GLuint)), index.data(),
                      GL_STATIC_DRAW);
        index_capacity_ = quad_count;
    }
    gl.BindBuffer(GL_ARRAY_BUFFER, vertices_);
    gl.BufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(quads.size() * sizeof(Vertex)), quads.data(), GL_STREAM_DRAW);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.Viewport(0, 0, width, height);
    gl.Enable(GL_BLEND);
    gl.BlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.UseProgram(program_);
    gl.Uniform2f(gl.GetUniformLocation(program_, "u_size"), static_cast<float>(width), static_cast<float>(height));
    gl.Uniform1f(gl.GetUniformLocation(program_, "u_scale"), static_cast<float>(std::max(scale, 1)));
    gl.DrawElements(GL_TRIANGLES, static_cast<GLsizei>(quad_count * 6), GL_UNSIGNED_INT, nullptr);
    gl.UseProgram(0);
    gl.Disable(GL_BLEND);
    gl.BindBuffer(GL_ARRAY_BUFFER, 0);
    gl.BindVertexArray(0);
    gl_util::check(gl, "the overlay");
}

}  // namespace viewer
