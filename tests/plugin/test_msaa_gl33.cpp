// MSAA inputs on a genuine GL 3.3 core context: no
// GL_TEXTURE_TARGET query there, so the library tells a multisampled input
// from a 2D one by binding it (see test_plugin_gl33.cpp for how the context
// is made). The first execute tries the previous frame's target (2D at
// first): that failed bind raises one GL_INVALID_OPERATION, documented in
// ssao.h; a host that keeps multisampled inputs raises none after that.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "gl_fixture.h"
#include "msaa_copy.h"
#include "test_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

using analytic::GBuffer;
using testscenes::crease_scene;
using testscenes::kFov;

namespace {

// The bindings the MSAA path touches (gl_state_snapshot.h reads GL 4.x state a
// 3.3 context does not have): both texture targets of units 0..3, the active
// unit, the blend function and equation.
std::vector<GLint> bindings(GladGLContext& gl) {
    std::vector<GLint> v;
    GLint active = 0;
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
    v.push_back(active);
    for (GLenum u = 0; u < 4; ++u) {
        gl.ActiveTexture(GL_TEXTURE0 + u);
        GLint t = 0, ms = 0;
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &t);
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &ms);
        v.push_back(t);
        v.push_back(ms);
    }
    gl.ActiveTexture(static_cast<GLenum>(active));
    for (GLenum e : {GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA, GL_BLEND_EQUATION_RGB,
                     GL_BLEND_EQUATION_ALPHA, GL_DRAW_FRAMEBUFFER_BINDING, GL_CURRENT_PROGRAM}) {
        GLint x = 0;
        gl.GetIntegerv(e, &x);
        v.push_back(x);
    }
    return v;
}

// The crease scene at w x h, single-sample and as 4x MSAA textures whose
// every sample holds it (D32F depth, RGBA8 normals).
struct CreaseInputs {
    glm::dmat4 proj;
    msaa::Textures single, ms;
    CreaseInputs(testgl::Gl33Fixture& fx, int w, int h)
        : proj(analytic::perspective(kFov, double(w) / h, 0.1, 100.0)),
          single(fx.upload(analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, w, h),
                           GL_DEPTH_COMPONENT32F, GL_RGBA8)),
          ms(msaa::make(fx.gl(), {single}, w, h, 4, GL_DEPTH_COMPONENT32F, GL_RGBA8)) {}
};

}  // namespace

TEST_CASE("GL 3.3: MSAA inputs give the single-sample AO and errors are refused and bindings are restored") {
    testgl::Gl33Fixture fx;
    auto& gl = fx.gl();
    const int w = 32, h = 24;
    const CreaseInputs crease(fx, w, h);
    const auto& [proj, single, ms] = crease;
    ssao_settings s = testscenes::make(16, SSAO_BLUR_DEPTH_AWARE);
    s.output_format = SSAO_OUTPUT_R16F;
    s.radius = 1.5f;
    for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY}) {
        CAPTURE(method);
        s.method = method;
        fx.settings(s);
        ssao_inputs in = fx.inputs(single.depth, single.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        in.normal_packing = SSAO_NORMAL_PACKING_UNORM;
        ssao_output out{};
        out.size = sizeof out;
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        const auto want = fx.read_red(out.texture, w, h);
        in.depth_texture = ms.depth;
        in.normal_texture = ms.normal;
        in.sample_index = 2;
        const size_t errors_before = fx.gl_errors().size();
        // The host's own textures on both targets of units 0..3, and its blending.
        GLuint host[8] = {};
        gl.GenTextures(8, host);
        for (GLenum u = 0; u < 4; ++u) {
            gl.ActiveTexture(GL_TEXTURE0 + u);
            gl.BindTexture(GL_TEXTURE_2D, host[u]);
            gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, host[4 + u]);
        }
        gl.ActiveTexture(GL_TEXTURE1);
        gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_DST_COLOR, GL_ZERO);
        gl.BlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
        const std::vector<GLint> before = bindings(gl);
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        // At most the one failed 2D bind of the first multisampled frame.
        CHECK(fx.gl_errors().size() - errors_before <= 1);
        const size_t errors_after_first = fx.gl_errors().size();
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        CHECK(fx.gl_errors().size() == errors_after_first);  // a steady MSAA host: no failed bind
        CHECK(bindings(gl) == before);
        CHECK(fx.read_red(out.texture, w, h) == want);
    }
    // Refusals found by binding: mixed targets and a sample index out of range.
    ssao_inputs in = fx.inputs(ms.depth, single.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    ssao_output out{};
    out.size = sizeof out;
    CHECK(fx.api().execute(fx.ctx(), &in, &out) == SSAO_ERROR_INVALID_TEXTURE);
    CHECK(std::string(fx.api().last_error(fx.ctx())).find("both must be multisampled") != std::string::npos);
    in.normal_texture = ms.normal;
    in.sample_index = 4;
    CHECK(fx.api().execute(fx.ctx(), &in, &out) == SSAO_ERROR_INVALID_VALUE);
    CHECK(std::string(fx.api().last_error(fx.ctx())).find("sample_index") != std::string::npos);
}

TEST_CASE("GL 3.3: a refused multisampled execute does not change the target the next execute tries first") {
    // Below GL 4.5 the inputs' target is found by binding, the last
    // successful execute's first: a refused call must leave that as it was,
    // or the next single-sample frame raises a failed-bind error.
    testgl::Gl33Fixture fx;
    const CreaseInputs crease(fx, 16, 12);
    const auto& [proj, single, ms] = crease;
    fx.settings(testscenes::make(8, SSAO_BLUR_NONE));
    ssao_inputs in = fx.inputs(single.depth, single.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    in.normal_packing = SSAO_NORMAL_PACKING_UNORM;
    REQUIRE(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_OK);
    const size_t errors_single = fx.gl_errors().size();
    ssao_inputs refused = in;
    refused.depth_texture = ms.depth;
    refused.normal_texture = ms.normal;
    refused.sample_index = 9;  // out of range: refused after the inputs were bound
    CHECK(fx.api().execute(fx.ctx(), &refused, nullptr) == SSAO_ERROR_INVALID_VALUE);
    const size_t errors_refused = fx.gl_errors().size();
    CHECK(errors_refused - errors_single <= 1);  // the documented failed 2D bind of a first multisampled input
    REQUIRE(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_OK);
    CHECK(fx.gl_errors().size() == errors_refused);
}

TEST_CASE("GL 3.3: MULTIPLY multiplies the lit image and restores the blend function, equation and enable") {
    testgl::Gl33Fixture fx;
    auto& gl = fx.gl();
    const int w = 32, h = 24;
    const auto proj = analytic::perspective(kFov, double(w) / h, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, w, h);
    const GLuint depth = fx.make_depth(GL_DEPTH_COMPONENT32F, w, h, g.depth);
    const GLuint normal = fx.make_normals(GL_RGBA8, w, h, g.normal);
    ssao_settings s = testscenes::make(16, SSAO_BLUR_DEPTH_AWARE);
    s.output_format = SSAO_OUTPUT_R16F;
    s.radius = 1.5f;
    fx.settings(s);
    ssao_inputs in = fx.inputs(depth, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    in.normal_packing = SSAO_NORMAL_PACKING_UNORM;
    ssao_output out{};
    out.size = sizeof out;
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    const auto ao = fx.read_red(out.texture, w, h);
    // A grey lit image (RGBA32F: the blender's product is exact).
    std::vector<float> lit(size_t(w) * h * 4, 0.75f);
    GLuint target = 0;
    gl.GenTextures(1, &target);
    gl.BindTexture(GL_TEXTURE_2D, target);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, lit.data());
    gl.BindTexture(GL_TEXTURE_2D, 0);
    for (bool host_blend : {false, true}) {
        CAPTURE(host_blend);
        if (host_blend) gl.Enable(GL_BLEND); else gl.Disable(GL_BLEND);
        gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_DST_COLOR, GL_ZERO);
        gl.BlendEquationSeparate(GL_FUNC_SUBTRACT, GL_MAX);
        const std::vector<GLint> before = bindings(gl);
        gl.BindTexture(GL_TEXTURE_2D, target);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, w, h, 0, GL_RGBA, GL_FLOAT, lit.data());
        gl.BindTexture(GL_TEXTURE_2D, 0);
        in.output_texture = target;
        in.output_mode = SSAO_OUTPUT_MODE_MULTIPLY;
        REQUIRE(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_OK);
        CHECK(bindings(gl) == before);
        CHECK(bool(gl.IsEnabled(GL_BLEND)) == host_blend);
        std::vector<float> got(size_t(w) * h * 4);
        gl.BindTexture(GL_TEXTURE_2D, target);
        gl.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, got.data());
        gl.BindTexture(GL_TEXTURE_2D, 0);
        // The reference AO went through R16F; the multiplied one did not.
        int wrong = 0;
        for (size_t i = 0; i < ao.size(); ++i) {
            for (int c = 0; c < 3; ++c) wrong += std::abs(got[i * 4 + c] - 0.75f * ao[i]) > 1e-3f;
            wrong += got[i * 4 + 3] != 0.75f;  // alpha untouched
        }
        CHECK(wrong == 0);
        CHECK(*std::min_element(ao.begin(), ao.end()) < 0.9f);  // there was occlusion to multiply
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("GL 3.3 with GL_ARB_draw_buffers_blend: MULTIPLY keeps every draw buffer's own blend function and equation") {
    // The extension gives a 3.3 context GL 4.0's per-buffer blend state
    // through ARB-suffixed calls (Mesa offers it); the global glBlendFunc*
    // sets every buffer, so a restore through it would give buffer 1 buffer 0's.
    testgl::Gl33Fixture fx;
    auto& gl = fx.gl();
    if (!gl.ARB_draw_buffers_blend) {
        MESSAGE("no GL_ARB_draw_buffers_blend on this GL 3.3 context: nothing to observe");
        return;
    }
    const int w = 16, h = 16;
    const auto proj = analytic::perspective(kFov, double(w) / h, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, w, h);
    const GLuint depth = fx.make_depth(GL_DEPTH_COMPONENT32F, w, h, g.depth);
    GLuint target = 0;
    gl.GenTextures(1, &target);
    gl.BindTexture(GL_TEXTURE_2D, target);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BlendFuncSeparateiARB(0, GL_SRC_ALPHA, GL_ONE, GL_DST_COLOR, GL_ZERO);
    gl.BlendEquationSeparateiARB(0, GL_FUNC_SUBTRACT, GL_MAX);
    gl.BlendFuncSeparateiARB(1, GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR, GL_SRC_COLOR, GL_ONE);
    gl.BlendEquationSeparateiARB(1, GL_MIN, GL_FUNC_REVERSE_SUBTRACT);
    fx.settings(testscenes::make(8, SSAO_BLUR_NONE));
    ssao_inputs in = fx.inputs(depth, 0, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    in.output_texture = target;
    in.output_mode = SSAO_OUTPUT_MODE_MULTIPLY;
    REQUIRE(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_OK);
    const GLenum queries[] = {GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA,
                              GL_BLEND_DST_ALPHA, GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA};
    const GLint expected[2][6] = {
        {GL_SRC_ALPHA, GL_ONE, GL_DST_COLOR, GL_ZERO, GL_FUNC_SUBTRACT, GL_MAX},
        {GL_ONE_MINUS_DST_ALPHA, GL_CONSTANT_COLOR, GL_SRC_COLOR, GL_ONE, GL_MIN, GL_FUNC_REVERSE_SUBTRACT}};
    for (GLuint buffer : {0u, 1u}) {
        CAPTURE(buffer);
        for (int q = 0; q < 6; ++q) {
            CAPTURE(q);
            GLint got = 0;
            gl.GetIntegeri_v(queries[q], buffer, &got);
            CHECK(got == expected[buffer][q]);
        }
    }
    CHECK(fx.gl_errors().empty());
}

int main(int argc, char** argv) {
    doctest::Context context;
    context.applyCommandLine(argc, argv);
    return context.run();
}
