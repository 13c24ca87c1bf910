// test_debug_names.cpp - what a debugger (RenderDoc, apitrace) sees of the
// library through KHR_debug: one group "ssao" around every execute, one group
// per pass inside it named after the pass and in the plan's order, balanced
// on every return and never overflowing the host's group stack; and a
// "ssao: ..." label on every GL object the library made.
#include <doctest/doctest.h>

#include "debug_groups.h"
#include "crease_textures.h"
#include "gl_fixture.h"
#include "test_scenes.h"

#include <initializer_list>
#include <map>
#include <set>
#include <string>
#include <vector>

using testgl::DebugGroupLog;
using testscenes::make;

namespace {

using Events = std::vector<DebugGroupLog::Event>;

// The events of one execute that ran `passes` (debug-group names), in order.
Events expected_groups(const std::vector<std::string>& passes) {
    Events e{{true, GL_DEBUG_SOURCE_APPLICATION, "ssao"}};
    for (const std::string& p : passes) {
        e.push_back({true, GL_DEBUG_SOURCE_APPLICATION, p});
        e.push_back({false, GL_DEBUG_SOURCE_APPLICATION, p});
    }
    e.push_back({false, GL_DEBUG_SOURCE_APPLICATION, "ssao"});
    return e;
}

// The names of the passes in the order they ran, from the per-pass timings
// of a measured frame (the plan's order, as the library reports it).
std::vector<std::string> names_of(const ssao_timings& t) {
    const std::map<uint32_t, std::string> name = {{SSAO_PASS_OCCLUSION, "ssao: kernel"},
                                                  {SSAO_PASS_BLUR_X, "ssao: blur x"},
                                                  {SSAO_PASS_BLUR_Y, "ssao: blur y"},
                                                  {SSAO_PASS_CLEAR, "ssao: clear"},
                                                  {SSAO_PASS_GRID, "ssao: grid"},
                                                  {SSAO_PASS_UPSAMPLE, "ssao: upsample"}};
    std::vector<std::string> out;
    for (uint32_t i = 0; i < t.pass_count; ++i) out.push_back(name.at(t.pass_kind[i]));
    return out;
}

using Inputs = testscenes::CreaseTextures;

}  // namespace

TEST_CASE("debug groups: each pass in its own group inside 'ssao', in the plan's order, stack depth unchanged") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    REQUIRE((gl.PushDebugGroup != nullptr));  // GL 4.5: KHR_debug is core
    Inputs scene(fx);
    ssao_settings off = make(16, SSAO_BLUR_DEFAULT);
    off.strength = SSAO_STRENGTH_OFF;
    ssao_settings half = make(16, SSAO_BLUR_DEPTH_AWARE), quarter_box = make(16, SSAO_BLUR_BOX_4X4);
    half.resolution = SSAO_RESOLUTION_HALF;
    quarter_box.resolution = SSAO_RESOLUTION_QUARTER;
    struct Case {
        const char* what;
        ssao_settings settings;
        std::vector<std::string> passes;
    };
    const Case cases[] = {
        {"depth-aware", make(16, SSAO_BLUR_DEPTH_AWARE), {"ssao: grid", "ssao: kernel", "ssao: blur x", "ssao: blur y"}},
        {"gaussian", make(16, SSAO_BLUR_GAUSSIAN), {"ssao: kernel", "ssao: blur x", "ssao: blur y"}},
        {"box", make(16, SSAO_BLUR_BOX_4X4), {"ssao: kernel", "ssao: blur x"}},
        {"no blur", make(16, SSAO_BLUR_NONE), {"ssao: kernel"}},
        {"strength off", off, {"ssao: clear"}},
        {"half resolution", half,
         {"ssao: grid", "ssao: kernel", "ssao: blur x", "ssao: blur y", "ssao: upsample"}},
        {"quarter resolution, box", quarter_box, {"ssao: grid", "ssao: kernel", "ssao: blur x", "ssao: upsample"}},
    };
    DebugGroupLog log(gl);
    for (const Case& c : cases) {
        const std::string what_ = c.what;
        CAPTURE(what_);
        fx.settings(c.settings);
        // Inside a group of the host's own: the library's nest in it.
        gl.PushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 7, -1, "host frame");
        const GLint depth_before = testgl::debug_group_depth(gl);
        log.clear();
        ssao_timings t{};
        t.size = sizeof t;
        for (int frame = 0; frame < 12 && !(t.available && t.frame > 0 && t.pass_count == c.passes.size()); ++frame) {
            log.clear();
            ssao_output out{};
            out.size = sizeof out;
            REQUIRE(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_OK);
            CHECK(testgl::debug_group_depth(gl) == depth_before);
            const std::string events = log.text();
            CAPTURE(events);
            CHECK(log.events() == expected_groups(c.passes));
            gl.Finish();
            REQUIRE(fx.api().get_timings(fx.ctx(), &t) == SSAO_OK);
        }
        // The groups name the passes the library reports it ran, in that order.
        REQUIRE(t.available == 1u);
        CHECK(names_of(t) == c.passes);
        gl.PopDebugGroup();
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("debug groups: a refused execute pushes and pops 'ssao' only, at every stage it can be refused") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    Inputs scene(fx);
    const GLuint small_normal = fx.make_normals(GL_RGBA16F, 8, 8, std::vector<glm::vec3>(64, glm::vec3(0, 0, 1)));
    DebugGroupLog log(gl);
    struct Bad {
        const char* what;
        ssao_inputs in;
    };
    ssao_inputs bad_enum = scene.in, no_depth = scene.in, wrong_size = scene.in, bad_viewport = scene.in;
    bad_enum.clip_range = static_cast<ssao_clip_range>(9);
    no_depth.depth_texture = 0;
    wrong_size.normal_texture = small_normal;  // refused after the textures were bound (inside the guard)
    bad_viewport.viewport[2] = 1000;
    bad_viewport.viewport[3] = 10;
    const Bad bad[] = {{"enum", bad_enum}, {"no depth", no_depth}, {"normal size", wrong_size},
                       {"viewport", bad_viewport}};
    for (const Bad& b : bad) {
        const std::string what_ = b.what;
        CAPTURE(what_);
        const GLint depth_before = testgl::debug_group_depth(gl);
        log.clear();
        CHECK(fx.api().execute(fx.ctx(), &b.in, nullptr) != SSAO_OK);
        CHECK(testgl::debug_group_depth(gl) == depth_before);
        const std::string events = log.text();
        CAPTURE(events);
        CHECK(log.events() == expected_groups({}));
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("debug groups: a host stack with no room for two more gets none, and no GL error") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    Inputs scene(fx);
    fx.settings(make(16, SSAO_BLUR_DEFAULT));
    GLint max_depth = 0;
    gl.GetIntegerv(GL_MAX_DEBUG_GROUP_STACK_DEPTH, &max_depth);
    REQUIRE(max_depth >= 64);  // the spec's minimum
    DebugGroupLog log(gl);
    const ssao_output reference = [&] {
        ssao_output out{};
        out.size = sizeof out;
        REQUIRE(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_OK);
        return out;
    }();
    const std::vector<float> ao_reference = fx.read_red(reference.texture, scene.g.width, scene.g.height);

    // Fill the host's stack up to `free_slots` below its limit.
    auto fill_to = [&](int free_slots) {
        while (testgl::debug_group_depth(gl) < max_depth - free_slots)
            gl.PushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 1, -1, "host");
    };
    auto empty_stack = [&] {
        while (testgl::debug_group_depth(gl) > 1) gl.PopDebugGroup();
    };
    for (int free_slots : {0, 1, 2}) {
        CAPTURE(free_slots);
        fill_to(free_slots);
        const GLint depth_before = testgl::debug_group_depth(gl);
        log.clear();
        ssao_output out{};
        out.size = sizeof out;
        REQUIRE(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_OK);
        CHECK(testgl::debug_group_depth(gl) == depth_before);
        const std::string events = log.text();
        CAPTURE(events);
        // Two free slots hold "ssao" and one pass group; fewer get nothing.
        if (free_slots >= 2)
            CHECK(log.events() == expected_groups({"ssao: grid", "ssao: kernel", "ssao: blur x", "ssao: blur y"}));
        else
            CHECK(log.events().empty());
        CHECK(fx.read_red(out.texture, scene.g.width, scene.g.height) == ao_reference);
        empty_stack();
    }
    CHECK(fx.gl_errors().empty());  // no GL_STACK_OVERFLOW
}

TEST_CASE("object labels: every GL object the library made carries an 'ssao: ...' name, the host's none, on a "
          "software rasteriser's plan and a GPU's") {
  for (const testgl::RendererKind& kind : testgl::kRendererKinds) {
    const std::string renderer = kind.gl_renderer;
    CAPTURE(renderer);
    testgl::Fixture fx;
    fx.recreate_context_as(kind.gl_renderer);
    auto& gl = fx.gl();
    Inputs scene(fx);
    fx.settings(make(16, SSAO_BLUR_DEFAULT));
    ssao_output out{};
    out.size = sizeof out;
    for (int i = 0; i < 3; ++i) {
        REQUIRE(fx.api().execute(fx.ctx(), &scene.in, &out) == SSAO_OK);
        gl.Finish();
    }
    CHECK(testgl::object_label(gl, GL_TEXTURE, out.texture).rfind("ssao: output ", 0) == 0);
    CHECK(testgl::object_label(gl, GL_TEXTURE, scene.depth).empty());
    CHECK(testgl::object_label(gl, GL_TEXTURE, scene.normal).empty());

    // Every live object of each type, by name, and its label.
    struct Kind {
        GLenum identifier;
        GLboolean (*is)(GladGLContext&, GLuint);
        std::multiset<std::string> expected;  // the library's labels of this type
    };
    // A software rasteriser's plan tests the output against a copy of the
    // host's depth and clears the sky; a GPU's draws the sky fill (plan.h).
    std::multiset<std::string> textures = {"ssao: intermediate 0", "ssao: intermediate 1", "ssao: intermediate 2",
                                           "ssao: intermediate 3", "ssao: noise",          "ssao: output",
                                           "ssao: sky mask 0"};
    std::multiset<std::string> programs = {"ssao: kernel program", "ssao: kernel program", "ssao: blur program",
                                           "ssao: visibility program", "ssao: grid program", "ssao: upsample program"};
    std::multiset<std::string> framebuffers = {"ssao: framebuffer"};
    if (kind.software) {
        textures.insert("ssao: sky mask 1");
        framebuffers.insert("ssao: depth copy source");
    } else {
        programs.insert("ssao: sky fill program");
    }
    const Kind kinds[] = {
        // Textures: the grid pass's two (the depth-aware blur reads its tangent planes), the AO, the blur's x
        // pass; the sky masks: the grid's, and (software) the copy of the host's depth the last blur tests.
        {GL_TEXTURE, [](GladGLContext& g, GLuint n) { return g.IsTexture(n); }, textures},
        // Programs: those create_context compiles, and the kernel's variant that reads the grid.
        {GL_PROGRAM, [](GladGLContext& g, GLuint n) { return g.IsProgram(n); }, programs},
        {GL_BUFFER, [](GladGLContext& g, GLuint n) { return g.IsBuffer(n); },
         {"ssao: frame constants", "ssao: kernel"}},
        {GL_FRAMEBUFFER, [](GladGLContext& g, GLuint n) { return g.IsFramebuffer(n); }, framebuffers},
        {GL_VERTEX_ARRAY, [](GladGLContext& g, GLuint n) { return g.IsVertexArray(n); }, {"ssao: vertex array"}},
        {GL_SAMPLER, [](GladGLContext& g, GLuint n) { return g.IsSampler(n); }, {"ssao: sampler"}},
    };
    for (const Kind& k : kinds) {
        CAPTURE(k.identifier);
        std::multiset<std::string> library, unlabelled_host;
        for (GLuint name = 1; name < 512; ++name) {
            if (!k.is(gl, name)) continue;
            std::string label = testgl::object_label(gl, k.identifier, name);
            // The vertex array's label ends in a number unique in the process
            // (how the library recognises its GL context): "ssao: vertex array 7".
            // The output texture's ends in the same number.
            for (const std::string numbered : {"ssao: vertex array ", "ssao: output "})
                if (label.rfind(numbered, 0) == 0 && label.size() > numbered.size() &&
                    label.find_first_not_of("0123456789", numbered.size()) == std::string::npos)
                    label = numbered.substr(0, numbered.size() - 1);
            if (label.rfind("ssao: ", 0) == 0)
                library.insert(label);
            else
                CHECK(label.empty());  // the host's objects are left alone
        }
        CHECK(library == k.expected);
    }
    // Timer queries: every one used so far (one per stamp: 5 a frame for four passes, 3 frames) is named.
    int timers = 0;
    for (GLuint name = 1; name < 512; ++name)
        if (gl.IsQuery(name)) {
            CHECK(testgl::object_label(gl, GL_QUERY, name) == "ssao: timer");
            ++timers;
        }
    CHECK(timers == 3 * 5);
    CHECK(fx.gl_errors().empty());
  }
}
