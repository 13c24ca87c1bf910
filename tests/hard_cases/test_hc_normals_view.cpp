// The normal debug views (ssao_settings.debug_view NORMALS and
// RECONSTRUCTED_NORMALS) and the ABI's handling of
// normal_texture = 0: the NORMALS view shows the decoded G-buffer normal,
// the reconstructed view ignores the normal texture, the library's own output
// is RGBA8 for them, and every refusal of a bad depth texture stays.
#include <doctest/doctest.h>

#include "hc_util.h"
#include "normals_view_util.h"

#include <cmath>
#include <string>

using analytic::GBuffer;

namespace {

constexpr int kW = 48, kH = 40;

GBuffer crease_scene(const glm::dmat4& proj, ssao_clip_range clip) {
    return analytic::render(hc::crease_scene(), proj, clip, kW, kH);
}

}  // namespace

TEST_CASE("normals view: with a G-buffer it shows the decoded normal texture (view, world, unorm), sky grey, alpha 1") {
    testgl::Fixture fx;
    const auto proj = analytic::reverse_z(hc::kFov, double(kW) / kH, 0.1, 100.0);
    const GBuffer g = crease_scene(proj, SSAO_CLIP_ZERO_TO_ONE);
    struct Case {
        const char* name;
        GLenum format;
        ssao_normal_space space;
        double tol;  // the storage's precision: half floats ~1e-3, 8-bit unorm 1/127.5
    };
    const Case cases[] = {{"view RGBA16F", GL_RGBA16F, SSAO_NORMAL_SPACE_VIEW, 2e-3},
                          {"world RGBA16F", GL_RGBA16F, SSAO_NORMAL_SPACE_WORLD, 2e-3},
                          {"view RGBA8", GL_RGBA8, SSAO_NORMAL_SPACE_VIEW, 1.2 / 127.5},
                          {"world RGBA32F", GL_RGBA32F, SSAO_NORMAL_SPACE_WORLD, 1e-5}};
    for (const Case& c : cases) {
        CAPTURE(c.name);
        nfd::ViewOptions o;
        o.view = SSAO_DEBUG_VIEW_NORMALS;
        o.depth_only = false;
        o.normal_format = c.format;
        o.normal_space = c.space;
        o.view_matrix = hc::crease_view();
        o.pad = 1;
        const auto r = nfd::run_view(fx, g, proj, SSAO_CLIP_ZERO_TO_ONE, GL_DEPTH_COMPONENT32F, o);
        REQUIRE(r.status == SSAO_OK);
        CHECK(r.passes_run == (SSAO_PASS_GRID | SSAO_PASS_NORMALS_VIEW));
        int off = 0, sky_not_grey = 0, alpha_not_one = 0;
        for (size_t i = 0; i < r.n.size(); ++i) {
            alpha_not_one += r.alpha[i] != 1.0f;
            if (std::isnan(g.position[i].x)) {
                sky_not_grey += glm::length(r.n[i]) > 1e-6f;
                continue;
            }
            const glm::vec3 e = glm::abs(r.n[i] - g.normal[i]);
            if (std::max(e.x, std::max(e.y, e.z)) > c.tol) ++off;
        }
        CHECK(off == 0);
        CHECK(sky_not_grey == 0);
        CHECK(alpha_not_one == 0);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("normals view: depth only it is the reconstructed view, the reconstructed view ignores a G-buffer") {
    testgl::Fixture fx;
    const auto proj = analytic::perspective(hc::kFov, double(kW) / kH, 0.1, 100.0);
    const GBuffer g = crease_scene(proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    auto view = [&](ssao_debug_view v, bool depth_only) {
        nfd::ViewOptions o;
        o.view = v;
        o.depth_only = depth_only;
        const auto r = nfd::run_view(fx, g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, GL_DEPTH_COMPONENT24, o);
        REQUIRE(r.status == SSAO_OK);
        return r.n;
    };
    const auto rebuilt = view(SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS, true);
    CHECK(view(SSAO_DEBUG_VIEW_NORMALS, true) == rebuilt);
    CHECK(view(SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS, false) == rebuilt);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("normals view: the library's own output is RGBA8 holding n * 0.5 + 0.5, whatever output_format says") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = analytic::perspective_zo(hc::kFov, double(kW) / kH, 0.1, 100.0);
    const GBuffer g = crease_scene(proj, SSAO_CLIP_ZERO_TO_ONE);
    ssao_settings s{};
    s.size = sizeof s;
    s.debug_view = SSAO_DEBUG_VIEW_NORMALS;
    s.output_format = SSAO_OUTPUT_R16F;
    fx.settings(s);
    const GLuint dt = fx.make_depth(GL_DEPTH_COMPONENT32F, kW, kH, g.depth);
    const GLuint nt = fx.make_normals(GL_RGBA16F, kW, kH, g.normal);
    ssao_inputs in = fx.inputs(dt, nt, proj, SSAO_CLIP_ZERO_TO_ONE);
    ssao_output out{};
    out.size = sizeof out;
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    gl.BindTexture(GL_TEXTURE_2D, out.texture);
    GLint internal = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    CHECK(internal == GL_RGBA8);
    std::vector<unsigned char> px(size_t(kW) * kH * 4);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
    gl.BindTexture(GL_TEXTURE_2D, 0);
    int off = 0;
    for (size_t i = 0; i < g.normal.size(); ++i) {
        const glm::vec3 want = std::isnan(g.position[i].x) ? glm::vec3(0.5f) : g.normal[i] * 0.5f + 0.5f;
        for (int k = 0; k < 3; ++k)
            if (std::abs(px[i * 4 + k] / 255.0f - want[k]) > 1.0f / 255 + 1e-3f) ++off;
        if (px[i * 4 + 3] != 255) ++off;
    }
    CHECK(off == 0);
    // Back to the AO: the output is R16F again and holds AO.
    s.debug_view = SSAO_DEBUG_VIEW_NONE;
    fx.settings(s);
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    gl.BindTexture(GL_TEXTURE_2D, out.texture);
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &internal);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    CHECK(internal == GL_R16F);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("normals view: a host output texture without blue is refused (UNSUPPORTED_FORMAT), with RGB it is written") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = analytic::perspective_zo(hc::kFov, double(kW) / kH, 0.1, 100.0);
    const GBuffer g = crease_scene(proj, SSAO_CLIP_ZERO_TO_ONE);
    const GLuint dt = fx.make_depth(GL_DEPTH_COMPONENT32F, kW, kH, g.depth);
    for (ssao_debug_view view : {SSAO_DEBUG_VIEW_NORMALS, SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS, SSAO_DEBUG_VIEW_NONE}) {
        CAPTURE(view);
        ssao_settings s{};
        s.size = sizeof s;
        s.debug_view = view;
        fx.settings(s);
        for (GLenum format : {GLenum(GL_R8), GLenum(GL_RG16F), GLenum(GL_RGBA8)}) {
            CAPTURE(format);
            GLuint t = 0;
            gl.GenTextures(1, &t);
            gl.BindTexture(GL_TEXTURE_2D, t);
            gl.TexStorage2D(GL_TEXTURE_2D, 1, format, kW, kH);
            gl.BindTexture(GL_TEXTURE_2D, 0);
            ssao_inputs in = fx.inputs(dt, 0, proj, SSAO_CLIP_ZERO_TO_ONE);
            in.output_texture = t;
            const bool refused = view != SSAO_DEBUG_VIEW_NONE && format != GL_RGBA8;
            const ssao_status st = fx.api().execute(fx.ctx(), &in, nullptr);
            CHECK(st == (refused ? SSAO_ERROR_UNSUPPORTED_FORMAT : SSAO_OK));
            if (refused) CHECK(std::string(fx.api().last_error(fx.ctx())).find("red, green and blue") != std::string::npos);
            gl.DeleteTextures(1, &t);
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("depth-only input: normal_texture 0 ignores normal space, packing and view matrix, a bad depth texture is still refused") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = analytic::perspective(hc::kFov, double(kW) / kH, 0.1, 100.0);
    const GBuffer g = crease_scene(proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    ssao_settings s{};
    s.size = sizeof s;
    fx.settings(s);
    const GLuint dt = fx.make_depth(GL_DEPTH_COMPONENT24, kW, kH, g.depth);
    ssao_output out{};
    out.size = sizeof out;

    ssao_inputs in = fx.inputs(dt, 0, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    const std::vector<float> want = fx.read_red(out.texture, kW, kH);
    CHECK((out.passes_run & SSAO_PASS_GRID) != 0);
    // Values that would be refused with a normal texture describe nothing now.
    in.normal_space = static_cast<ssao_normal_space>(77);
    in.normal_packing = static_cast<ssao_normal_packing>(0x7fffffff);
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    CHECK(fx.read_red(out.texture, kW, kH) == want);
    in.normal_space = SSAO_NORMAL_SPACE_WORLD;
    in.view_matrix[5] = std::nanf("");
    REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
    CHECK(fx.read_red(out.texture, kW, kH) == want);
    const GLuint last_good = out.texture;

    auto refused = [&](ssao_inputs bad, ssao_status want_status, const char* words) {
        ssao_output o{};
        o.size = sizeof o;
        CHECK(fx.api().execute(fx.ctx(), &bad, &o) == want_status);
        const std::string err = fx.api().last_error(fx.ctx());
        CAPTURE(err);
        CHECK(err.find(words) != std::string::npos);
    };
    ssao_inputs bad = in;
    bad.depth_texture = 0;
    refused(bad, SSAO_ERROR_INVALID_TEXTURE, "depth_texture is 0");
    bad.depth_texture = 987654;
    refused(bad, SSAO_ERROR_INVALID_TEXTURE, "depth_texture");
    GLuint colour = 0;
    gl.GenTextures(1, &colour);
    gl.BindTexture(GL_TEXTURE_2D, colour);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kW, kH, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    bad.depth_texture = colour;
    refused(bad, SSAO_ERROR_UNSUPPORTED_FORMAT, "depth_texture has 0-bit depth");
    bad = in;
    bad.viewport[2] = kW + 1;
    bad.viewport[3] = kH;
    refused(bad, SSAO_ERROR_INVALID_SIZE, "viewport");
    bad = in;
    bad.clip_range = static_cast<ssao_clip_range>(9);
    refused(bad, SSAO_ERROR_INVALID_ENUM, "clip_range");
    // The refused calls changed nothing: the last good output is intact.
    CHECK(fx.read_red(last_good, kW, kH) == want);
    gl.DeleteTextures(1, &colour);
}

TEST_CASE("depth-only input is free when off: with a G-buffer the kernel at full resolution runs no grid pass") {
    // (The visibility march reads the grid at every resolution; what depth-only
    // input changes there is the grid pass's variant: tests/unit/test_plan.cpp.)
    testgl::Fixture fx;
    const auto proj = analytic::perspective(hc::kFov, double(kW) / kH, 0.1, 100.0);
    const GBuffer g = crease_scene(proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    ssao_settings s{};
    s.size = sizeof s;
    s.resolution = SSAO_RESOLUTION_FULL;
    s.method = SSAO_METHOD_KERNEL;
    fx.settings(s);
    const auto r = fx.run(g, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    REQUIRE(r.status == SSAO_OK);
    CHECK((r.output.passes_run & SSAO_PASS_GRID) == 0);
}
