#include "report_text.h"

#include "cli.h"
#include "preset_text.h"

#include <cstdio>

namespace report_text {

namespace {

std::string ms(const char* name, double v) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%s %.3f ms", name, v);
    return buffer;
}

}  // namespace

// The debug groups' names, so the printed times and a GPU debugger's capture
// say the same.
const char* pass_name(uint32_t kind, uint32_t method, bool brief) {
    switch (kind) {
        case SSAO_PASS_OCCLUSION: return method == SSAO_METHOD_VISIBILITY ? (brief ? "vis" : "visibility") : "kernel";
        case SSAO_PASS_BLUR_X: return "blur x";
        case SSAO_PASS_BLUR_Y: return "blur y";
        case SSAO_PASS_CLEAR: return "clear";
        case SSAO_PASS_GRID: return "grid";
        case SSAO_PASS_UPSAMPLE: return brief ? "up" : "upsample";
        case SSAO_PASS_NORMALS_VIEW: return brief ? "normals" : "normals view";
        default: return "pass";
    }
}

std::string estimator(const ssao_settings& s) {
    std::string words = preset_text::describe(s);
    char buffer[64];
    if (s.method == SSAO_METHOD_VISIBILITY) {
        std::snprintf(buffer, sizeof buffer, ", thickness %.4g", static_cast<double>(s.thickness));
        words += buffer;
        if (s.max_step_texels > 0.0f) {
            std::snprintf(buffer, sizeof buffer, ", steps <= %.4g texels apart", static_cast<double>(s.max_step_texels));
            words += buffer;
        }
    } else {
        words += std::string(", kernel ") + cli::name(s.kernel_shape);
    }
    return words;
}

std::string pass_times(const ssao_timings& t, uint32_t method) {
    std::string line;
    for (uint32_t i = 0; i < t.pass_count && i < SSAO_MAX_PASSES; ++i)
        line += ms(pass_name(t.pass_kind[i], method), t.pass_ms[i]) + ", ";
    return line + ms("total", t.total_ms);
}

}  // namespace report_text
