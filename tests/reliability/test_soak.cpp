// test_soak.cpp - a long session as a renderer has one: 10,000
// executes with the viewport resized every few frames (1x1 and odd sizes
// among them), output format, output target and blur toggled and settings
// changed, then 500 create/destroy cycles. Run under LeakSanitizer by
// scripts/run-sanitizers.sh. Checks: every call OK and no GL error; the GL
// objects the library owns (counted through the proc-address function) stay
// constant during the session and return to zero after every destroy; and the
// last frame equals the first one with the same inputs (no drifting state).
#include "gl_fixture.h"
#include "gl_object_counter.h"
#include "test_scenes.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr int kW = 37, kH = 29;  // odd sizes on purpose
constexpr int kFrames = 10000;
constexpr int kCycles = 500;

struct Viewport {
    int x, y, w, h;
};
// Full (0,0,0,0 = the textures' size), 1x1 at corners, thin strips, odd sizes.
const Viewport kViewports[] = {{0, 0, 0, 0},  {0, 0, 1, 1},   {36, 28, 1, 1}, {5, 3, 1, 1},  {1, 2, 7, 5},
                               {0, 0, 37, 29}, {2, 1, 33, 27}, {0, 0, 17, 1},  {0, 0, 1, 29}, {3, 4, 31, 23},
                               {0, 13, 37, 3}, {11, 0, 13, 29}};
const ssao_blur kBlurs[] = {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN};

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

ssao_settings settings_for(int step) {
    ssao_settings s{};
    s.size = sizeof s;
    s.sample_count = static_cast<uint32_t>(1 + (step * 7) % 64);
    s.radius = 0.2f + 0.1f * static_cast<float>(step % 9);
    s.blur = kBlurs[step % 4];
    s.blur_radius = static_cast<uint32_t>(1 + step % 16);
    s.kernel_shape = static_cast<ssao_kernel_shape>(step % 4);
    s.rotation = static_cast<ssao_rotation>(step % 4);
    s.output_format = (step / 2) % 2 ? SSAO_OUTPUT_R16F : SSAO_OUTPUT_R8;
    if (step % 17 == 16) s.strength = SSAO_STRENGTH_OFF;
    return s;
}

ssao_context* create_counted(const ssao_api& api) {
    ssao_context_desc desc{};
    desc.size = sizeof desc;
    desc.get_proc_address = &reliability::counting_get_proc;
    ssao_context* ctx = nullptr;
    REQUIRE(api.create_context(&desc, &ctx) == SSAO_OK);
    return ctx;
}

}  // namespace

TEST_CASE("soak: 10,000 executes and 500 create/destroy cycles leave nothing behind") {
    using namespace testscenes;
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const ssao_api& api = fx.api();
    const auto proj = analytic::perspective(kFov, double(kW) / kH, 0.1, 100.0);
    const analytic::GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH);
    const GLuint depth = fx.make_depth(GL_DEPTH_COMPONENT32F, kW, kH, g.depth);
    const GLuint normal = fx.make_normals(GL_RGBA16F, kW, kH, g.normal);
    GLuint host_output = 0;
    gl.GenTextures(1, &host_output);
    gl.BindTexture(GL_TEXTURE_2D, host_output);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_R16F, kW, kH, 0, GL_RED, GL_FLOAT, nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    const ssao_inputs base = fx.inputs(depth, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);

    // ---- one long session
    const auto t0 = std::chrono::steady_clock::now();
    ssao_context* ctx = create_counted(api);
    REQUIRE(reliability::live_total() > 0);  // the wrappers saw the library's objects
    const ssao_settings first_settings = settings_for(1);
    REQUIRE(api.set_settings(ctx, &first_settings) == SSAO_OK);
    ssao_output out{};
    out.size = sizeof out;
    REQUIRE(api.execute(ctx, &base, &out) == SSAO_OK);
    const std::vector<float> first = fx.read_red(out.texture, kW, kH);

    int failures = 0;
    long long live_min = -1, live_max = -1;
    int settings_step = 1;
    for (int frame = 1; frame < kFrames; ++frame) {
        if (frame % 11 == 0) {
            const ssao_settings s = settings_for(++settings_step);
            if (api.set_settings(ctx, &s) != SSAO_OK) ++failures;
        }
        ssao_inputs in = base;
        const Viewport& v = kViewports[(frame / 3) % (sizeof kViewports / sizeof kViewports[0])];
        in.viewport[0] = v.x;
        in.viewport[1] = v.y;
        in.viewport[2] = v.w;
        in.viewport[3] = v.h;
        if (frame % 13 == 0) in.output_texture = host_output;
        if (api.execute(ctx, &in, &out) != SSAO_OK) {
            if (failures++ == 0) MESSAGE("frame ", frame, ": ", api.last_error(ctx));
        }
        if (frame % 97 == 0) {
            ssao_timings t{};
            t.size = sizeof t;
            if (api.get_timings(ctx, &t) != SSAO_OK) ++failures;
        }
        // After every kind of frame has been seen, the object count is fixed:
        // resizes and format changes reallocate in place.
        if (frame >= 500) {
            const long long live = reliability::live_total();
            live_min = live_min < 0 ? live : std::min(live_min, live);
            live_max = std::max(live_max, live);
        }
    }
    CHECK(failures == 0);
    CHECK(live_min == live_max);
    // What a context can own at most: 6 programs (ao, visibility, blur,
    // downsample, upsample, normals view: variant 0 of each, compiled at
    // creation), vertex array, 2 framebuffers (the passes' and the depth
    // copy's source), 2 uniform buffers, noise texture, sampler, the plan's 4
    // intermediates (a half-resolution plan with a separable blur uses all 4:
    // the grid's view z and normals, the AO, the blur's x pass) and 2 sky
    // masks (the grid's, the copy of the host's depth), the output, and a
    // timestamp per pass boundary for each frame in flight.
    CHECK(live_max <= 6 + 7 + 4 + 2 + 1 + 8 * (SSAO_MAX_PASSES + 1));
    // Back to the first frame's settings and viewport: the same AO, bit for bit.
    REQUIRE(api.set_settings(ctx, &first_settings) == SSAO_OK);
    REQUIRE(api.execute(ctx, &base, &out) == SSAO_OK);
    const std::vector<float> last = fx.read_red(out.texture, kW, kH);
    CHECK(std::memcmp(first.data(), last.data(), first.size() * sizeof(float)) == 0);
    REQUIRE(api.destroy_context(ctx) == SSAO_OK);
    const auto left = reliability::live_objects();
    CHECK(left.empty());
    for (const auto& kind : left) MESSAGE("left after destroy: ", kind.second, " ", kind.first);
    const double session_s = seconds_since(t0);

    // ---- create/destroy cycles, a few frames each
    const auto t1 = std::chrono::steady_clock::now();
    int cycles_with_leftovers = 0;
    failures = 0;
    for (int cycle = 0; cycle < kCycles; ++cycle) {
        ssao_context* c = create_counted(api);
        const ssao_settings s = settings_for(cycle);
        if (api.set_settings(c, &s) != SSAO_OK) ++failures;
        ssao_inputs in = base;
        const Viewport& v = kViewports[cycle % (sizeof kViewports / sizeof kViewports[0])];
        std::memcpy(in.viewport, &v, sizeof in.viewport);
        if (cycle % 2) in.output_texture = host_output;
        for (int f = 0; f < 1 + cycle % 3; ++f)
            if (api.execute(c, &in, nullptr) != SSAO_OK) ++failures;
        if (api.destroy_context(c) != SSAO_OK) ++failures;
        if (reliability::live_total() != 0) ++cycles_with_leftovers;
    }
    CHECK(failures == 0);
    CHECK(cycles_with_leftovers == 0);
    const double cycles_s = seconds_since(t1);
    CHECK(fx.gl_errors().empty());
    for (const auto& e : fx.gl_errors()) MESSAGE("GL error: ", e);
    MESSAGE("soak: ", kFrames, " executes in ", session_s, " s; ", kCycles, " create/destroy cycles in ", cycles_s,
            " s; ", reliability::wrapped_calls(), " counted object calls");
    gl.DeleteTextures(1, &host_output);
}

TEST_CASE("soak: the object counter sees what is made and deleted through it, so a leak would show") {
    testgl::Fixture fx;  // a current EGL context
    const long long before = reliability::live_total();
    auto gen = reinterpret_cast<PFNGLGENTEXTURESPROC>(reliability::counting_get_proc(nullptr, "glGenTextures"));
    auto del = reinterpret_cast<PFNGLDELETETEXTURESPROC>(reliability::counting_get_proc(nullptr, "glDeleteTextures"));
    auto make_program = reinterpret_cast<PFNGLCREATEPROGRAMPROC>(reliability::counting_get_proc(nullptr, "glCreateProgram"));
    auto delete_program = reinterpret_cast<PFNGLDELETEPROGRAMPROC>(reliability::counting_get_proc(nullptr, "glDeleteProgram"));
    REQUIRE((gen && del && make_program && delete_program));
    GLuint t[3] = {};
    gen(3, t);
    const GLuint p = make_program();
    CHECK(reliability::live_total() == before + 4);
    CHECK(reliability::live_objects()["texture"] == 3);
    del(2, t);
    delete_program(p);
    CHECK(reliability::live_total() == before + 1);  // one texture "leaked"
    del(1, t + 2);
    CHECK(reliability::live_total() == before);
    CHECK(fx.gl_errors().empty());
}
