// The plugin on a real GL 3.3 core context. Mesa's EGL hands out 4.5 when 3.3
// is asked for, so this test sets MESA_GL_VERSION_OVERRIDE=3.3 before any EGL
// call, which makes Mesa create a genuine 3.3 core context (GL_VERSION says
// 3.3, so the plugin takes its 3.3 paths: no texture-target query).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "cpu_ssao.h"
#include "gl_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
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
    setenv("MESA_GL_VERSION_OVERRIDE", "3.3", 1);
    testgl::Fixture fx(3, 3);
    auto& gl = fx.gl();
    const std::string version = reinterpret_cast<const char*>(gl.GetString(GL_VERSION));
    CAPTURE(version);
    REQUIRE(version.rfind("3.3", 0) == 0);
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
    setenv("MESA_GL_VERSION_OVERRIDE", "3.3", 1);
    testgl::Fixture fx(3, 3);
    auto& gl = fx.gl();
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 16, 16);
    const GLuint depth = fx.make_depth(GL_DEPTH_COMPONENT32F, 16, 16, g.depth);
    const GLuint normal = fx.make_normals(GL_RGBA16F, 16, 16, g.normal);
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
    // GL itself reports the failed bind (documented): exactly that one error.
    CHECK(fx.gl_errors().size() == 1);
    gl.DeleteTextures(1, &array);
}

TEST_CASE("GL 3.3: create_context with the host's program flagged for deletion leaves program 0, without a GL error") {
    // Without glProgramUniform the plugin binds its programs to set their
    // samplers; the host's flagged program is deleted by that, so 0 is
    // restored rather than its dead name (GL_INVALID_VALUE before).
    setenv("MESA_GL_VERSION_OVERRIDE", "3.3", 1);
    testgl::Fixture fx(3, 3);
    auto& gl = fx.gl();
    const GLuint host = testgl::make_host_program(gl);
    gl.UseProgram(host);
    gl.DeleteProgram(host);
    ssao_context_desc desc{};
    desc.size = sizeof desc;
    desc.get_proc_address = &eglctx::Context::get_proc;
    ssao_context* second = nullptr;
    REQUIRE(fx.api().create_context(&desc, &second) == SSAO_OK);
    GLint current = -1;
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &current);
    CHECK(current == 0);
    CHECK(fx.gl_errors().empty());
    // Its samplers were still set: it renders the same AO as the fixture's context.
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 16, 16);
    const auto reference = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(reference.status == SSAO_OK);
    const GLuint depth = fx.make_depth(GL_DEPTH_COMPONENT32F, 16, 16, g.depth);
    const GLuint normal = fx.make_normals(GL_RGBA16F, 16, 16, g.normal);
    const ssao_inputs in = fx.inputs(depth, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
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
