// A driver that keeps to the core profile's letter, as NVIDIA's does where
// Mesa is lenient: glGetIntegerv(GL_POLYGON_MODE) writes one value (the core
// state table holds one mode), and glPolygonMode refuses GL_FRONT and GL_BACK
// with GL_INVALID_ENUM. The library gets GL through wrappers that behave so,
// and the host's polygon mode must come back without a refused call.
#include <doctest/doctest.h>

#include "gl_fixture.h"
#include "test_scenes.h"

#include <cstring>

namespace {

PFNGLGETINTEGERVPROC g_get_integerv = nullptr;
PFNGLPOLYGONMODEPROC g_polygon_mode = nullptr;
int g_refused_faces = 0;

void GLAD_API_PTR strict_get_integerv(GLenum pname, GLint* data) {
    if (pname != GL_POLYGON_MODE) {
        g_get_integerv(pname, data);
        return;
    }
    GLint both[2] = {};
    g_get_integerv(pname, both);
    data[0] = both[0];
}

void GLAD_API_PTR strict_polygon_mode(GLenum face, GLenum mode) {
    if (face != GL_FRONT_AND_BACK) {
        ++g_refused_faces;
        return;
    }
    g_polygon_mode(face, mode);
}

ssao_gl_proc SSAO_CALL strict_get_proc(void* user, const char* name) {
    if (std::strcmp(name, "glGetIntegerv") == 0) return reinterpret_cast<ssao_gl_proc>(&strict_get_integerv);
    if (std::strcmp(name, "glPolygonMode") == 0) return reinterpret_cast<ssao_gl_proc>(&strict_polygon_mode);
    return eglctx::Context::get_proc(user, name);
}

}  // namespace

TEST_CASE("a strict core driver (one GL_POLYGON_MODE value, GL_FRONT refused): the host's mode comes back through "
          "GL_FRONT_AND_BACK alone") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    g_get_integerv = gl.GetIntegerv;
    g_polygon_mode = gl.PolygonMode;
    g_refused_faces = 0;
    ssao_context_desc desc{};
    desc.size = sizeof desc;
    desc.get_proc_address = &strict_get_proc;
    ssao_context* ctx = nullptr;
    REQUIRE(fx.api().create_context(&desc, &ctx) == SSAO_OK);
    const auto proj = analytic::perspective(testscenes::kFov, 1.0, 0.1, 100.0);
    const analytic::GBuffer g =
        analytic::render(testscenes::crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 16, 16);
    const testgl::Textures t = fx.upload(g);
    const ssao_inputs in = fx.inputs(t.depth, t.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    ssao_output out{};
    out.size = sizeof out;
    for (GLenum mode : {GL_LINE, GL_POINT, GL_FILL}) {
        CAPTURE(mode);
        gl.PolygonMode(GL_FRONT_AND_BACK, mode);
        CHECK(fx.api().execute(ctx, &in, &out) == SSAO_OK);
        // Two values from Mesa, one from a strict driver (the second slot untouched).
        GLint after[2] = {0, -1};
        gl.GetIntegerv(GL_POLYGON_MODE, after);
        CHECK(after[0] == GLint(mode));
        CHECK((after[1] == -1 || after[1] == GLint(mode)));
    }
    CHECK(g_refused_faces == 0);
    fx.api().destroy_context(ctx);
    CHECK(fx.gl_errors().empty());
}
