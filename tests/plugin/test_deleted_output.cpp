// The host deletes the library-owned output texture it was handed: the next
// execute makes a new one (same size, or after a size change) with the AO a
// fresh context gives, without a GL error. (A host texture that took the
// deleted name is told apart by its label; Mesa does not hand a freed name
// out again, so that case cannot be made here.) The library's output handed
// back as an input is refused.
#include <doctest/doctest.h>

#include "gl_fixture.h"
#include "crease_textures.h"
#include "test_scenes.h"

#include <string>
#include <vector>

using testscenes::CreaseTextures;
using testscenes::kFov;
using testscenes::make;

namespace {

constexpr int kSize = 32;
constexpr int kSmallW = 24, kSmallH = 20;  // the size-change viewport

struct Scene : CreaseTextures {
    explicit Scene(testgl::Fixture& fx) : CreaseTextures(fx, kSize) { fx.settings(make(8, SSAO_BLUR_DEFAULT)); }
    ssao_inputs small() const {
        ssao_inputs s = in;
        s.viewport[0] = 3;
        s.viewport[1] = 5;
        s.viewport[2] = kSmallW;
        s.viewport[3] = kSmallH;
        return s;
    }
};

struct Expected {
    std::vector<float> full, small;
};

// What a fresh context renders (its own EGL and library context, gone after).
Expected fresh_results() {
    testgl::Fixture fx;
    Scene scene(fx);
    ssao_output out{};
    out.size = sizeof out;
    Expected e;
    REQUIRE(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_OK);
    e.full = fx.read_red(out.texture, kSize, kSize);
    const ssao_inputs small = scene.small();
    REQUIRE(fx.api().execute(fx.ctx(), &small, &out) == SSAO_OK);
    e.small = fx.read_red(out.texture, kSmallW, kSmallH);
    return e;
}

}  // namespace

TEST_CASE("deleted output: the host deletes the library's output, the next execute makes a new one, same size or not") {
    const Expected expected = fresh_results();
    testgl::Fixture fx;
    auto& gl = fx.gl();
    Scene scene(fx);
    ssao_output out{};
    out.size = sizeof out;
    REQUIRE(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_OK);

    // Same size.
    gl.DeleteTextures(1, &out.texture);
    out.texture = 0;
    REQUIRE(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_OK);
    CHECK(gl.IsTexture(out.texture));
    CHECK(fx.read_red(out.texture, kSize, kSize) == expected.full);
    for (const std::string& e : fx.gl_errors()) MESSAGE(e);
    CHECK(fx.gl_errors().empty());

    // With a size change in the same execute.
    gl.DeleteTextures(1, &out.texture);
    const ssao_inputs small = scene.small();
    REQUIRE(fx.api().execute(fx.ctx(), &small, &out) == SSAO_OK);
    CHECK(fx.read_red(out.texture, kSmallW, kSmallH) == expected.small);
    // And back, deleting it once more: the reallocation path again.
    gl.DeleteTextures(1, &out.texture);
    REQUIRE(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_OK);
    CHECK(fx.read_red(out.texture, kSize, kSize) == expected.full);
    // Deleted once more, then destroy_context: nothing of the host's deleted, no error.
    gl.DeleteTextures(1, &out.texture);
    REQUIRE(fx.api().destroy_context(fx.ctx()) == SSAO_OK);
    fx.forget_context();
    CHECK(gl.IsTexture(scene.depth));
    CHECK(gl.IsTexture(scene.normal));
    for (const std::string& e : fx.gl_errors()) MESSAGE(e);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("the library's own output passed back as an input is refused and left as it was") {
    // An execute without output_texture writes, and may reallocate, the
    // library's output: reading it as an input would be a feedback loop.
    testgl::Fixture fx;
    auto& gl = fx.gl();
    Scene scene(fx);
    ssao_settings normals_view{};
    normals_view.debug_view = SSAO_DEBUG_VIEW_NORMALS;  // an RGBA8 output, which passes as a normal texture
    fx.settings(normals_view);
    ssao_output out{};
    out.size = sizeof out;
    REQUIRE(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_OK);
    const GLuint own = out.texture;
    const std::vector<float> before = fx.read_red(own, kSize, kSize);
    const auto format_of_own = [&] {
        GLint format = 0;
        gl.BindTexture(GL_TEXTURE_2D, own);
        gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
        gl.BindTexture(GL_TEXTURE_2D, 0);
        return format;
    };
    REQUIRE(format_of_own() == GL_RGBA8);
    fx.settings(make(8, SSAO_BLUR_DEFAULT));  // an R8 output: the execute would reallocate the texture it reads
    for (const char* field : {"depth_texture", "normal_texture"}) {
        CAPTURE(field);
        ssao_inputs in = scene.in;
        (std::string(field) == "depth_texture" ? in.depth_texture : in.normal_texture) = own;
        in.normal_packing = SSAO_NORMAL_PACKING_UNORM;
        ssao_output refused{};
        refused.size = sizeof refused;
        CHECK(fx.api().execute(fx.ctx(), &in, &refused) == SSAO_ERROR_INVALID_TEXTURE);
        const std::string why = fx.api().last_error(fx.ctx());
        CHECK(why.find(std::string("inputs.") + field + " is the library's own output") != std::string::npos);
    }
    CHECK(format_of_own() == GL_RGBA8);
    CHECK(fx.read_red(own, kSize, kSize) == before);
    // With a host output the library's own is not written: reading it as the normals is allowed.
    GLuint host_output = 0;
    gl.GenTextures(1, &host_output);
    gl.BindTexture(GL_TEXTURE_2D, host_output);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    ssao_inputs in = scene.in;
    in.normal_texture = own;
    in.normal_packing = SSAO_NORMAL_PACKING_UNORM;
    in.output_texture = host_output;
    CHECK(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_OK);
    CHECK(fx.read_red(own, kSize, kSize) == before);
    gl.DeleteTextures(1, &host_output);
    CHECK(fx.gl_errors().empty());
}
