// A host buffer bound at every buffer binding point while execute and
// get_timings run: GL_QUERY_BUFFER (where reading a query result writes into
// the bound buffer) and each binding the library does not use. For each one:
// no GL error, every binding and piece of state as the host left it, the
// timings become available, and the AO is the AO without the binding.
#include <doctest/doctest.h>

#include "crease_textures.h"
#include "gl_fixture.h"
#include "gl_state_snapshot.h"
#include "test_scenes.h"

#include <string>
#include <vector>

using testscenes::make;

namespace {

constexpr int kSize = 32;
constexpr int kFrames = 8;  // more than the timer ring's latency on llvmpipe, with a glFinish after each

struct Binding {
    const char* name;
    GLenum target;
    int version;        // the GL version that has the target (x10)
};

const Binding kBindings[] = {
    {"GL_QUERY_BUFFER", GL_QUERY_BUFFER, 44},
    {"GL_PIXEL_PACK_BUFFER", GL_PIXEL_PACK_BUFFER, 33},
    {"GL_PIXEL_UNPACK_BUFFER", GL_PIXEL_UNPACK_BUFFER, 33},
    {"GL_ELEMENT_ARRAY_BUFFER", GL_ELEMENT_ARRAY_BUFFER, 33},  // of a host vertex array
    {"GL_DRAW_INDIRECT_BUFFER", GL_DRAW_INDIRECT_BUFFER, 40},
    {"GL_COPY_READ_BUFFER", GL_COPY_READ_BUFFER, 33},
    {"GL_COPY_WRITE_BUFFER", GL_COPY_WRITE_BUFFER, 33},
    {"GL_TEXTURE_BUFFER", GL_TEXTURE_BUFFER, 33},
    {"GL_TRANSFORM_FEEDBACK_BUFFER", GL_TRANSFORM_FEEDBACK_BUFFER, 33},
    {"GL_ATOMIC_COUNTER_BUFFER", GL_ATOMIC_COUNTER_BUFFER, 42},
    {"GL_SHADER_STORAGE_BUFFER", GL_SHADER_STORAGE_BUFFER, 43},
    {"GL_DISPATCH_INDIRECT_BUFFER", GL_DISPATCH_INDIRECT_BUFFER, 43},
    {"GL_ARRAY_BUFFER", GL_ARRAY_BUFFER, 33},
    {"GL_UNIFORM_BUFFER", GL_UNIFORM_BUFFER, 33},
};

}  // namespace

TEST_CASE("host buffers at every binding point: no GL error, state kept, timings available, AO unchanged") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const ssao_inputs in = testscenes::CreaseTextures(fx, kSize).in;
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    REQUIRE(major * 10 + minor >= 44);  // the query buffer is what this test is for

    // The AO of each binding's settings, without any binding (a new seed per
    // binding: its first execute uploads a new kernel with the binding in place).
    auto settings_for = [](int i) {
        ssao_settings s = make(8, SSAO_BLUR_DEFAULT);
        s.seed = static_cast<uint32_t>(2 + i);
        return s;
    };
    const int count = static_cast<int>(sizeof kBindings / sizeof kBindings[0]);
    std::vector<std::vector<float>> expected;
    for (int i = 0; i < count; ++i) {
        fx.settings(settings_for(i));
        ssao_output out{};
        out.size = sizeof out;
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        expected.push_back(fx.read_red(out.texture, kSize, kSize));
    }
    int executes = count;
    GLuint host_vao = 0;
    gl.GenVertexArrays(1, &host_vao);

    for (int i = 0; i < count; ++i) {
        const Binding& b = kBindings[i];
        CAPTURE(b.name);
        GLuint buffer = 0;
        gl.GenBuffers(1, &buffer);
        if (b.target == GL_ELEMENT_ARRAY_BUFFER) gl.BindVertexArray(host_vao);
        gl.BindBuffer(b.target, buffer);
        // Small: a query result written at a client pointer's value as offset is out of bounds.
        gl.BufferData(b.target, 64, nullptr, GL_DYNAMIC_COPY);
        fx.settings(settings_for(i));
        const testgl::Snapshot before = testgl::snapshot(gl);

        ssao_output out{};
        out.size = sizeof out;
        for (int f = 0; f < kFrames; ++f) {
            REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
            gl.Finish();
        }
        ssao_timings t{};
        t.size = sizeof t;
        REQUIRE(fx.api().get_timings(fx.ctx(), &t) == SSAO_OK);
        CHECK(t.available == 1u);
        CHECK(t.frame > static_cast<uint64_t>(executes));  // measured with the binding in place
        CHECK(t.total_ms > 0.0);
        executes += kFrames;

        CHECK(testgl::changed_state(before, testgl::snapshot(gl)) == "");
        for (const std::string& e : fx.gl_errors()) MESSAGE(e);
        CHECK(fx.gl_errors().empty());

        // Unbind (the read-back packs into client memory) and compare.
        gl.BindBuffer(b.target, 0);
        if (b.target == GL_ELEMENT_ARRAY_BUFFER) gl.BindVertexArray(0);
        gl.DeleteBuffers(1, &buffer);
        const std::vector<float> ao = fx.read_red(out.texture, kSize, kSize);
        CHECK(ao == expected[static_cast<size_t>(i)]);
        if (!fx.gl_errors().empty()) break;  // one binding's errors would repeat in every later one
    }
    gl.DeleteVertexArrays(1, &host_vao);
}
