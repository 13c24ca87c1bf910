// EGL integration tests of the plugin on Mesa llvmpipe, loaded with dlopen as
// a host would: analytic oracles, a CPU implementation of the same formula,
// GL state restoration, a GL 3.3 core context, and KHR_debug error capture.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "cpu_ssao.h"
#include "gl_fixture.h"
#include "gl_state_snapshot.h"
#include "gl_util.h"
#include "test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>

using analytic::GBuffer;
using analytic::Scene;

using testscenes::crease_scene;
using testscenes::kCreaseView;
using testscenes::kFov;
using testscenes::make;

TEST_CASE("a plane facing the camera stays unoccluded") {
    testgl::Fixture fx;
    Scene scene;
    scene.add_quad({-100, -100, -5}, {200, 0, 0}, {0, 200, 0});
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 64, 64);
    for (ssao_kernel_shape shape : {SSAO_KERNEL_HEMISPHERE, SSAO_KERNEL_SEPARABLE}) {
        ssao_settings s = make(32, SSAO_BLUR_DEFAULT);
        s.kernel_shape = shape;
        fx.settings(s);
        const auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        CHECK(*std::min_element(r.ao.begin(), r.ao.end()) >= 0.98f);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("the sphere kernel gives the Crytek look: a flat plane reads about one half") {
    testgl::Fixture fx;
    Scene scene;
    scene.add_quad({-100, -100, -5}, {200, 0, 0}, {0, 200, 0});
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 48, 48);
    ssao_settings s = make(64, SSAO_BLUR_NONE);
    s.kernel_shape = SSAO_KERNEL_SPHERE;
    s.distribution = SSAO_DISTRIBUTION_UNIFORM;
    s.bias = 1e-5f;  // count every sample below the surface
    fx.settings(s);
    const auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(r.status == SSAO_OK);
    double mean = 0;
    for (float v : r.ao) mean += v;
    mean /= r.ao.size();
    CHECK(mean == doctest::Approx(0.5).epsilon(0.1));
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("a 90-degree crease darkens towards the edge, monotonically") {
    testgl::Fixture fx;
    const Scene scene = crease_scene();
    // Camera at the origin looking down the -z axis a little downwards.
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 96, 96);
    const double radius = 1.5;
    ssao_settings s = make(32, SSAO_BLUR_DEFAULT);
    s.radius = static_cast<float>(radius);
    fx.settings(s);
    const auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(r.status == SSAO_OK);
    // Floor pixels, binned by their distance to the crease (the wall at z=-6),
    // out to a little beyond the radius.
    const int bins = 10;
    std::vector<double> sum(bins, 0.0), count(bins, 0.0);
    for (int y = 0; y < g.height; ++y)
        for (int x = 8; x < g.width - 8; ++x) {
            if (g.sky(x, y)) continue;
            const glm::dvec3 p = glm::dvec3(glm::inverse(kCreaseView) *
                                             glm::dvec4(g.position[static_cast<size_t>(y) * g.width + x], 1.0));
            if (std::abs(p.y) > 1e-6) continue;  // floor only
            const double dist = p.z + 6.0;
            const int b = static_cast<int>(dist / (radius / 8));
            if (b < 0 || b >= bins) continue;
            sum[b] += r.ao[static_cast<size_t>(y) * g.width + x];
            count[b] += 1;
        }
    std::vector<double> mean(bins);
    for (int b = 0; b < bins; ++b) {
        CAPTURE(b);
        REQUIRE(count[b] > 10);
        mean[b] = sum[b] / count[b];
        MESSAGE("distance bin " << b << ": AO " << mean[b]);
    }
    for (int b = 1; b < bins; ++b) CHECK(mean[b] >= mean[b - 1] - 0.01);
    CHECK(mean[0] < mean[bins - 1] - 0.15);  // clearly darker at the edge
    CHECK(mean[bins - 1] > 0.9);             // beyond the radius: open floor
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("the GPU output matches a CPU implementation of the same formula") {
    testgl::Fixture fx;
    Scene scene = crease_scene();
    scene.add_box({-1.5, -1, -4.5}, {-0.5, 0.2, -3.5});
    scene.add_box({0.8, -1, -5.2}, {1.6, 1.0, -4.4});
    const auto proj = analytic::perspective(kFov, 4.0 / 3.0, 0.1, 100.0);
    const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 80, 60);
    cpu::Input in;
    in.gbuffer = &g;
    analytic::to_floats(proj, in.projection);
    in.clip = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
    for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY})
    for (ssao_rotation rotation : {SSAO_ROTATION_GRADIENT_NOISE, SSAO_ROTATION_NOISE_4X4, SSAO_ROTATION_HASH, SSAO_ROTATION_NONE}) {
        CAPTURE(method);
        CAPTURE(rotation);
        ssao_settings s = make(16, SSAO_BLUR_NONE, rotation);
        s.output_format = SSAO_OUTPUT_R16F;
        s.power = 1.5f;
        s.method = method;
        s.step_count = 6;
        s.thickness = 0.3f;  // smaller than the boxes, so thickness decides some steps
        const ssao_settings resolved = fx.settings(s);
        const auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        int compared = 0, off = 0, occluded = 0;
        double worst = 0;
        for (int y = 1; y < g.height; y += 3)
            for (int x = 2; x < g.width; x += 3) {
                const float expect = cpu::ao(in, resolved, x, y);
                const float got = r.ao[static_cast<size_t>(y) * g.width + x];
                const double diff = std::abs(expect - got);
                worst = std::max(worst, diff);
                ++compared;
                if (expect < 0.95f) ++occluded;
                // One kernel sample (or direction) flipping across a
                // comparison boundary (float vs double) moves the result by
                // about 1/16.
                if (diff > 2e-3) ++off;
                CHECK(diff < 0.09);
            }
        MESSAGE("compared " << compared << " pixels (" << occluded << " below 0.95), " << off
                            << " differ by more than 2e-3, worst " << worst);
        CHECK(off <= compared / 50);
        CHECK(occluded >= compared / 20);  // the comparison covers occluded pixels, not only open floor
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("background pixels exit early with exactly 1 and the passes run are only those asked for") {
    testgl::Fixture fx;
    Scene scene;
    scene.add_quad({-1, -1, -5}, {2, 0, 0}, {0, 2, 0});  // a small quad in the sky
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 32, 32);
    fx.settings(make(16, SSAO_BLUR_DEFAULT));
    auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(r.status == SSAO_OK);
    // The depth-aware blur tests its taps against the grid's tangent planes.
    CHECK(r.output.passes_run == (SSAO_PASS_GRID | SSAO_PASS_AO | SSAO_PASS_BLUR_X | SSAO_PASS_BLUR_Y));
    for (int i = 0; i < 32 * 32; ++i)
        if (g.sky(i % 32, i / 32)) CHECK(r.ao[i] == 1.0f);

    fx.settings(make(16, SSAO_BLUR_NONE));
    r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    CHECK(r.output.passes_run == SSAO_PASS_AO);
    fx.settings(make(16, SSAO_BLUR_BOX_4X4));
    r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    CHECK(r.output.passes_run == (SSAO_PASS_AO | SSAO_PASS_BLUR_X));
    ssao_settings off = make(16, SSAO_BLUR_DEFAULT);
    off.strength = SSAO_STRENGTH_OFF;
    fx.settings(off);
    r = fx.run(crease_scene().quads.empty() ? g : analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 32, 32),
               proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    CHECK(r.output.passes_run == SSAO_PASS_CLEAR);
    CHECK(*std::min_element(r.ao.begin(), r.ao.end()) == 1.0f);
    CHECK(fx.gl_errors().empty());
}

namespace {

// Everything else an engine leaves set, each to a non-default value.
// The host framebuffer must be bound (its draw and read buffers are set).
void disturb_engine_state(GladGLContext& gl) {
    gl.ViewportIndexedf(0, 3.25f, 5.5f, 17.75f, 19.125f);  // sub-pixel viewport at index 0
    gl.Enable(GL_PRIMITIVE_RESTART);
    gl.PrimitiveRestartIndex(0xfffe);
    gl.Enable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
    gl.Enable(GL_DEPTH_CLAMP);
    gl.Enable(GL_PROGRAM_POINT_SIZE);
    gl.DepthRange(0.25, 0.75);
    gl.DepthRangeIndexed(2, 0.125, 0.875);  // glDepthRange sets every index: index 2 differs
    gl.LineWidth(2.0f);
    gl.BlendFuncSeparate(GL_SRC_COLOR, GL_DST_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_CONSTANT_COLOR);
    gl.BlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_MAX);
    gl.BlendColor(0.1f, 0.2f, 0.3f, 0.4f);
    gl.StencilFuncSeparate(GL_FRONT, GL_LEQUAL, 3, 0x7f);
    gl.StencilFuncSeparate(GL_BACK, GL_GREATER, 5, 0x3f);
    gl.StencilOpSeparate(GL_FRONT, GL_INCR, GL_DECR, GL_INVERT);
    gl.StencilOpSeparate(GL_BACK, GL_REPLACE, GL_INCR_WRAP, GL_DECR_WRAP);
    gl.ClearColor(0.5f, 0.25f, 0.125f, 0.75f);
    gl.ClearDepth(0.5);
    gl.ClearStencil(7);
    GLuint feedback = 0;
    gl.GenTransformFeedbacks(1, &feedback);
    gl.BindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback);
    GLuint pack = 0;
    gl.GenBuffers(1, &pack);
    gl.BindBuffer(GL_PIXEL_PACK_BUFFER, pack);
    gl.PixelStorei(GL_PACK_ROW_LENGTH, 9);
    gl.PixelStorei(GL_PACK_SKIP_ROWS, 1);
    gl.PixelStorei(GL_PACK_SKIP_PIXELS, 2);
    gl.PixelStorei(GL_PACK_IMAGE_HEIGHT, 3);
    gl.PixelStorei(GL_PACK_SKIP_IMAGES, 4);
    gl.PixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
    gl.PixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
    const GLenum draw_buffers[3] = {GL_NONE, GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT2};
    gl.DrawBuffers(3, draw_buffers);
    gl.ReadBuffer(GL_COLOR_ATTACHMENT3);
    gl.Enable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    gl.ProvokingVertex(GL_FIRST_VERTEX_CONVENTION);
    gl.Enable(GL_SAMPLE_COVERAGE);
    gl.SampleCoverage(0.5f, GL_TRUE);
    gl.SampleMaski(0, 0x5);
    gl.DepthFunc(GL_GEQUAL);
    gl.FrontFace(GL_CW);
    gl.LogicOp(GL_XOR);
    gl.PolygonOffset(2.0f, 3.0f);
    gl.Enable(GL_POLYGON_OFFSET_LINE);
    gl.Enable(GL_SAMPLE_ALPHA_TO_ONE);
    GLint max_draw_buffers = 0;
    gl.GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw_buffers);
    for (GLint i = 2; i < max_draw_buffers; ++i) {  // every draw buffer's own mask and blend
        const GLuint b = static_cast<GLuint>(i);
        gl.ColorMaski(b, i & 1, (i >> 1) & 1, (i >> 2) & 1, GL_FALSE);
        if (i % 3 == 0) gl.Enablei(GL_BLEND, b);
    }
}

// Puts every listed piece of state into a non-default value a host might use.
void disturb_state(GladGLContext& gl, GLuint host_fbo, GLuint host_vao, GLuint host_program, GLuint* host_objects) {
    gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, host_fbo);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, host_fbo);
    gl.UseProgram(host_program);
    gl.BindVertexArray(host_vao);
    for (int u = 0; u < 4; ++u) {
        gl.ActiveTexture(GL_TEXTURE0 + u);
        gl.BindTexture(GL_TEXTURE_2D, host_objects[u]);
        gl.BindSampler(static_cast<GLuint>(u), host_objects[4]);
    }
    gl.ActiveTexture(GL_TEXTURE5);
    gl.BindBuffer(GL_ARRAY_BUFFER, host_objects[5]);
    gl.BindBufferRange(GL_UNIFORM_BUFFER, 0, host_objects[6], 256, 64);
    gl.BindBufferBase(GL_UNIFORM_BUFFER, 1, host_objects[6]);
    gl.BindBuffer(GL_UNIFORM_BUFFER, host_objects[5]);
    gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, host_objects[7]);
    gl.Viewport(3, 5, 17, 19);
    gl.Scissor(1, 2, 3, 4);
    gl.Enable(GL_SCISSOR_TEST);
    // Viewport arrays: other indices hold their own values.
    gl.ViewportIndexedf(1, 5, 6, 7, 8);
    gl.ScissorIndexed(1, 1, 2, 3, 4);
    gl.Disablei(GL_SCISSOR_TEST, 1);
    gl.ViewportIndexedf(3, 9, 10, 11, 12);
    gl.Enable(GL_DEPTH_TEST);
    gl.Enable(GL_STENCIL_TEST);
    gl.Enable(GL_CULL_FACE);
    gl.CullFace(GL_FRONT_AND_BACK);
    gl.Enable(GL_POLYGON_OFFSET_FILL);
    gl.Enable(GL_COLOR_LOGIC_OP);
    gl.Enable(GL_SAMPLE_MASK);
    gl.Disable(GL_DITHER);
    gl.Enable(GL_FRAMEBUFFER_SRGB);
    gl.Enable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    gl.Enablei(GL_BLEND, 0);
    gl.Enablei(GL_BLEND, 2);
    gl.BlendFunc(GL_ONE, GL_ONE);
    gl.ColorMaski(0, GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    gl.ColorMaski(1, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    gl.Enable(GL_CLIP_DISTANCE0);
    gl.Enable(GL_CLIP_DISTANCE3);
    gl.PolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    gl.DepthMask(GL_FALSE);
    gl.StencilMaskSeparate(GL_FRONT, 0x0f);
    gl.StencilMaskSeparate(GL_BACK, 0xf0);
    if (gl.ClipControl) gl.ClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.PixelStorei(GL_UNPACK_ROW_LENGTH, 7);
    gl.PixelStorei(GL_UNPACK_SKIP_ROWS, 2);
    gl.PixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 2);
    disturb_engine_state(gl);
}

// A host's own (linked) program: glUseProgram refuses unlinked ones.
GLuint link_trivial_program(GladGLContext& gl) {
    return gl_util::make_program(gl, "host", "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n",
                                 "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n");
}

// A host program made current, then flagged for deletion: GL deletes it once
// another program is made current. Returns its name.
GLuint current_flagged_program(GladGLContext& gl) {
    const GLuint program = link_trivial_program(gl);
    gl.UseProgram(program);
    gl.DeleteProgram(program);
    return program;
}

}  // namespace

TEST_CASE("every listed piece of GL state is identical before and after execute, and the result is unaffected, on "
          "a software rasteriser's plan and a GPU's") {
  // A GPU's plan draws the sky fill (its own program, the complementary depth test) where llvmpipe's clears.
  for (const testgl::RendererKind& kind : testgl::kRendererKinds) {
    const std::string renderer = kind.gl_renderer;
    CAPTURE(renderer);
    testgl::Fixture fx;
    fx.recreate_context_as(kind.gl_renderer);
    auto& gl = fx.gl();
    const Scene scene = crease_scene();
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(scene, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 40, 40);
    fx.settings(make(16, SSAO_BLUR_DEFAULT));
    const auto clean = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(clean.status == SSAO_OK);

    const GLuint depth = fx.make_depth(GL_DEPTH_COMPONENT32F, g.width, g.height, g.depth);
    const GLuint normal = fx.make_normals(GL_RGBA16F, g.width, g.height, g.normal);
    GLuint objects[8] = {};
    gl.GenTextures(4, objects);
    for (int i = 0; i < 4; ++i) {
        gl.BindTexture(GL_TEXTURE_2D, objects[i]);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    }
    gl.GenSamplers(1, &objects[4]);
    gl.GenBuffers(3, &objects[5]);
    gl.BindBuffer(GL_UNIFORM_BUFFER, objects[6]);
    gl.BufferData(GL_UNIFORM_BUFFER, 1024, nullptr, GL_STATIC_DRAW);
    gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, objects[7]);
    gl.BufferData(GL_PIXEL_UNPACK_BUFFER, 1024, nullptr, GL_STATIC_DRAW);
    gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    GLuint host_fbo = 0, host_color = 0, host_vao = 0;
    gl.GenTextures(1, &host_color);
    gl.BindTexture(GL_TEXTURE_2D, host_color);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl.GenFramebuffers(1, &host_fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, host_fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, host_color, 0);
    gl.GenVertexArrays(1, &host_vao);
    const GLuint host_program = link_trivial_program(gl);

    disturb_state(gl, host_fbo, host_vao, host_program, objects);
    const testgl::Snapshot before = testgl::snapshot(gl);
    ssao_inputs in = fx.inputs(depth, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    ssao_output out{};
    out.size = sizeof out;
    // Run twice: the first run allocates, the second reuses.
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    CHECK(testgl::changed_state(before, testgl::snapshot(gl)) == "");
    // The host's odd state (upper-left origin, line mode, scissor, masks) did not leak into the AO.
    gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);  // the read-back below packs into client memory
    for (GLenum e : {GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_IMAGE_HEIGHT,
                     GL_PACK_SKIP_IMAGES, GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST})
        gl.PixelStorei(e, 0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    if (gl.ClipControl) gl.ClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    const auto ao = fx.read_red(out.texture, g.width, g.height);
    for (size_t i = 0; i < ao.size(); ++i) CHECK(std::abs(ao[i] - clean.ao[i]) < 1e-6f);
    for (const std::string& e : fx.gl_errors()) MESSAGE(e);
    CHECK(fx.gl_errors().empty());
  }
}

TEST_CASE("a host's colour mask on draw buffer 1 does not reach the grid pass's second target on the first frame") {
    // The grid pass writes plane texels and normals to two draw buffers. The
    // colour mask is context state per draw buffer index, so the host's mask
    // on buffer 1 applies to the library's framebuffer too unless the passes
    // reset it; a first frame has no earlier normals to hide a masked write.
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 40, 40);
    std::vector<float> clean;
    {
        testgl::Fixture fx;
        fx.settings(ssao_settings{});
        const auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        REQUIRE(r.status == SSAO_OK);
        clean = r.ao;
    }
    testgl::Fixture fx;
    fx.settings(ssao_settings{});
    GLboolean mask[4] = {};
    fx.gl().ColorMaski(1, GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
    const auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(r.status == SSAO_OK);
    fx.gl().GetBooleani_v(GL_COLOR_WRITEMASK, 1, mask);
    CHECK((mask[0] == GL_TRUE && mask[1] == GL_FALSE && mask[2] == GL_FALSE && mask[3] == GL_FALSE));
    REQUIRE(r.ao.size() == clean.size());
    float worst = 0.0f;
    for (size_t i = 0; i < clean.size(); ++i) worst = std::max(worst, std::abs(r.ao[i] - clean[i]));
    CHECK(worst < 1e-6f);
}

TEST_CASE("GL errors are caught by the KHR_debug capture (the detector itself can fail)") {
    testgl::Fixture fx;
    CHECK(fx.gl_errors().empty());
    fx.gl().BindTexture(0x1234, 1);  // an invalid target: GL_INVALID_ENUM
    CHECK_FALSE(fx.gl_errors().empty());
}

TEST_CASE("GPU timings arrive from earlier frames without stalling") {
    testgl::Fixture fx;
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 32, 32);
    fx.settings(make(16, SSAO_BLUR_DEFAULT));
    ssao_timings t{};
    t.size = sizeof t;
    for (int i = 0; i < 12; ++i) {
        REQUIRE(fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE).status == SSAO_OK);
        fx.gl().Finish();
    }
    REQUIRE(fx.api().get_timings(fx.ctx(), &t) == SSAO_OK);
    CHECK(t.available == 1);
    CHECK(t.frame >= 1);
    CHECK(t.frame <= 12);
    CHECK(t.ao_ms > 0.0);
    CHECK(t.total_ms >= t.ao_ms);
    CHECK(t.blur_ms > 0.0);  // the two blur passes ran and took time
    // Without a blur no pass runs between the last two stamps.
    fx.settings(make(16, SSAO_BLUR_NONE));
    for (int i = 0; i < 12; ++i) {
        REQUIRE(fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE).status == SSAO_OK);
        fx.gl().Finish();
    }
    REQUIRE(fx.api().get_timings(fx.ctx(), &t) == SSAO_OK);
    CHECK(t.frame > 12);
    CHECK(t.blur_ms < 0.25 * t.ao_ms);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("a refused execute changes nothing: no host texture stays attached, the library's output keeps its AO") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 32, 32);
    fx.settings(make(16, SSAO_BLUR_DEFAULT));
    const auto first = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(first.status == SSAO_OK);

    // RGB9_E5 is not colour-renderable: the call is refused after the output was attached to look at it.
    GLuint bad = 0;
    gl.GenTextures(1, &bad);
    gl.BindTexture(GL_TEXTURE_2D, bad);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB9_E5, 32, 32, 0, GL_RGB, GL_FLOAT, nullptr);
    const GLuint depth = fx.make_depth(GL_DEPTH_COMPONENT32F, 32, 32, g.depth);
    const GLuint normal = fx.make_normals(GL_RGBA16F, 32, 32, g.normal);
    ssao_inputs in = fx.inputs(depth, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    in.output_texture = bad;
    CHECK(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_ERROR_UNSUPPORTED_FORMAT);
    // No framebuffer of the library's (any name that is one) still holds the host's texture.
    for (GLuint name = 1; name < 64; ++name) {
        if (!gl.IsFramebuffer(name)) continue;
        gl.BindFramebuffer(GL_FRAMEBUFFER, name);
        GLint attached = 0;
        gl.GetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                               GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &attached);
        CAPTURE(name);
        CHECK(static_cast<GLuint>(attached) != bad);
    }
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    // The texture the library returned before still holds that frame's AO.
    const auto again = fx.read_red(first.output.texture, 32, 32);
    for (size_t i = 0; i < again.size(); ++i) CHECK(again[i] == first.ao[i]);

    // Rendering into an input is a feedback loop: refused.
    in.output_texture = normal;
    CHECK(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_ERROR_INVALID_TEXTURE);
    // Normals need x, y and z, in a float or normalized format.
    GLuint rg = 0, integer = 0;
    gl.GenTextures(1, &rg);
    gl.BindTexture(GL_TEXTURE_2D, rg);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RG16F, 32, 32, 0, GL_RG, GL_FLOAT, nullptr);
    gl.GenTextures(1, &integer);
    gl.BindTexture(GL_TEXTURE_2D, integer);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32I, 32, 32, 0, GL_RGBA_INTEGER, GL_INT, nullptr);
    in.output_texture = 0;
    in.normal_texture = rg;
    CHECK(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_ERROR_UNSUPPORTED_FORMAT);
    in.normal_texture = integer;
    CHECK(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_ERROR_UNSUPPORTED_FORMAT);
    CHECK(std::string(fx.api().last_error(fx.ctx())).find("integer") != std::string::npos);
    const GLuint names[] = {bad, rg, integer};
    gl.DeleteTextures(3, names);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("a host program flagged for deletion stays current through a refused execute and a frame that binds no "
          "program") {
    // The header: a failing call changes nothing, and the flagged program is
    // deleted only when execute binds its own.
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 16, 16);
    const GLuint program = current_flagged_program(gl);
    const auto still_current = [&] {
        GLint current = -1;
        gl.GetIntegerv(GL_CURRENT_PROGRAM, &current);
        return current == static_cast<GLint>(program) && gl.IsProgram(program) == GL_TRUE;
    };
    // Refused after the state guard is up: a colour texture where the depth belongs.
    GLuint colour = 0;
    gl.GenTextures(1, &colour);
    gl.BindTexture(GL_TEXTURE_2D, colour);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, g.width, g.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    const GLuint normal = fx.make_normals(GL_RGBA16F, g.width, g.height, g.normal);
    ssao_inputs in = fx.inputs(colour, normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    ssao_output out{};
    out.size = sizeof out;
    CHECK(fx.api().execute(fx.ctx(), &in, &out) == SSAO_ERROR_UNSUPPORTED_FORMAT);
    CHECK(still_current());
    // Strength 0: the output is cleared to 1 and no pass draws.
    ssao_settings off{};
    off.strength = SSAO_STRENGTH_OFF;
    fx.settings(off);
    REQUIRE(fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE).status == SSAO_OK);
    CHECK(still_current());
    gl.UseProgram(0);  // the host lets it go
    CHECK(gl.IsProgram(program) == GL_FALSE);
    gl.DeleteTextures(1, &colour);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("a host program flagged for deletion while current does not make the restore raise an error") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 16, 16);
    current_flagged_program(gl);
    REQUIRE(fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE).status == SSAO_OK);
    GLint current = -1;
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &current);
    CHECK(current == 0);  // it no longer exists; the documented fallback
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("a current host program whose re-link failed does not make the restore raise an error") {
    // GL keeps such a program's old executable in use but refuses to make it
    // current again (GL_INVALID_OPERATION), so it cannot be restored.
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = analytic::perspective(kFov, 1.0, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 16, 16);
    const GLuint program = link_trivial_program(gl);
    gl.UseProgram(program);
    // A second fragment shader with its own main: the re-link fails.
    const GLuint second = gl.CreateShader(GL_FRAGMENT_SHADER);
    const char* source = "#version 330 core\nvoid main() {}\n";
    gl.ShaderSource(second, 1, &source, nullptr);
    gl.CompileShader(second);
    gl.AttachShader(program, second);
    gl.LinkProgram(program);
    GLint linked = GL_TRUE;
    gl.GetProgramiv(program, GL_LINK_STATUS, &linked);
    REQUIRE(linked == GL_FALSE);
    REQUIRE(fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE).status == SSAO_OK);
    GLint current = -1;
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &current);
    CHECK(current == 0);  // not the library's program: the documented fallback
    CHECK(fx.gl_errors().empty());
    gl.DeleteProgram(program);
    gl.DeleteShader(second);
}
