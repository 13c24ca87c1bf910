// The library on a GL context other than the one it was created on: an
// unrelated context, one sharing objects with the creator, none at all, and
// one made after the creator was destroyed. execute, get_timings and
// destroy_context return SSAO_ERROR_WRONG_CONTEXT there, raise no GL error,
// and make, bind or delete nothing in that context.
#include <doctest/doctest.h>

#include "debug_groups.h"
#include "gl_fixture.h"
#include "crease_textures.h"
#include "gl_state_snapshot.h"
#include "other_context.h"
#include "test_scenes.h"

#include <set>
#include <stdexcept>
#include <string>
#include <vector>

using testgl::OtherContext;
using testscenes::CreaseTextures;
using testscenes::kFov;
using testscenes::make;

namespace {

constexpr int kSize = 32;

// The crease scene's G-buffer, uploaded on the fixture's (current) context.
struct Scene : CreaseTextures {
    explicit Scene(testgl::Fixture& fx) : CreaseTextures(fx, kSize) {}
};

// Names 1..255 that are objects of a kind in the current context.
template <typename Is>
std::set<GLuint> live(Is is) {
    std::set<GLuint> names;
    for (GLuint n = 1; n < 256; ++n)
        if (is(n)) names.insert(n);
    return names;
}

std::set<GLuint> live_vertex_arrays(GladGLContext& gl) { return live([&](GLuint n) { return gl.IsVertexArray(n); }); }
std::set<GLuint> live_framebuffers(GladGLContext& gl) { return live([&](GLuint n) { return gl.IsFramebuffer(n); }); }
std::set<GLuint> live_programs(GladGLContext& gl) { return live([&](GLuint n) { return gl.IsProgram(n); }); }
std::set<GLuint> live_textures(GladGLContext& gl) { return live([&](GLuint n) { return gl.IsTexture(n); }); }
std::set<GLuint> live_queries(GladGLContext& gl) { return live([&](GLuint n) { return gl.IsQuery(n); }); }

bool says_wrong_context(const ssao_api& api, const ssao_context* ctx) {
    return std::string(api.last_error(ctx)).find("not the one this ssao_context was created on") != std::string::npos;
}

void run_frames(testgl::Fixture& fx, const ssao_inputs& in, int frames) {
    for (int i = 0; i < frames; ++i) {
        REQUIRE(fx.api().execute(fx.ctx(), &in, nullptr) == SSAO_OK);
        fx.gl().Finish();
    }
}

}  // namespace

TEST_CASE("wrong context: an unrelated GL context current: refused, no GL error, nothing made, bound or changed there") {
    testgl::Fixture fx;
    fx.settings(make(8, SSAO_BLUR_DEFAULT));
    Scene scene(fx);
    run_frames(fx, scene.in, 3);

    OtherContext other(OtherContext::Sharing::none);
    other.make_current();
    auto& gl = other.gl();
    // The host's own objects in that context, and its state.
    GLuint host_vao = 0, host_fbo = 0;
    gl.GenVertexArrays(1, &host_vao);
    gl.BindVertexArray(host_vao);
    gl.GenFramebuffers(1, &host_fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, host_fbo);
    const std::set<GLuint> vaos = live_vertex_arrays(gl), fbos = live_framebuffers(gl);
    const testgl::Snapshot before = testgl::snapshot(gl);

    ssao_output out{};
    out.size = sizeof out;
    CHECK(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_ERROR_WRONG_CONTEXT);
    CHECK(says_wrong_context(fx.api(), fx.ctx()));
    CHECK(out.texture == 0u);  // nothing written
    ssao_timings t{};
    t.size = sizeof t;
    t.frame = 12345;
    CHECK(fx.api().get_timings(fx.ctx(), &t) == SSAO_ERROR_WRONG_CONTEXT);
    CHECK(t.frame == 12345u);  // out untouched
    // Calls that need no GL still work.
    ssao_settings s{};
    s.size = sizeof s;
    CHECK(fx.api().get_settings(fx.ctx(), &s) == SSAO_OK);
    CHECK(fx.api().set_settings(fx.ctx(), &s) == SSAO_OK);

    CHECK(other.gl_errors().empty());
    for (const std::string& e : other.gl_errors()) MESSAGE(e);
    CHECK(live_vertex_arrays(gl) == vaos);
    CHECK(live_framebuffers(gl) == fbos);
    CHECK(testgl::changed_state(before, testgl::snapshot(gl)) == "");

    // Back on the creating context everything works as before.
    other.make_first_current();
    run_frames(fx, scene.in, 1);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("wrong context: another GL context with its own ssao_context (same object names, same labels but the number)") {
    testgl::Fixture fx;
    Scene scene(fx);
    run_frames(fx, scene.in, 1);
    const std::set<GLuint> first_vaos = live_vertex_arrays(fx.gl());

    // A second library context on a second GL context: its vertex array gets
    // the same name there (both are the first one each context made).
    OtherContext other(OtherContext::Sharing::none);
    other.make_current();
    ssao_context* second = nullptr;
    REQUIRE(testgl::create_default_context(fx.api(), &second) == SSAO_OK);
    CHECK(live_vertex_arrays(other.gl()) == first_vaos);

    CHECK(fx.api().execute(fx.ctx(), &scene.in, nullptr) == SSAO_ERROR_WRONG_CONTEXT);
    CHECK(says_wrong_context(fx.api(), fx.ctx()));
    CHECK(other.gl_errors().empty());
    CHECK(fx.api().destroy_context(second) == SSAO_OK);
    CHECK(other.gl_errors().empty());
    other.make_first_current();
}

TEST_CASE("wrong context: destroy_context there frees the library's memory and deletes none of that context's objects") {
    testgl::Fixture fx;
    Scene scene(fx);
    run_frames(fx, scene.in, 2);
    auto& first = fx.gl();
    // The library's programs, vertex array and textures on the creating context.
    std::set<GLuint> library_programs;
    for (GLuint n : live_programs(first))
        if (testgl::object_label(first, GL_PROGRAM, n).rfind("ssao: ", 0) == 0) library_programs.insert(n);
    REQUIRE_FALSE(library_programs.empty());
    const std::set<GLuint> first_vaos = live_vertex_arrays(first), first_textures = live_textures(first),
                           first_programs = live_programs(first);

    // A second context whose own programs take the same names as the library's.
    OtherContext other(OtherContext::Sharing::none);
    other.make_current();
    auto& gl = other.gl();
    std::vector<GLuint> host_programs;
    host_programs.push_back(testgl::make_host_program(gl));  // one linked, as a host's
    while (host_programs.back() < *library_programs.rbegin()) {
        host_programs.push_back(gl.CreateProgram());
        REQUIRE(host_programs.size() < 256u);
    }
    GLuint host_vao = 0, host_fbo = 0, host_texture = 0;
    gl.GenVertexArrays(1, &host_vao);
    gl.BindVertexArray(host_vao);
    gl.GenFramebuffers(1, &host_fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, host_fbo);
    gl.GenTextures(1, &host_texture);
    gl.BindTexture(GL_TEXTURE_2D, host_texture);
    const std::set<GLuint> programs = live_programs(gl), vaos = live_vertex_arrays(gl), fbos = live_framebuffers(gl),
                           textures = live_textures(gl);
    int clashes = 0;  // library program names that name a host program here
    for (GLuint p : library_programs) clashes += static_cast<int>(programs.count(p));
    REQUIRE(clashes >= 3);

    CHECK(fx.api().destroy_context(fx.ctx()) == SSAO_ERROR_WRONG_CONTEXT);
    fx.forget_context();  // freed: the fixture must not destroy it again
    CHECK(other.gl_errors().empty());
    CHECK(live_programs(gl) == programs);
    CHECK(live_vertex_arrays(gl) == vaos);
    CHECK(live_framebuffers(gl) == fbos);
    CHECK(live_textures(gl) == textures);

    // Nothing was deleted on the creating context either: its objects go
    // with that context.
    other.make_first_current();
    CHECK(live_vertex_arrays(first) == first_vaos);
    CHECK(live_textures(first) == first_textures);
    CHECK(live_programs(first) == first_programs);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("wrong context: a context sharing objects with the creating one is refused without a GL error") {
    testgl::Fixture fx;
    fx.settings(make(8, SSAO_BLUR_DEFAULT));
    Scene scene(fx);
    run_frames(fx, scene.in, 3);  // timer queries pending: reading them on the sharing context raised errors

    OtherContext shared(OtherContext::Sharing::with_current);
    shared.make_current();
    auto& gl = shared.gl();
    REQUIRE(gl.IsTexture(scene.depth));  // it does share the textures
    const std::set<GLuint> vaos = live_vertex_arrays(gl), fbos = live_framebuffers(gl), queries = live_queries(gl);
    CHECK(fx.api().execute(fx.ctx(), &scene.in, nullptr) == SSAO_ERROR_WRONG_CONTEXT);
    CHECK(says_wrong_context(fx.api(), fx.ctx()));
    ssao_timings t{};
    t.size = sizeof t;
    CHECK(fx.api().get_timings(fx.ctx(), &t) == SSAO_ERROR_WRONG_CONTEXT);
    for (const std::string& e : shared.gl_errors()) MESSAGE(e);
    CHECK(shared.gl_errors().empty());
    CHECK(live_vertex_arrays(gl) == vaos);
    CHECK(live_framebuffers(gl) == fbos);
    CHECK(live_queries(gl) == queries);

    shared.make_first_current();
    run_frames(fx, scene.in, 1);
    CHECK(fx.api().get_timings(fx.ctx(), &t) == SSAO_OK);
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("wrong context: no context current, and the creating context destroyed with another made current") {
    auto first = testgl::make_debug_context();
    plugin::Library lib;
    std::string error;
    REQUIRE_MESSAGE(lib.open(plugin::Library::default_path(), error), error);
    const ssao_api& api = lib.api();
    ssao_context* ctx = nullptr;
    REQUIRE(testgl::create_default_context(api, &ctx) == SSAO_OK);
    // Inputs on the first context.
    auto& g = first->gl();
    const std::vector<float> depth(kSize * kSize, 0.5f), normal(kSize * kSize * 4, 0.0f);
    GLuint tex[2] = {};
    g.GenTextures(2, tex);
    g.BindTexture(GL_TEXTURE_2D, tex[0]);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, kSize, kSize, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    g.BindTexture(GL_TEXTURE_2D, tex[1]);
    g.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, kSize, kSize, 0, GL_RGBA, GL_FLOAT, normal.data());
    g.BindTexture(GL_TEXTURE_2D, 0);
    ssao_inputs in{};
    in.size = sizeof in;
    in.depth_texture = tex[0];
    in.normal_texture = tex[1];
    analytic::to_floats(analytic::perspective(kFov, 1.0, 0.1, 100.0), in.projection);
    REQUIRE(api.execute(ctx, &in, nullptr) == SSAO_OK);
    REQUIRE(api.execute(ctx, &in, nullptr) == SSAO_OK);

    OtherContext other(OtherContext::Sharing::none);
    other.release_current();
    ssao_timings t{};
    t.size = sizeof t;
    CHECK(api.execute(ctx, &in, nullptr) == SSAO_ERROR_WRONG_CONTEXT);  // none current
    CHECK(api.get_timings(ctx, &t) == SSAO_ERROR_WRONG_CONTEXT);

    other.make_first_current();
    first.reset();  // the creating context is destroyed (and nothing is current)
    CHECK(api.execute(ctx, &in, nullptr) == SSAO_ERROR_WRONG_CONTEXT);
    other.make_current();
    const std::set<GLuint> vaos = live_vertex_arrays(other.gl());
    CHECK(api.execute(ctx, &in, nullptr) == SSAO_ERROR_WRONG_CONTEXT);
    CHECK(says_wrong_context(api, ctx));
    CHECK(api.get_timings(ctx, &t) == SSAO_ERROR_WRONG_CONTEXT);
    CHECK(api.destroy_context(ctx) == SSAO_ERROR_WRONG_CONTEXT);
    CHECK(live_vertex_arrays(other.gl()) == vaos);
    for (const std::string& e : other.gl_errors()) MESSAGE(e);
    CHECK(other.gl_errors().empty());
    other.release_current();
}
