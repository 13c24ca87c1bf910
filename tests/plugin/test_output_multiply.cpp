// Output mode MULTIPLY: the host's lit image's RGB at
// the viewport rectangle is multiplied by AO through blending, alpha and the
// pixels outside the viewport untouched. The oracle is the host's own
// composite: the same frame's AO written in overwrite mode into an RGBA32F
// texture, multiplied into the lit image on the CPU.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "gl_fixture.h"
#include "gl_state_snapshot.h"
#include "test_scenes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using analytic::GBuffer;
using testscenes::crease_scene;
using testscenes::kFov;

namespace {

// Textures of kTW x kTH; the viewport is the rectangle at (kVX, kVY) of kVW x kVH.
constexpr int kTW = 48, kTH = 40, kVX = 5, kVY = 4, kVW = 32, kVH = 28;

struct Frame {
    GLuint depth = 0, normal = 0;
    glm::dmat4 proj;
};

// The crease rendered at the viewport's size, embedded in larger textures (sky around it).
Frame make_frame(testgl::Fixture& fx) {
    Frame f;
    f.proj = analytic::perspective(kFov, double(kVW) / kVH, 0.1, 100.0);
    const GBuffer g = analytic::render(crease_scene(), f.proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kVW, kVH);
    std::vector<float> depth(size_t(kTW) * kTH, 1.0f);
    std::vector<glm::vec3> normal(size_t(kTW) * kTH, glm::vec3(0, 0, 1));
    for (int y = 0; y < kVH; ++y)
        for (int x = 0; x < kVW; ++x) {
            depth[size_t(y + kVY) * kTW + (x + kVX)] = g.depth[size_t(y) * kVW + x];
            normal[size_t(y + kVY) * kTW + (x + kVX)] = g.normal[size_t(y) * kVW + x];
        }
    f.depth = fx.make_depth(GL_DEPTH_COMPONENT32F, kTW, kTH, depth);
    f.normal = fx.make_normals(GL_RGBA16F, kTW, kTH, normal);
    return f;
}

ssao_inputs inputs_for(testgl::Fixture& fx, const Frame& f, GLuint output, ssao_output_mode mode) {
    ssao_inputs in = fx.inputs(f.depth, f.normal, f.proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    testgl::set_viewport(in, kVX, kVY, kVW, kVH);
    in.output_texture = output;
    in.output_mode = mode;
    return in;
}

// A lit image: every texel a different colour and alpha.
std::vector<uint8_t> lit_pixels() {
    std::vector<uint8_t> px(size_t(kTW) * kTH * 4);
    uint32_t h = 12345;
    for (uint8_t& v : px) {
        h = h * 1664525u + 1013904223u;
        v = static_cast<uint8_t>(h >> 24);
    }
    return px;
}

GLuint make_texture(GladGLContext& gl, GLenum internal, GLenum type, const void* data) {
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D, t);
    gl.TexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), kTW, kTH, 0, GL_RGBA, type, data);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    return t;
}

template <typename T>
std::vector<T> read_rgba(GladGLContext& gl, GLuint texture, GLenum type) {
    std::vector<T> px(size_t(kTW) * kTH * 4);
    gl.BindTexture(GL_TEXTURE_2D, texture);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, type, px.data());
    gl.BindTexture(GL_TEXTURE_2D, 0);
    return px;
}

bool in_viewport(int x, int y) { return x >= kVX && x < kVX + kVW && y >= kVY && y < kVY + kVH; }

// The frame's AO (overwrite mode into RGBA32F), texture-sized, 1 outside the viewport.
std::vector<float> overwrite_ao(testgl::Fixture& fx, const Frame& f) {
    auto& gl = fx.gl();
    const GLuint t = make_texture(gl, GL_RGBA32F, GL_FLOAT, nullptr);
    ssao_inputs in = inputs_for(fx, f, t, SSAO_OUTPUT_MODE_OVERWRITE);
    REQUIRE(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_OK);
    const auto px = read_rgba<float>(gl, t, GL_FLOAT);
    gl.DeleteTextures(1, &t);
    std::vector<float> ao(size_t(kTW) * kTH, 1.0f);
    for (int y = 0; y < kTH; ++y)
        for (int x = 0; x < kTW; ++x)
            if (in_viewport(x, y)) ao[size_t(y) * kTW + x] = px[(size_t(y) * kTW + x) * 4];
    return ao;
}

ssao_settings settings_for(ssao_method method, ssao_resolution res, ssao_blur blur) {
    ssao_settings s = testscenes::make(16, blur);
    s.method = method;
    s.resolution = res;
    s.radius = 1.5f;
    return s;
}

double srgb_decode(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double srgb_encode(double l) { return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055; }

}  // namespace

TEST_CASE("MULTIPLY multiplies the lit image's RGB by the overwrite mode's AO with alpha and the outside untouched") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const Frame f = make_frame(fx);
    const std::vector<uint8_t> lit = lit_pixels();
    struct Config {
        ssao_method method;
        ssao_resolution res;
        ssao_blur blur;
    };
    // The final pass is the AO pass, the vertical blur, the box blur, the upsample.
    const Config configs[] = {{SSAO_METHOD_KERNEL, SSAO_RESOLUTION_FULL, SSAO_BLUR_NONE},
                              {SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_FULL, SSAO_BLUR_DEPTH_AWARE},
                              {SSAO_METHOD_KERNEL, SSAO_RESOLUTION_FULL, SSAO_BLUR_BOX_4X4},
                              {SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_HALF, SSAO_BLUR_DEPTH_AWARE}};
    for (const Config& c : configs) {
        CAPTURE(c.method);
        CAPTURE(c.res);
        CAPTURE(c.blur);
        fx.settings(settings_for(c.method, c.res, c.blur));
        const std::vector<float> ao = overwrite_ao(fx, f);
        REQUIRE(*std::min_element(ao.begin(), ao.end()) < 0.95f);  // there is occlusion to apply

        const GLuint target = make_texture(gl, GL_RGBA8, GL_UNSIGNED_BYTE, lit.data());
        ssao_inputs in = inputs_for(fx, f, target, SSAO_OUTPUT_MODE_MULTIPLY);
        ssao_output out{};
        out.size = sizeof out;
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        CHECK(out.texture == target);
        CHECK(out.origin[0] == kVX);
        CHECK(out.origin[1] == kVY);
        const auto got = read_rgba<uint8_t>(gl, target, GL_UNSIGNED_BYTE);
        int worst = 0, outside_changed = 0, alpha_changed = 0;
        for (int y = 0; y < kTH; ++y)
            for (int x = 0; x < kTW; ++x) {
                const size_t i = size_t(y) * kTW + x;
                for (int ch = 0; ch < 4; ++ch) {
                    const int have = got[i * 4 + ch], was = lit[i * 4 + ch];
                    if (!in_viewport(x, y)) {
                        outside_changed += have != was;
                    } else if (ch == 3) {
                        alpha_changed += have != was;
                    } else {
                        const int want = static_cast<int>(std::lround(was * double(ao[i])));
                        worst = std::max(worst, std::abs(have - want));
                    }
                }
            }
        CHECK(worst <= 1);
        CHECK(outside_changed == 0);
        CHECK(alpha_changed == 0);
        gl.DeleteTextures(1, &target);

        // RGBA32F: one float multiply in the blender, the CPU's product bit for bit.
        std::vector<float> litf(lit.size());
        for (size_t i = 0; i < lit.size(); ++i) litf[i] = lit[i] / 255.0f;
        const GLuint ftarget = make_texture(gl, GL_RGBA32F, GL_FLOAT, litf.data());
        in.output_texture = ftarget;
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        const auto gotf = read_rgba<float>(gl, ftarget, GL_FLOAT);
        int differ = 0;
        for (int y = 0; y < kTH; ++y)
            for (int x = 0; x < kTW; ++x) {
                const size_t i = size_t(y) * kTW + x;
                for (int ch = 0; ch < 4; ++ch) {
                    const float want = in_viewport(x, y) && ch < 3 ? litf[i * 4 + ch] * ao[i] : litf[i * 4 + ch];
                    differ += gotf[i * 4 + ch] != want;
                }
            }
        CHECK(differ == 0);
        gl.DeleteTextures(1, &ftarget);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("MULTIPLY into an sRGB lit image multiplies in linear space") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const Frame f = make_frame(fx);
    const std::vector<uint8_t> lit = lit_pixels();
    fx.settings(settings_for(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_FULL, SSAO_BLUR_NONE));
    const std::vector<float> ao = overwrite_ao(fx, f);
    const GLuint target = make_texture(gl, GL_SRGB8_ALPHA8, GL_UNSIGNED_BYTE, lit.data());
    ssao_inputs in = inputs_for(fx, f, target, SSAO_OUTPUT_MODE_MULTIPLY);
    REQUIRE(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_OK);
    const auto got = read_rgba<uint8_t>(gl, target, GL_UNSIGNED_BYTE);
    int worst = 0;
    for (int y = kVY; y < kVY + kVH; ++y)
        for (int x = kVX; x < kVX + kVW; ++x) {
            const size_t i = size_t(y) * kTW + x;
            for (int ch = 0; ch < 3; ++ch) {
                const double lin = srgb_decode(lit[i * 4 + ch] / 255.0) * ao[i];
                const int want = static_cast<int>(std::lround(srgb_encode(lin) * 255.0));
                worst = std::max(worst, std::abs(int(got[i * 4 + ch]) - want));
            }
            CHECK(got[i * 4 + 3] == lit[i * 4 + 3]);
        }
    // Blending in 8 bits: AO and the decoded colour are rounded before the
    // product is encoded; a multiply of the stored (encoded) values would be
    // off by up to ~50 steps in the mid-tones.
    CHECK(worst <= 2);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("MULTIPLY restores the blend state it changes and strength off runs no pass and the library's output is refused") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const Frame f = make_frame(fx);
    const std::vector<uint8_t> lit = lit_pixels();
    fx.settings(settings_for(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_HALF, SSAO_BLUR_DEPTH_AWARE));
    const GLuint target = make_texture(gl, GL_RGBA8, GL_UNSIGNED_BYTE, lit.data());

    // A host with blending of its own: per-buffer functions and equations, a constant colour, sRGB writes.
    gl.Enablei(GL_BLEND, 0);
    gl.Enablei(GL_BLEND, 1);
    gl.BlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_CONSTANT_ALPHA);
    gl.BlendFuncSeparatei(1, GL_DST_COLOR, GL_ONE, GL_ZERO, GL_SRC_ALPHA_SATURATE);
    gl.BlendEquationSeparatei(0, GL_FUNC_SUBTRACT, GL_MIN);
    gl.BlendEquationSeparatei(1, GL_MAX, GL_FUNC_REVERSE_SUBTRACT);
    gl.BlendColor(0.1f, 0.2f, 0.3f, 0.4f);
    gl.Enable(GL_FRAMEBUFFER_SRGB);
    auto blend_of = [&](GLuint buffer) {
        std::vector<GLint> v;
        for (GLenum e : {GL_BLEND_SRC_RGB, GL_BLEND_DST_RGB, GL_BLEND_SRC_ALPHA, GL_BLEND_DST_ALPHA,
                         GL_BLEND_EQUATION_RGB, GL_BLEND_EQUATION_ALPHA}) {
            GLint x = 0;
            gl.GetIntegeri_v(e, buffer, &x);
            v.push_back(x);
        }
        return v;
    };
    const auto blend0 = blend_of(0), blend1 = blend_of(1);
    const testgl::Snapshot before = testgl::snapshot(gl);
    ssao_inputs in = inputs_for(fx, f, target, SSAO_OUTPUT_MODE_MULTIPLY);
    ssao_output out{};
    out.size = sizeof out;
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    CHECK((out.passes_run & SSAO_PASS_UPSAMPLE) != 0);
    CHECK(testgl::changed_state(before, testgl::snapshot(gl)) == "");
    CHECK(blend_of(0) == blend0);
    CHECK(blend_of(1) == blend1);
    gl.Disable(GL_FRAMEBUFFER_SRGB);
    gl.Disablei(GL_BLEND, 0);
    gl.Disablei(GL_BLEND, 1);

    // Strength off: multiplying by 1 runs nothing and leaves the image as it is.
    const auto before_off = read_rgba<uint8_t>(gl, target, GL_UNSIGNED_BYTE);
    ssao_settings off = settings_for(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_HALF, SSAO_BLUR_DEPTH_AWARE);
    off.strength = SSAO_STRENGTH_OFF;
    fx.settings(off);
    out = ssao_output{};
    out.size = sizeof out;
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    CHECK(out.passes_run == 0u);
    CHECK(out.texture == target);
    CHECK(out.origin[0] == kVX);
    CHECK(out.origin[1] == kVY);
    CHECK(read_rgba<uint8_t>(gl, target, GL_UNSIGNED_BYTE) == before_off);
    ssao_timings timings{};
    timings.size = sizeof timings;
    REQUIRE(fx.api().get_timings(fx.ctx(), &timings) == SSAO_OK);

    // Multiply needs the host's image: the library-owned output is refused, nothing changes.
    const testgl::Snapshot before_refused = testgl::snapshot(gl);
    in.output_texture = 0;
    CHECK(fx.api().execute(fx.ctx(), &in, &out) == SSAO_ERROR_INVALID_VALUE);
    CHECK(std::string(fx.api().last_error(fx.ctx())).find("MULTIPLY") != std::string::npos);
    const testgl::Snapshot after_refused = testgl::snapshot(gl);
    CHECK(after_refused == before_refused);
    // An integer lit image cannot be blended (nor written): refused as before.
    GLuint int_target = 0;
    gl.GenTextures(1, &int_target);
    gl.BindTexture(GL_TEXTURE_2D, int_target);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8UI, kTW, kTH, 0, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    in.output_texture = int_target;
    fx.settings(settings_for(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_HALF, SSAO_BLUR_DEPTH_AWARE));
    CHECK(fx.api().execute(fx.ctx(), &in, &out) == SSAO_ERROR_UNSUPPORTED_FORMAT);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("a debug view overwrites the output rectangle in MULTIPLY mode too: the view is what the host sees") {
    // ssao.h (ssao_debug_view): a view replaces the AO whatever output_mode
    // says; multiplying a lit image by packed normals or blur weights would
    // show neither. BLUR_WEIGHTS without a blur is the clear pass: it must
    // write 1 there, not clear the host's image.
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const Frame f = make_frame(fx);
    const std::vector<uint8_t> lit = lit_pixels();
    const struct {
        ssao_debug_view view;
        ssao_blur blur;
    } cases[] = {{SSAO_DEBUG_VIEW_RAW_AO, SSAO_BLUR_DEPTH_AWARE},
                 {SSAO_DEBUG_VIEW_BLUR_WEIGHTS, SSAO_BLUR_DEPTH_AWARE},
                 {SSAO_DEBUG_VIEW_BLUR_WEIGHTS, SSAO_BLUR_NONE},
                 {SSAO_DEBUG_VIEW_NORMALS, SSAO_BLUR_NONE},
                 {SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS, SSAO_BLUR_NONE}};
    for (const auto& c : cases) {
        CAPTURE(c.view);
        CAPTURE(c.blur);
        ssao_settings s = settings_for(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_FULL, c.blur);
        s.debug_view = c.view;
        fx.settings(s);
        // The view in overwrite mode, as RGBA8 like the lit image.
        const GLuint reference = make_texture(gl, GL_RGBA8, GL_UNSIGNED_BYTE, lit.data());
        ssao_inputs in = inputs_for(fx, f, reference, SSAO_OUTPUT_MODE_OVERWRITE);
        REQUIRE(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_OK);
        const auto want = read_rgba<uint8_t>(gl, reference, GL_UNSIGNED_BYTE);
        gl.DeleteTextures(1, &reference);

        const GLuint target = make_texture(gl, GL_RGBA8, GL_UNSIGNED_BYTE, lit.data());
        in = inputs_for(fx, f, target, SSAO_OUTPUT_MODE_MULTIPLY);
        ssao_output out{};
        out.size = sizeof out;
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        CHECK(out.passes_run != 0u);
        const auto got = read_rgba<uint8_t>(gl, target, GL_UNSIGNED_BYTE);
        gl.DeleteTextures(1, &target);
        CHECK(got == want);
        // Inside the viewport the view replaced the lit image (alpha = 1).
        int alpha_one = 0;
        for (int y = kVY; y < kVY + kVH; ++y)
            for (int x = kVX; x < kVX + kVW; ++x) alpha_one += got[(size_t(y) * kTW + x) * 4 + 3] == 255;
        CHECK(alpha_one == kVW * kVH);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("strength off in MULTIPLY mode: no pass and the lit image untouched, but an AO debug view still writes its 1s") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const Frame f = make_frame(fx);
    const std::vector<uint8_t> lit = lit_pixels();
    for (ssao_debug_view view : {SSAO_DEBUG_VIEW_NONE, SSAO_DEBUG_VIEW_RAW_AO, SSAO_DEBUG_VIEW_BLUR_WEIGHTS}) {
        CAPTURE(view);
        ssao_settings s = settings_for(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_FULL, SSAO_BLUR_DEPTH_AWARE);
        s.strength = SSAO_STRENGTH_OFF;
        s.debug_view = view;
        fx.settings(s);
        const GLuint target = make_texture(gl, GL_RGBA8, GL_UNSIGNED_BYTE, lit.data());
        ssao_inputs in = inputs_for(fx, f, target, SSAO_OUTPUT_MODE_MULTIPLY);
        ssao_output out{};
        out.size = sizeof out;
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        const auto got = read_rgba<uint8_t>(gl, target, GL_UNSIGNED_BYTE);
        gl.DeleteTextures(1, &target);
        const bool view_on = view != SSAO_DEBUG_VIEW_NONE;
        CHECK(out.passes_run == (view_on ? uint32_t(SSAO_PASS_CLEAR) : 0u));
        int wrong = 0;
        for (int y = 0; y < kTH; ++y)
            for (int x = 0; x < kTW; ++x)
                for (int ch = 0; ch < 4; ++ch) {
                    const size_t i = (size_t(y) * kTW + x) * 4 + ch;
                    const int want = view_on && in_viewport(x, y) ? 255 : lit[i];
                    wrong += got[i] != want;
                }
        CHECK(wrong == 0);
    }
    CHECK(fx.gl_errors().empty());
}
