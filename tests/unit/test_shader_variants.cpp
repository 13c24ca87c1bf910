// test_shader_variants.cpp - every pass program compiles and links in every
// variant (plan.h, namespace variant): each bit alone and all bits together,
// on a GL 3.3 core and a 4.5 core context. The plugin compiles a variant only
// when a frame first asks for it, so a broken #ifdef path would otherwise
// surface as SSAO_ERROR_SHADER in a host's execute.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "egl_context.h"
#include "pass_table.h"
#include "plan.h"
#include "settings.h"
#include "shader_build.h"
#include "shader_source.h"

#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace ssao_impl;

namespace {

// "" when the program links, else the log.
std::string build(GladGLContext& gl, ProgramId id, uint32_t variant) {
    GLuint program = 0;
    const std::string log = shader_build::link_pass_program(gl, id, variant, program);
    gl.DeleteProgram(program);
    return log;
}

std::vector<uint32_t> variants_to_try() {
    std::vector<uint32_t> v{0u, (1u << variant::kBits) - 1u};
    for (int bit = 0; bit < variant::kBits; ++bit) v.push_back(1u << bit);
    return v;
}

void check_all(int major, int minor) {
    eglctx::Options options;
    options.major = major;
    options.minor = minor;
    std::string error;
    auto egl = eglctx::Context::create(options, error);
    REQUIRE_MESSAGE(egl, "no EGL context: " << error);
    for (int i = 0; i < static_cast<int>(ProgramId::count); ++i) {
        const ProgramId id = static_cast<ProgramId>(i);
        for (uint32_t variant : variants_to_try()) {
            CAPTURE(program_info(id).file_name);
            CAPTURE(variant);
            CHECK(build(egl->gl(), id, variant) == "");
        }
    }
}

// Every (program, variant) pair the planner asks for over a grid of settings
// and inputs: the combinations a host can actually reach.
std::set<std::pair<ProgramId, uint32_t>> planned_pairs() {
    std::set<std::pair<ProgramId, uint32_t>> pairs;
    for (int method = 1; method <= 2; ++method)
        for (int res = 1; res <= 3; ++res)
            for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_DEPTH_AWARE})
                for (int view = 0; view <= 4; ++view)
                    for (int features = 0; features < 8; ++features)
                        for (int inputs = 0; inputs < 16; ++inputs) {
                            ssao_settings in{};
                            in.size = sizeof in;
                            in.method = static_cast<ssao_method>(method);
                            in.resolution = static_cast<ssao_resolution>(res);
                            in.blur = blur;
                            in.debug_view = static_cast<ssao_debug_view>(view);
                            if (features & 1) in.fade_end = 10.0f;
                            if (features & 2) in.radius_pixels = 16.0f;
                            if (features & 4) in.strength = SSAO_STRENGTH_OFF;
                            ssao_settings s{};
                            s.size = sizeof s;
                            std::string why;
                            REQUIRE(resolve_settings(in, s, why) == SSAO_OK);
                            AnalysedInputs a;
                            a.texture_width = a.viewport[2] = 33;
                            a.texture_height = a.viewport[3] = 17;
                            a.depth.bits = 32;
                            a.depth.is_float = true;
                            a.multisample = inputs & 1;
                            a.samples = a.multisample ? 4 : 0;
                            a.normals_from_depth = inputs & 2;
                            a.frame_index = inputs & 4 ? 7u : 0u;
                            a.multiply_output = inputs & 8;
                            a.output_texture = a.multiply_output ? 9u : 0u;
                            const FramePlan plan = plan_frame(s, a);
                            for (int i = 0; i < plan.pass_count; ++i)
                                if (program_of(plan.passes[i].kind) != ProgramId::none)
                                    pairs.insert({program_of(plan.passes[i].kind), plan.passes[i].variant});
                        }
    return pairs;
}

}  // namespace

TEST_CASE("shader variants: every (program, variant) the planner can ask for compiles and links (GL 4.5 and 3.3 core)") {
    const auto pairs = planned_pairs();
    MESSAGE(pairs.size() << " distinct (program, variant) pairs planned");
    CHECK(pairs.size() > 20);  // the grid reaches the features, not only variant 0
    for (int major_minor : {45, 33}) {
        eglctx::Options options;
        options.major = major_minor / 10;
        options.minor = major_minor % 10;
        std::string error;
        auto egl = eglctx::Context::create(options, error);
        REQUIRE_MESSAGE(egl, "no EGL context: " << error);
        for (const auto& p : pairs) {
            CAPTURE(major_minor);
            CAPTURE(program_info(p.first).file_name);
            CAPTURE(p.second);
            CHECK(build(egl->gl(), p.first, p.second) == "");
        }
    }
}

TEST_CASE("shader variants: each bit's define is in the source and no other") {
    for (int bit = 0; bit < variant::kBits; ++bit) {
        CAPTURE(bit);
        const std::string define = std::string("#define SSAO_") + variant_name(bit) + " 1\n";
        CHECK(fragment_source(ProgramId::kernel, 1u << bit).find(define) != std::string::npos);
        CHECK(fragment_source(ProgramId::kernel, 0).find(define) == std::string::npos);
    }
    // #version must stay the first line for GLSL to accept the source.
    CHECK(fragment_source(ProgramId::blur, (1u << variant::kBits) - 1u).rfind("#version 330 core\n", 0) == 0);
}

TEST_CASE("shader variants: every program compiles and links in every variant (GL 4.5 core)") { check_all(4, 5); }

TEST_CASE("shader variants: every program compiles and links in every variant (GL 3.3 core)") { check_all(3, 3); }
