// The plugin on a real GL 3.3 core context. Mesa's EGL hands out 4.5 when 3.3
// is asked for, so this test sets MESA_GL_VERSION_OVERRIDE=3.3 before any EGL
// call, which makes Mesa create a genuine 3.3 core context (GL_VERSION says
// 3.3, so the plugin takes its 3.3 paths: no texture-target query).
//
// KHR_debug: Mesa exposes GL_KHR_debug on its 3.3 core contexts too, so the
// library names its passes there through the extension (checked below). A
// context without KHR_debug is made in a child process with
// MESA_EXTENSION_OVERRIDE=-GL_KHR_debug (Mesa reads the override once per
// process, at its first context). Mesa 22 prints "extension 'GL_KHR_debug'
// cannot be disabled" (it keeps it internally) but leaves it out of the
// extension list, so glad, the library's loader, loads none of its functions:
// the child checks that, then that the library runs as before without
// touching a KHR_debug function (a call through the NULL pointer would crash).
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "child_process.h"
#include "cpu_ssao.h"
#include "crease_textures.h"
#include "debug_groups.h"
#include "gl_fixture.h"
#include "other_context.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include "test_scenes.h"

using analytic::GBuffer;
using analytic::Scene;
using testscenes::crease_scene;
using testscenes::kFov;
using testscenes::make;

TEST_CASE("a GL 3.3 core context works: AO from D24S8 depth matches the CPU formula") {
    const Scene scene = crease_scene();
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 48, 48);
    testgl::Gl33Fixture fx;
    ssao_settings s = make(16, SSAO_BLUR_NONE);
    s.radius = 1.5f;
    s.output_format = SSAO_OUTPUT_R16F;
    const ssao_settings resolved = fx.settings(s);
    const auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, GL_DEPTH24_STENCIL8);
    REQUIRE(r.status == SSAO_OK);
    // The CPU formula sees the depth as D24 stored it.
    GBuffer quantised = g;
    for (float& d : quantised.depth) d = static_cast<float>(std::round(double(d) * 16777215.0) / 16777215.0);
    cpu::Input in;
    in.gbuffer = &quantised;
    analytic::to_floats(proj, in.projection);
    in.depth_step = 1.0 / 16777215.0;
    int off = 0, compared = 0;
    float lo = 1.0f;
    for (int y = 0; y < g.height; y += 2)
        for (int x = 0; x < g.width; x += 2) {
            const float got = r.ao[static_cast<size_t>(y) * g.width + x];
            lo = std::min(lo, got);
            ++compared;
            if (std::abs(got - cpu::ao(in, resolved, x, y)) > 2e-3) ++off;
        }
    CHECK(off <= compared / 50);
    CHECK(lo < 0.9f);  // the crease is there
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("below GL 4.5 a texture of another target is refused (INVALID_TEXTURE) and the host's binding kept") {
    testgl::Gl33Fixture fx;
    auto& gl = fx.gl();
    const testscenes::CreaseTextures scene(fx, 16);
    const glm::dmat4& proj = scene.proj;
    const GLuint depth = scene.depth, normal = scene.normal;
    GLuint array = 0;
    gl.GenTextures(1, &array);
    gl.BindTexture(GL_TEXTURE_2D_ARRAY, array);
    gl.TexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, 16, 16, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, depth);  // the host's texture on unit 0
    ssao_inputs in = fx.inputs(array, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    CHECK(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_ERROR_INVALID_TEXTURE);
    GLint bound = 0;
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    CHECK(static_cast<GLuint>(bound) == depth);
    // GL itself reports the failed binds (documented): exactly those two
    // errors, GL_TEXTURE_2D then (1.2) GL_TEXTURE_2D_MULTISAMPLE.
    CHECK(fx.gl_errors().size() == 2);
    GLint bound_ms = 0;
    gl.GetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &bound_ms);
    CHECK(bound_ms == 0);
    gl.DeleteTextures(1, &array);
}

namespace {

bool has_extension(GladGLContext& gl, const char* name) {
    GLint count = 0;
    gl.GetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
        if (std::strcmp(reinterpret_cast<const char*>(gl.GetStringi(GL_EXTENSIONS, static_cast<GLuint>(i))), name) == 0)
            return true;
    return false;
}

// The crease scene's AO with the CPU formula's tolerance (see the first test):
// how many of the compared pixels differ, or -1 when execute failed.
int ao_mismatches(testgl::Fixture& fx) {
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 32, 32);
    ssao_settings s = make(16, SSAO_BLUR_NONE);
    s.radius = 1.5f;
    s.output_format = SSAO_OUTPUT_R16F;
    const ssao_settings resolved = fx.settings(s);
    const auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    if (r.status != SSAO_OK) return -1;
    cpu::Input in;
    in.gbuffer = &g;
    analytic::to_floats(proj, in.projection);
    int off = 0;
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x)
            if (std::abs(r.ao[static_cast<size_t>(y) * g.width + x] - cpu::ao(in, resolved, x, y)) > 2e-3) ++off;
    return off;
}

// The child's exit code where the driver is not Mesa's.
constexpr int kNotMesa = 77;

// Child process: a 3.3 context without KHR_debug. Exit codes: 0 the library
// ran correctly; 2 the override did not remove KHR_debug on Mesa (kNotMesa:
// not Mesa's driver, which has no such override); 3 execute failed
// or its AO is wrong; 4 a GL error; 5 the debug stack or labels changed;
// 6 execute on another context (told apart by the vertex array's name alone,
// without labels) was not refused with WRONG_CONTEXT, or raised a GL error there.
int child_without_khr_debug() {
    setenv("MESA_EXTENSION_OVERRIDE", "-GL_KHR_debug", 1);
    testgl::Gl33Fixture fx;
    auto& gl = fx.gl();
    if (has_extension(gl, "GL_KHR_debug") || gl.KHR_debug || gl.PushDebugGroup || gl.ObjectLabel) {
        // The override is Mesa's: another driver keeps the extension.
        const char* vendor = reinterpret_cast<const char*>(gl.GetString(GL_VENDOR));
        return vendor && std::strstr(vendor, "Mesa") ? 2 : kNotMesa;
    }
    const int off = ao_mismatches(fx);
    if (off < 0 || off > 32 * 32 / 50) return 3;
    for (int i = 0; i < 3; ++i)
        if (ao_mismatches(fx) != off) return 3;
    if (gl.GetError() != GL_NO_ERROR) return 4;
    testgl::OtherContext other(testgl::OtherContext::Sharing::none, 3, 3);
    other.make_current();
    ssao_inputs in{};
    in.size = sizeof in;
    const ssao_status st = fx.api().execute(fx.ctx(), &in, nullptr);
    const bool clean = other.gl().GetError() == GL_NO_ERROR;
    other.make_first_current();
    if (st != SSAO_ERROR_WRONG_CONTEXT || !clean) return 6;
    return ao_mismatches(fx) == off && gl.GetError() == GL_NO_ERROR ? 0 : 3;
}

}  // namespace

TEST_CASE("GL 3.3 with the KHR_debug extension: the passes are named there too") {
    testgl::Gl33Fixture fx;
    auto& gl = fx.gl();
    // Mesa 22 exposes the extension on 3.3 core; without it this case has
    // nothing to observe (the child-process case covers that context).
    if (!has_extension(gl, "GL_KHR_debug")) {
        MESSAGE("this driver has no GL_KHR_debug on GL 3.3: nothing to observe here");
        return;
    }
    REQUIRE((gl.PushDebugGroup != nullptr));
    testgl::DebugGroupLog log(gl);
    const GLint depth = testgl::debug_group_depth(gl);
    REQUIRE(ao_mismatches(fx) <= 32 * 32 / 50);
    const std::string events = log.text();
    CAPTURE(events);
    CHECK(events == "+ssao\n+ssao: kernel\n-ssao: kernel\n-ssao\n");
    CHECK(testgl::debug_group_depth(gl) == depth);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("without KHR_debug (3.3, extension removed) execute runs as before and calls none of it") {
    // A NULL KHR_debug pointer called by the library would crash the child.
    const testgl::ChildResult child = testgl::run_self("test_plugin_gl33", {"--child-without-khr-debug"});
    CAPTURE(child.crashed);
    CAPTURE(child.code);
    CHECK_FALSE(child.crashed);
    if (child.code == kNotMesa) {
        MESSAGE("not Mesa's driver: GL_KHR_debug cannot be removed here, nothing to observe");
        return;
    }
    CHECK(child.code == 0);
}

TEST_CASE("GL 3.3: create_context with the host's program flagged for deletion leaves program 0, without a GL error") {
    // Without glProgramUniform the plugin binds its programs to set their
    // samplers; the host's flagged program is deleted by that, so 0 is
    // restored rather than its dead name (GL_INVALID_VALUE before).
    testgl::Gl33Fixture fx;
    auto& gl = fx.gl();
    const GLuint host = testgl::make_host_program(gl);
    gl.UseProgram(host);
    gl.DeleteProgram(host);
    ssao_context* second = nullptr;
    REQUIRE(testgl::create_default_context(fx.api(), &second) == SSAO_OK);
    GLint current = -1;
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &current);
    CHECK(current == 0);
    CHECK(fx.gl_errors().empty());
    // Its samplers were still set: it renders the same AO as the fixture's context.
    const testscenes::CreaseTextures scene(fx, 16);
    const auto reference = fx.run(scene.g, scene.proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(reference.status == SSAO_OK);
    const ssao_inputs& in = scene.in;
    ssao_output out{};
    out.size = sizeof out;
    REQUIRE(fx.api().execute(second, &in, &out) == SSAO_OK);
    const auto ao = fx.read_red(out.texture, 16, 16);
    int differing = 0;
    for (size_t i = 0; i < ao.size(); ++i) differing += std::abs(ao[i] - reference.ao[i]) > 1e-6f;
    CHECK(differing == 0);
    CHECK(fx.api().destroy_context(second) == SSAO_OK);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("GL 3.3 with GL_ARB_viewport_array: the host's other viewports, scissor boxes and depth ranges are kept") {
    // The extension gives a 3.3 context GL 4.1's viewport arrays (Mesa offers
    // it); glViewport, glScissor and glDepthRange set every index, so the
    // guard must restore the others one by one here too.
    testgl::Gl33Fixture fx;
    auto& gl = fx.gl();
    if (!gl.ARB_viewport_array) {
        MESSAGE("no GL_ARB_viewport_array on this GL 3.3 context: nothing to observe");
        return;
    }
    gl.ViewportIndexedf(1, 5.0f, 6.0f, 7.0f, 8.0f);
    gl.ScissorIndexed(1, 1, 2, 3, 4);
    gl.DepthRangeIndexed(1, 0.25, 0.75);
    const testscenes::CreaseTextures scene(fx, 16);
    REQUIRE(fx.run(scene.g, scene.proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE).status == SSAO_OK);
    GLfloat v[4] = {};
    GLint box[4] = {};
    GLdouble range[2] = {};
    gl.GetFloati_v(GL_VIEWPORT, 1, v);
    gl.GetIntegeri_v(GL_SCISSOR_BOX, 1, box);
    gl.GetDoublei_v(GL_DEPTH_RANGE, 1, range);
    CHECK((v[0] == 5.0f && v[1] == 6.0f && v[2] == 7.0f && v[3] == 8.0f));
    CHECK((box[0] == 1 && box[1] == 2 && box[2] == 3 && box[3] == 4));
    CHECK((range[0] == 0.25 && range[1] == 0.75));
    CHECK(fx.gl_errors().empty());
}

int main(int argc, char** argv) {
    if (argc == 2 && std::strcmp(argv[1], "--child-without-khr-debug") == 0) return child_without_khr_debug();
    doctest::Context context(argc, argv);
    return context.run();
}
