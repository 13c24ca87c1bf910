// test_abi_gl.cpp - the ABI with a context on a real (headless EGL, Mesa)
// GL 4.5 core context: NULL pointers and struct sizes of every context
// function, every execute validation error, settings that must not apply,
// which passes run, and the plugin-owned output across resizes.
#include "abi_common.h"
#include "analytic_scene.h"
#include "child_process.h"
#include "test_scenes.h"

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace unit;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

constexpr int kW = 16, kH = 16;

// Host textures of a flat wall facing the camera at view distance 10.
struct Scene {
    GLuint depth = 0, normal = 0;
    ssao_inputs inputs{};
    Scene(GladGLContext& gl, int w, int h) {
        float proj[16];
        default_projection(proj);
        depth = make_depth(gl, w, h, depth_at(proj, 10.0f));
        normal = make_normals(gl, w, h);
        inputs = make_inputs(depth, normal);
    }
};

// A failing execute returns `expected`, writes nothing into `out`, leaves
// the GL state and the last frame info alone, and explains itself in
// last_error (naming `keyword`) and in the log.
void expect_execute_fails(GlFixture& f, const ssao_inputs& in, ssao_status expected, const char* keyword) {
    const ssao_api& a = api();
    GladGLContext& gl = f.gl();
    set_host_state(gl);
    const GlSnapshot state_before = snapshot(gl);
    ssao_frame_info info_before = sized<ssao_frame_info>();
    REQUIRE(a.get_frame_info(f.ctx, &info_before) == SSAO_OK);
    ssao_output out = sentinel<ssao_output>();
    const ssao_output out_before = out;
    const size_t logged = f.log.entries.size();

    CHECK(a.execute(f.ctx, &in, &out) == expected);

    CHECK(same_bytes(out, out_before));
    CHECK(snapshot(gl) == state_before);
    ssao_frame_info info_after = sized<ssao_frame_info>();
    REQUIRE(a.get_frame_info(f.ctx, &info_after) == SSAO_OK);
    CHECK(same_bytes(info_after, info_before));
    const std::string error = f.last_error();
    CAPTURE(error);
    CHECK_FALSE(error.empty());
    CHECK(contains(error, keyword));
    REQUIRE(f.log.entries.size() == logged + 1);
    CHECK(f.log.entries.back().level == SSAO_LOG_ERROR);
    CHECK(f.log.entries.back().message == error);
}

// Full resolution: these cases name the full-resolution passes.
ssao_settings with_blur(ssao_blur blur) {
    ssao_settings s = sized<ssao_settings>();
    s.blur = blur;
    s.resolution = SSAO_RESOLUTION_FULL;
    return s;
}

void set_settings_ok(GlFixture& f, const ssao_settings& s) {
    REQUIRE(api().set_settings(f.ctx, &s) == SSAO_OK);
}

ssao_settings current_settings(GlFixture& f) {
    ssao_settings s = sized<ssao_settings>();
    REQUIRE(api().get_settings(f.ctx, &s) == SSAO_OK);
    return s;
}

void level0(GladGLContext& gl, GLuint tex, GLint& w, GLint& h, GLint& format) {
    gl.GetTextureLevelParameteriv(tex, 0, GL_TEXTURE_WIDTH, &w);
    gl.GetTextureLevelParameteriv(tex, 0, GL_TEXTURE_HEIGHT, &h);
    gl.GetTextureLevelParameteriv(tex, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
}

std::vector<float> read_red(GladGLContext& gl, GLuint tex, int w, int h) {
    std::vector<float> px(static_cast<size_t>(w) * h, -1.0f);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.GetTextureImage(tex, 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(px.size() * sizeof(float)), px.data());
    return px;
}

}  // namespace

TEST_CASE("abi: every context function rejects NULL pointers") {
    GlFixture f;
    const ssao_api& a = api();
    Scene scene(f.gl(), kW, kH);
    ssao_settings s = sized<ssao_settings>();
    ssao_output out = sized<ssao_output>();
    ssao_timings t = sized<ssao_timings>();
    ssao_frame_info fi = sized<ssao_frame_info>();

    CHECK(a.set_settings(nullptr, &s) == SSAO_ERROR_NULL_POINTER);
    CHECK(a.get_settings(nullptr, &s) == SSAO_ERROR_NULL_POINTER);
    CHECK(a.execute(nullptr, &scene.inputs, &out) == SSAO_ERROR_NULL_POINTER);
    CHECK(a.get_timings(nullptr, &t) == SSAO_ERROR_NULL_POINTER);
    CHECK(a.get_frame_info(nullptr, &fi) == SSAO_ERROR_NULL_POINTER);
    CHECK(a.destroy_context(nullptr) == SSAO_OK);

    struct Call {
        const char* what;
        ssao_status (*call)(const ssao_api&, ssao_context*);
    };
    const Call calls[] = {
        {"set_settings", [](const ssao_api& x, ssao_context* c) { return x.set_settings(c, nullptr); }},
        {"get_settings", [](const ssao_api& x, ssao_context* c) { return x.get_settings(c, nullptr); }},
        {"execute", [](const ssao_api& x, ssao_context* c) {
             ssao_output o = sized<ssao_output>();
             return x.execute(c, nullptr, &o);
         }},
        {"get_timings", [](const ssao_api& x, ssao_context* c) { return x.get_timings(c, nullptr); }},
        {"get_frame_info", [](const ssao_api& x, ssao_context* c) { return x.get_frame_info(c, nullptr); }},
    };
    for (const Call& c : calls) {
        const std::string what_ = c.what;
        CAPTURE(what_);
        // Clear last_error with a successful call first.
        REQUIRE(a.execute(f.ctx, &scene.inputs, nullptr) == SSAO_OK);
        const size_t logged = f.log.entries.size();
        CHECK(c.call(a, f.ctx) == SSAO_ERROR_NULL_POINTER);
        CHECK_FALSE(f.last_error().empty());
        CHECK(f.log.entries.size() == logged + 1);
    }
    // `out` may be NULL.
    CHECK(a.execute(f.ctx, &scene.inputs, nullptr) == SSAO_OK);
}

TEST_CASE("abi: every context function rejects wrong struct sizes and writes nothing") {
    GlFixture f;
    const ssao_api& a = api();
    Scene scene(f.gl(), kW, kH);
    REQUIRE(a.execute(f.ctx, &scene.inputs, nullptr) == SSAO_OK);
    const ssao_settings settings_before = current_settings(f);
    for (int delta : {-2, 4, -1000}) {
        CAPTURE(delta);
        auto bad = [delta](uint32_t size) { return static_cast<uint32_t>(static_cast<int>(size) + delta); };

        ssao_settings s = sized<ssao_settings>();
        s.radius = 3.0f;
        s.size = bad(sizeof s);
        CHECK(a.set_settings(f.ctx, &s) == SSAO_ERROR_STRUCT_SIZE);
        CHECK_FALSE(f.last_error().empty());
        CHECK(same_bytes(current_settings(f), settings_before));

        ssao_inputs in = scene.inputs;
        in.size = bad(sizeof in);
        ssao_output out = sentinel<ssao_output>();
        ssao_output out_before = out;
        CHECK(a.execute(f.ctx, &in, &out) == SSAO_ERROR_STRUCT_SIZE);
        CHECK(same_bytes(out, out_before));
        CHECK(contains(f.last_error(), "size"));

        out = sentinel<ssao_output>();
        out.size = bad(sizeof out);
        out_before = out;
        CHECK(a.execute(f.ctx, &scene.inputs, &out) == SSAO_ERROR_STRUCT_SIZE);
        CHECK(same_bytes(out, out_before));
        CHECK(contains(f.last_error(), "size"));

        ssao_timings t = sentinel<ssao_timings>();
        t.size = bad(sizeof t);
        const ssao_timings t_before = t;
        CHECK(a.get_timings(f.ctx, &t) == SSAO_ERROR_STRUCT_SIZE);
        CHECK(same_bytes(t, t_before));
        CHECK_FALSE(f.last_error().empty());
    }
}

TEST_CASE("abi: a 1.1-sized ssao_inputs is accepted and its missing 1.2 fields read as today's behaviour") {
    // A host compiled against interface 1.1 hands 172 bytes: what follows in
    // its memory must not be read, and the AO equals the full struct's with
    // the 1.2 fields zero. The crease scene, so that a frame index read from
    // past the struct would show in the noise.
    GlFixture f;
    const ssao_api& a = api();
    GladGLContext& gl = f.gl();
    const auto proj = analytic::perspective(testscenes::kFov, 1.0, 0.1, 100.0);
    const analytic::GBuffer g =
        analytic::render(testscenes::crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH);
    GLuint tex[2] = {};
    gl.GenTextures(2, tex);
    gl.BindTexture(GL_TEXTURE_2D, tex[0]);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, kW, kH, 0, GL_DEPTH_COMPONENT, GL_FLOAT, g.depth.data());
    gl.BindTexture(GL_TEXTURE_2D, tex[1]);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, kW, kH, 0, GL_RGB, GL_FLOAT, g.normal.data());
    gl.BindTexture(GL_TEXTURE_2D, 0);
    ssao_inputs inputs = make_inputs(tex[0], tex[1]);
    const glm::mat4 projf(proj);
    std::memcpy(inputs.projection, glm::value_ptr(projf), sizeof inputs.projection);
    ssao_output out = sized<ssao_output>();
    REQUIRE(a.execute(f.ctx, &inputs, &out) == SSAO_OK);
    const std::vector<float> full = read_red(gl, out.texture, kW, kH);
    REQUIRE(*std::min_element(full.begin(), full.end()) < 0.9f);  // occlusion, so noise would show
    ssao_inputs old = inputs;
    std::memset(reinterpret_cast<unsigned char*>(&old) + SSAO_INPUTS_SIZE_1_1, 0xab, sizeof old - SSAO_INPUTS_SIZE_1_1);
    old.size = SSAO_INPUTS_SIZE_1_1;
    REQUIRE(a.execute(f.ctx, &old, &out) == SSAO_OK);
    CHECK(read_red(gl, out.texture, kW, kH) == full);
    // Past the struct a valid output mode and a frame index: still ignored.
    old.output_mode = SSAO_OUTPUT_MODE_OVERWRITE;
    old.frame_index = 7;
    REQUIRE(a.execute(f.ctx, &old, &out) == SSAO_OK);
    CHECK(read_red(gl, out.texture, kW, kH) == full);
    // The frame index read as a 1.2 struct does change the AO: the check above can fail.
    old.size = sizeof old;
    old.sample_index = 0;
    REQUIRE(a.execute(f.ctx, &old, &out) == SSAO_OK);
    CHECK(read_red(gl, out.texture, kW, kH) != full);
    std::memset(reinterpret_cast<unsigned char*>(&old) + SSAO_INPUTS_SIZE_1_1, 0xab, sizeof old - SSAO_INPUTS_SIZE_1_1);
    // The same garbage read as a 1.2 struct is refused: the tail is not ignored there.
    old.size = sizeof old;
    CHECK(a.execute(f.ctx, &old, &out) == SSAO_ERROR_INVALID_ENUM);
}

TEST_CASE("abi: get_settings and get_frame_info failures are reported in last_error and the log") {
    // The contract: "when a context is given, last_error(ctx) holds a sentence
    // on the most recent failure of that context", and the log "receives
    // every error message too".
    GlFixture f;
    const ssao_api& a = api();
    Scene scene(f.gl(), kW, kH);
    REQUIRE(a.execute(f.ctx, &scene.inputs, nullptr) == SSAO_OK);  // clears last_error
    size_t logged = f.log.entries.size();
    CHECK(a.get_settings(f.ctx, nullptr) == SSAO_ERROR_NULL_POINTER);
    CHECK_FALSE(f.last_error().empty());
    CHECK(f.log.entries.size() == ++logged);

    REQUIRE(a.execute(f.ctx, &scene.inputs, nullptr) == SSAO_OK);
    CHECK(a.get_frame_info(f.ctx, nullptr) == SSAO_ERROR_NULL_POINTER);
    CHECK_FALSE(f.last_error().empty());
    CHECK(f.log.entries.size() == ++logged);

    REQUIRE(a.execute(f.ctx, &scene.inputs, nullptr) == SSAO_OK);

    ssao_settings s = sentinel<ssao_settings>();
    s.size = sizeof s - 2;
    const ssao_settings s_before = s;
    CHECK(a.get_settings(f.ctx, &s) == SSAO_ERROR_STRUCT_SIZE);
    CHECK(same_bytes(s, s_before));
    CHECK_FALSE(f.last_error().empty());
    CHECK(f.log.entries.size() == ++logged);

    REQUIRE(a.execute(f.ctx, &scene.inputs, nullptr) == SSAO_OK);
    ssao_frame_info fi = sentinel<ssao_frame_info>();
    fi.size = sizeof fi + 4;
    const ssao_frame_info fi_before = fi;
    CHECK(a.get_frame_info(f.ctx, &fi) == SSAO_ERROR_STRUCT_SIZE);
    CHECK(same_bytes(fi, fi_before));
    CHECK_FALSE(f.last_error().empty());
    CHECK(f.log.entries.size() == ++logged);
}

TEST_CASE("abi: execute rejects missing or foreign or wrong-target textures") {
    GlFixture f;
    GladGLContext& gl = f.gl();
    Scene scene(gl, kW, kH);
    ssao_inputs in = scene.inputs;

    in.depth_texture = 0;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "depth_texture");
    // (1.2) normal_texture = 0 is no longer refused: it asks for normals
    // rebuilt from depth (tests/hard_cases/test_hc_normals_view.cpp).
    in = scene.inputs;
    in.depth_texture = 12345;  // not a texture name
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "depth_texture");
    in = scene.inputs;
    in.normal_texture = 12345;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "normal_texture");

    // A GL_TEXTURE_3D (GL 4.5 can tell the target).
    GLuint tex3d = 0;
    gl.GenTextures(1, &tex3d);
    gl.BindTexture(GL_TEXTURE_3D, tex3d);
    gl.TexImage3D(GL_TEXTURE_3D, 0, GL_R32F, kW, kH, 1, 0, GL_RED, GL_FLOAT, nullptr);
    gl.BindTexture(GL_TEXTURE_3D, 0);
    in = scene.inputs;
    in.depth_texture = tex3d;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "depth_texture");
    in = scene.inputs;
    in.normal_texture = tex3d;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "normal_texture");
    // A 2D array texture of the right size.
    GLuint array = 0;
    gl.GenTextures(1, &array);
    gl.BindTexture(GL_TEXTURE_2D_ARRAY, array);
    gl.TexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_DEPTH_COMPONENT32F, kW, kH, 1);
    gl.BindTexture(GL_TEXTURE_2D_ARRAY, 0);
    in = scene.inputs;
    in.depth_texture = array;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "depth_texture");

    // A normal texture of another size.
    const GLuint small_normal = make_normals(gl, kW, kH / 2);
    in = scene.inputs;
    in.normal_texture = small_normal;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "normal_texture");
    const GLuint wide_normal = make_normals(gl, kW + 1, kH);
    in.normal_texture = wide_normal;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "normal_texture");

    // Output texture: not a texture, too small, not colour-renderable.
    in = scene.inputs;
    in.output_texture = 12345;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "output_texture");
    in.output_texture = make_color(gl, kW - 1, kH);
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_SIZE, "output_texture");
    in.output_texture = make_depth(gl, kW, kH, 0.5f);
    expect_execute_fails(f, in, SSAO_ERROR_UNSUPPORTED_FORMAT, "output_texture");
    // Integer outputs are complete colour attachments but would get float
    // bit patterns (accepted before).
    for (GLenum internal : {GL_R32UI, GL_RGBA8UI, GL_R16I}) {
        CAPTURE(internal);
        in.output_texture = make_color(gl, kW, kH, internal);
        expect_execute_fails(f, in, SSAO_ERROR_UNSUPPORTED_FORMAT, "integer");
    }

    // A buffer texture: refused without a GL error, even where GL 4.5 can
    // query targets (its target query raised GL_INVALID_OPERATION before).
    GLuint buffer = 0, buffer_texture = 0;
    gl.GenBuffers(1, &buffer);
    gl.BindBuffer(GL_TEXTURE_BUFFER, buffer);
    gl.BufferData(GL_TEXTURE_BUFFER, 1024, nullptr, GL_STATIC_DRAW);
    gl.BindBuffer(GL_TEXTURE_BUFFER, 0);
    gl.GenTextures(1, &buffer_texture);
    gl.BindTexture(GL_TEXTURE_BUFFER, buffer_texture);
    gl.TexBuffer(GL_TEXTURE_BUFFER, GL_R32F, buffer);
    gl.BindTexture(GL_TEXTURE_BUFFER, 0);
    in = scene.inputs;
    in.depth_texture = buffer_texture;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "depth_texture");
    in = scene.inputs;
    in.output_texture = buffer_texture;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_TEXTURE, "output_texture");
    gl.DeleteTextures(1, &buffer_texture);
    gl.DeleteBuffers(1, &buffer);
}

TEST_CASE("abi: execute rejects a colour texture as depth (UNSUPPORTED_FORMAT) and accepts every depth format") {
    GlFixture f;
    GladGLContext& gl = f.gl();
    Scene scene(gl, kW, kH);
    for (GLenum internal : {GLenum(GL_RGBA8), GLenum(GL_R32F), GLenum(GL_RGBA16F)}) {
        CAPTURE(internal);
        ssao_inputs in = scene.inputs;
        in.depth_texture = make_color(gl, kW, kH, internal);
        expect_execute_fails(f, in, SSAO_ERROR_UNSUPPORTED_FORMAT, "depth_texture");
    }
    // The documented depth formats are accepted.
    for (GLenum internal : {GLenum(GL_DEPTH_COMPONENT16), GLenum(GL_DEPTH_COMPONENT24), GLenum(GL_DEPTH_COMPONENT32F),
                            GLenum(GL_DEPTH24_STENCIL8), GLenum(GL_DEPTH32F_STENCIL8)}) {
        CAPTURE(internal);
        ssao_inputs in = scene.inputs;
        GLuint depth = 0;
        gl.GenTextures(1, &depth);
        gl.BindTexture(GL_TEXTURE_2D, depth);
        gl.TexStorage2D(GL_TEXTURE_2D, 1, internal, kW, kH);
        gl.BindTexture(GL_TEXTURE_2D, 0);
        const bool stencil = internal == GL_DEPTH24_STENCIL8 || internal == GL_DEPTH32F_STENCIL8;
        // The host reads stencil from it: execute must read depth and put the mode back.
        if (stencil) gl.TextureParameteri(depth, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
        in.depth_texture = depth;
        ssao_output out = sized<ssao_output>();
        CHECK(api().execute(f.ctx, &in, &out) == SSAO_OK);
        if (stencil) {
            GLint mode = 0;
            gl.GetTextureParameteriv(depth, GL_DEPTH_STENCIL_TEXTURE_MODE, &mode);
            CHECK(mode == GL_STENCIL_INDEX);
        }
        ssao_frame_info fi = sized<ssao_frame_info>();
        REQUIRE(api().get_frame_info(f.ctx, &fi) == SSAO_OK);
        const uint32_t bits = internal == GL_DEPTH_COMPONENT16 ? 16u
                              : (internal == GL_DEPTH_COMPONENT24 || internal == GL_DEPTH24_STENCIL8) ? 24u
                                                                                                     : 32u;
        CHECK(fi.depth_bits == bits);
    }
}

TEST_CASE("abi: execute rejects bad viewports (INVALID_SIZE)") {
    GlFixture f;
    Scene scene(f.gl(), kW, kH);
    const int32_t bad[][4] = {
        {0, 0, 0, kH},      {0, 0, kW, 0},        {0, 1, 0, 0},       {0, 0, -4, kH},        {0, 0, kW, -1},
        {0, 0, 20000, kH},  {0, 0, kW, 16385},    {0, 0, 16385, 16385}, {0, 0, kW + 1, kH},  {0, 0, kW, kH + 1},
        {8, 8, 9, 8},       {-1, 0, 8, 8},        {0, -1, 8, 8},      {kW, 0, 1, 1},         {0, kH, 1, 1},
        {0x7fffffff, 0, 16, 16}, {4, 4, 0x7fffffff, 4},
    };
    for (const auto& v : bad) {
        CAPTURE(v[0]);
        CAPTURE(v[1]);
        CAPTURE(v[2]);
        CAPTURE(v[3]);
        ssao_inputs in = scene.inputs;
        std::memcpy(in.viewport, v, sizeof in.viewport);
        expect_execute_fails(f, in, SSAO_ERROR_INVALID_SIZE, "viewport");
    }
    // A viewport inside the textures is fine.
    ssao_inputs in = scene.inputs;
    const int32_t ok[4] = {3, 2, 9, 7};
    std::memcpy(in.viewport, ok, sizeof ok);
    CHECK(api().execute(f.ctx, &in, nullptr) == SSAO_OK);
}

TEST_CASE("abi: execute rejects bad projections and view matrices and enums") {
    GlFixture f;
    Scene scene(f.gl(), kW, kH);
    for (int i : {0, 5, 10, 11, 14, 15}) {
        CAPTURE(i);
        ssao_inputs in = scene.inputs;
        in.projection[i] = kNaN;
        expect_execute_fails(f, in, SSAO_ERROR_INVALID_VALUE, "projection");
        in.projection[i] = -kInf;
        expect_execute_fails(f, in, SSAO_ERROR_INVALID_VALUE, "projection");
    }
    ssao_inputs in = scene.inputs;
    std::memset(in.projection, 0, sizeof in.projection);
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_PROJECTION, "projection");
    in = scene.inputs;
    const glm::mat4 lh = glm::perspectiveLH(glm::radians(60.0f), 1.0f, 1.0f, 100.0f);
    std::memcpy(in.projection, glm::value_ptr(lh), sizeof in.projection);
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_PROJECTION, "projection");
    in = scene.inputs;
    in.projection[14] = 0.0f;  // singular: no depth offset
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_PROJECTION, "projection");
    // Invertible in double but useless in the shaders' floats (OK and all 1.0 before).
    in = scene.inputs;
    in.projection[0] = in.projection[5] = 1e-40f;  // denormal diagonal
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_PROJECTION, "32-bit float");
    in = scene.inputs;
    in.projection[0] = in.projection[5] = 3e38f;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_PROJECTION, "32-bit float");

    // World-space normals read view_matrix, which must be finite.
    in = scene.inputs;
    in.normal_space = SSAO_NORMAL_SPACE_WORLD;
    in.view_matrix[5] = kNaN;
    expect_execute_fails(f, in, SSAO_ERROR_INVALID_VALUE, "view_matrix");

    for (int32_t raw : {3, -1, 1000}) {
        CAPTURE(raw);
        in = scene.inputs;
        set_raw(in.normal_space, raw);
        expect_execute_fails(f, in, SSAO_ERROR_INVALID_ENUM, "normal_space");
        in = scene.inputs;
        set_raw(in.normal_packing, raw);
        expect_execute_fails(f, in, SSAO_ERROR_INVALID_ENUM, "normal_packing");
        in = scene.inputs;
        set_raw(in.clip_range, raw);
        expect_execute_fails(f, in, SSAO_ERROR_INVALID_ENUM, "clip_range");
    }
}

TEST_CASE("abi: set_settings with invalid values changes nothing") {
    GlFixture f;
    const ssao_api& a = api();
    ssao_settings custom = sized<ssao_settings>();
    custom.sample_count = 24;
    custom.radius = 1.25f;
    custom.blur = SSAO_BLUR_GAUSSIAN;
    set_settings_ok(f, custom);
    const ssao_settings before = current_settings(f);
    CHECK(before.sample_count == 24u);
    CHECK(before.radius == 1.25f);

    struct Bad {
        const char* what;
        ssao_status expected;
        const char* keyword;
        void (*edit)(ssao_settings&);
    };
    const Bad bad[] = {
        {"radius NaN", SSAO_ERROR_INVALID_VALUE, "radius", [](ssao_settings& s) { s.radius = kNaN; }},
        {"radius -1", SSAO_ERROR_INVALID_VALUE, "radius", [](ssao_settings& s) { s.radius = -1.0f; }},
        {"blur 7", SSAO_ERROR_INVALID_ENUM, "blur", [](ssao_settings& s) { set_raw(s.blur, 7); }},
        {"blur -1", SSAO_ERROR_INVALID_ENUM, "blur", [](ssao_settings& s) { set_raw(s.blur, -1); }},
        {"sample_count 65", SSAO_ERROR_INVALID_VALUE, "sample_count", [](ssao_settings& s) { s.sample_count = 65; }},
        {"strength inf", SSAO_ERROR_INVALID_VALUE, "strength", [](ssao_settings& s) { s.strength = kInf; }},
        {"output_format 9", SSAO_ERROR_INVALID_ENUM, "output_format",
         [](ssao_settings& s) { set_raw(s.output_format, 9); }},
    };
    for (const Bad& b : bad) {
        const std::string what_ = b.what;
        CAPTURE(what_);
        ssao_settings s = sized<ssao_settings>();
        s.sample_count = 8;  // a valid change that must not apply either
        b.edit(s);
        const size_t logged = f.log.entries.size();
        CHECK(a.set_settings(f.ctx, &s) == b.expected);
        CHECK(same_bytes(current_settings(f), before));
        const std::string error = f.last_error();
        CAPTURE(error);
        CHECK(contains(error, b.keyword));
        REQUIRE(f.log.entries.size() == logged + 1);
        CHECK(f.log.entries.back().message == error);
    }
    // get_settings returns resolved values, never a zero that means default.
    set_settings_ok(f, sized<ssao_settings>());
    ssao_settings resolved = sentinel<ssao_settings>();
    ssao_settings zero = sized<ssao_settings>();
    REQUIRE(a.resolve_settings(&zero, &resolved) == SSAO_OK);
    CHECK(same_bytes(current_settings(f), resolved));
}

TEST_CASE("abi: create_context with initial settings uses them") {
    ssao_settings s = sized<ssao_settings>();
    s.sample_count = 40;
    s.strength = SSAO_STRENGTH_OFF;
    GlFixture f(&s);
    const ssao_settings got = current_settings(f);
    CHECK(got.sample_count == 40u);
    CHECK(got.strength == SSAO_STRENGTH_OFF);
    CHECK(got.radius == 0.5f);
}

TEST_CASE("abi: a valid execute runs the passes the settings call for") {
    GlFixture f;
    const ssao_api& a = api();
    GladGLContext& gl = f.gl();
    Scene scene(gl, kW, kH);

    struct Expect {
        const char* what;
        ssao_settings settings;
        uint32_t passes;
    };
    ssao_settings off = sized<ssao_settings>();
    off.strength = SSAO_STRENGTH_OFF;
    ssao_settings off_no_blur = off;
    off_no_blur.blur = SSAO_BLUR_NONE;
    ssao_settings half_no_blur = with_blur(SSAO_BLUR_NONE);
    half_no_blur.resolution = SSAO_RESOLUTION_HALF;
    ssao_settings kernel_no_blur = with_blur(SSAO_BLUR_NONE);
    kernel_no_blur.method = SSAO_METHOD_KERNEL;
    // The visibility march (the default method) reads the grid at full
    // resolution too; the kernel there reads the host's textures.
    const Expect expect[] = {
        {"half resolution, no blur", half_no_blur, SSAO_PASS_GRID | SSAO_PASS_OCCLUSION | SSAO_PASS_UPSAMPLE},
        {"depth-aware", with_blur(SSAO_BLUR_DEPTH_AWARE),
         SSAO_PASS_GRID | SSAO_PASS_OCCLUSION | SSAO_PASS_BLUR_X | SSAO_PASS_BLUR_Y},
        {"gaussian", with_blur(SSAO_BLUR_GAUSSIAN), SSAO_PASS_GRID | SSAO_PASS_OCCLUSION | SSAO_PASS_BLUR_X | SSAO_PASS_BLUR_Y},
        {"box 4x4", with_blur(SSAO_BLUR_BOX_4X4), SSAO_PASS_GRID | SSAO_PASS_OCCLUSION | SSAO_PASS_BLUR_X},
        {"no blur", with_blur(SSAO_BLUR_NONE), SSAO_PASS_GRID | SSAO_PASS_OCCLUSION},
        {"kernel, no blur", kernel_no_blur, SSAO_PASS_OCCLUSION},
        {"strength off", off, SSAO_PASS_CLEAR},
        {"strength off, no blur", off_no_blur, SSAO_PASS_CLEAR},
    };
    for (const Expect& e : expect) {
        const std::string what_ = e.what;
        CAPTURE(what_);
        set_settings_ok(f, e.settings);
        ssao_output out = sentinel<ssao_output>();
        REQUIRE(a.execute(f.ctx, &scene.inputs, &out) == SSAO_OK);
        CHECK(out.size == sizeof(ssao_output));
        CHECK(out.passes_run == e.passes);
        CHECK(out.texture != 0u);
        CHECK(out.texture != scene.depth);
        CHECK(out.texture != scene.normal);
        CHECK(out.origin[0] == 0);
        CHECK(out.origin[1] == 0);
        CHECK(gl.IsTexture(out.texture) == GL_TRUE);
        const std::vector<float> ao = read_red(gl, out.texture, kW, kH);
        float lo = 2.0f, hi = -1.0f;
        for (float v : ao) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        CAPTURE(lo);
        CAPTURE(hi);
        if (e.passes == SSAO_PASS_CLEAR) {
            CHECK(lo == 1.0f);  // strength 0: exactly 1 everywhere
            CHECK(hi == 1.0f);
        } else {
            // A flat wall facing the camera is not occluded by a hemisphere kernel.
            CHECK(lo > 0.9f);
            CHECK(hi <= 1.0f);
        }
    }
    // The frame info describes the inputs of the last execute.
    ssao_frame_info fi = sentinel<ssao_frame_info>();
    REQUIRE(a.get_frame_info(f.ctx, &fi) == SSAO_OK);
    CHECK(fi.size == sizeof(ssao_frame_info));
    CHECK(fi.orthographic == 0u);
    CHECK(fi.reverse_z == 0u);
    CHECK(fi.infinite_far == 0u);
    CHECK(fi.depth_bits == 32u);
    CHECK(fi.near_distance == doctest::Approx(1.0).epsilon(1e-4));
    CHECK(fi.far_distance == doctest::Approx(100.0).epsilon(1e-3));
}

TEST_CASE("abi: a host output texture is written at the viewport only and returned") {
    GlFixture f;
    const ssao_api& a = api();
    GladGLContext& gl = f.gl();
    constexpr int kSize = 32;
    Scene scene(gl, kSize, kSize);
    const int32_t viewport[4] = {4, 6, 16, 12};
    ssao_settings off = sized<ssao_settings>();
    off.strength = SSAO_STRENGTH_OFF;
    for (const ssao_settings& s : {with_blur(SSAO_BLUR_DEPTH_AWARE), off}) {
        set_settings_ok(f, s);
        // A host R8 texture filled with 0.25 everywhere.
        const GLuint host_out = make_color(gl, kSize, kSize, GL_R8);
        const std::vector<unsigned char> quarter(kSize * kSize, 64);
        gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gl.TextureSubImage2D(host_out, 0, 0, 0, kSize, kSize, GL_RED, GL_UNSIGNED_BYTE, quarter.data());
        ssao_inputs in = scene.inputs;
        in.output_texture = host_out;
        std::memcpy(in.viewport, viewport, sizeof viewport);
        ssao_output out = sentinel<ssao_output>();
        REQUIRE(a.execute(f.ctx, &in, &out) == SSAO_OK);
        CHECK(out.texture == host_out);
        CHECK(out.origin[0] == 4);
        CHECK(out.origin[1] == 6);
        CHECK(out.passes_run == (s.strength == SSAO_STRENGTH_OFF
                                     ? uint32_t(SSAO_PASS_CLEAR)
                                     : uint32_t(SSAO_PASS_GRID | SSAO_PASS_OCCLUSION | SSAO_PASS_BLUR_X | SSAO_PASS_BLUR_Y)));
        const std::vector<float> px = read_red(gl, host_out, kSize, kSize);
        int outside_changed = 0, inside_low = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const float v = px[static_cast<size_t>(y) * kSize + x];
                const bool inside = x >= 4 && x < 4 + 16 && y >= 6 && y < 6 + 12;
                if (inside)
                    inside_low += v < 0.9f;  // a flat wall: AO ~ 1 (exactly 1 when off)
                else
                    outside_changed += std::abs(v - 64.0f / 255.0f) > 1e-3f;
            }
        CHECK(outside_changed == 0);
        CHECK(inside_low == 0);
    }
}

TEST_CASE("abi: the plugin-owned output follows the viewport size and does not leak") {
    GlFixture f;
    const ssao_api& a = api();
    GladGLContext& gl = f.gl();
    Scene scene(gl, 48, 40);

    // Runs execute with viewport {x, y, w, h}; (w, h) = (0, 0) with x = y = 0
    // means the whole 48x40 texture.
    auto run = [&](int x, int y, int w, int h) {
        ssao_inputs in = scene.inputs;
        const int32_t v[4] = {x, y, w, h};
        std::memcpy(in.viewport, v, sizeof v);
        ssao_output out = sized<ssao_output>();
        REQUIRE(a.execute(f.ctx, &in, &out) == SSAO_OK);
        CHECK(out.origin[0] == 0);  // texel (0,0) = viewport pixel (x,y)
        CHECK(out.origin[1] == 0);
        GLint tw = 0, th = 0, format = 0;
        level0(gl, out.texture, tw, th, format);
        CHECK(tw == (w == 0 ? 48 : w));
        CHECK(th == (h == 0 ? 40 : h));
        return std::make_pair(out.texture, format);
    };

    const auto first = run(0, 0, 16, 16);
    CHECK(first.second == GL_R8);  // the default output format
    const auto second = run(0, 0, 32, 24);
    CHECK(second.first == first.first);
    const LiveObjects live = count_live(gl);

    const int sizes[][4] = {{0, 0, 48, 40}, {0, 0, 8, 5}, {3, 2, 1, 1}, {1, 1, 47, 39}, {5, 7, 32, 24}, {0, 0, 0, 0}};
    for (int round = 0; round < 10; ++round)
        for (const auto& v : sizes) {
            CAPTURE(round);
            CAPTURE(v[2]);
            CAPTURE(v[3]);
            CHECK(run(v[0], v[1], v[2], v[3]).first == first.first);
        }
    const LiveObjects after = count_live(gl);
    CHECK(after.textures == live.textures);
    CHECK(after.buffers == live.buffers);
    CHECK(after.framebuffers == live.framebuffers);

    // Switching the output format re-specifies the texture (R16F) at the viewport size.
    ssao_settings s = sized<ssao_settings>();
    s.output_format = SSAO_OUTPUT_R16F;
    set_settings_ok(f, s);
    const auto r16 = run(0, 0, 20, 10);
    CHECK(r16.second == GL_R16F);
    s.output_format = SSAO_OUTPUT_R8;
    set_settings_ok(f, s);
    const auto r8 = run(0, 0, 20, 10);
    CHECK(r8.second == GL_R8);
    CHECK(count_live(gl).textures == live.textures);
}

TEST_CASE("abi: destroy_context deletes every GL object the plugin made") {
    auto egl = make_egl();
    GladGLContext& gl = egl->gl();
    const ssao_api& a = api();
    Scene scene(gl, kW, kH);
    const LiveObjects before = count_live(gl);

    ssao_context* ctx = nullptr;
    REQUIRE(testgl::create_default_context(a, &ctx) == SSAO_OK);
    // Exercise every lazily made object: blur temporaries, output, timers.
    for (int i = 0; i < 6; ++i) REQUIRE(a.execute(ctx, &scene.inputs, nullptr) == SSAO_OK);
    ssao_timings t = sized<ssao_timings>();
    REQUIRE(a.get_timings(ctx, &t) == SSAO_OK);
    const LiveObjects during = count_live(gl);
    CHECK(during.textures > before.textures);  // the check below can fail
    CHECK(during.programs > before.programs);
    REQUIRE(a.destroy_context(ctx) == SSAO_OK);

    const LiveObjects after = count_live(gl);
    CHECK(after.textures == before.textures);
    CHECK(after.buffers == before.buffers);
    CHECK(after.framebuffers == before.framebuffers);
    CHECK(after.vertex_arrays == before.vertex_arrays);
    CHECK(after.samplers == before.samplers);
    CHECK(after.programs == before.programs);
    CHECK(after.queries == before.queries);
    // The host's textures are untouched.
    CHECK(gl.IsTexture(scene.depth) == GL_TRUE);
    CHECK(gl.IsTexture(scene.normal) == GL_TRUE);
}

TEST_CASE("abi: create_context with the host's program flagged for deletion keeps it current, without a GL error") {
    // Before: create_context made its programs current to set their
    // samplers, then restored the host's name, already deleted by then
    // (GL_INVALID_VALUE), leaving its own program current.
    GlFixture f;  // fails the test on any GL error
    GladGLContext& gl = f.gl();
    const GLuint host = testgl::make_host_program(gl);
    gl.UseProgram(host);
    gl.DeleteProgram(host);  // flagged: lives while current
    ssao_context* second = nullptr;
    REQUIRE(testgl::create_default_context(api(), &second) == SSAO_OK);
    GLint current = 0;
    gl.GetIntegerv(GL_CURRENT_PROGRAM, &current);
    CHECK(static_cast<GLuint>(current) == host);  // GL 4.5: set through glProgramUniform, never unbound
    GLint flagged = 0;
    gl.GetProgramiv(host, GL_DELETE_STATUS, &flagged);
    CHECK(flagged == GL_TRUE);
    // The new context works: its samplers point at the right units.
    Scene scene(gl, kW, kH);
    ssao_output out = sized<ssao_output>();
    CHECK(api().execute(second, &scene.inputs, &out) == SSAO_OK);
    CHECK(api().destroy_context(second) == SSAO_OK);
}

// Runs this test program as a child whose loader hands back NULL for `name`
// (test_abi_main.cpp child_missing_function: create_context's status where
// it fails, else 0 when one execute succeeded) and checks that it exits with
// `code`, not by a crash.
namespace {
void check_child_without(const char* name, int code) {
    const std::string what_ = name;
    CAPTURE(what_);
    const testgl::ChildResult child = testgl::run_self("unit_abi", {"--unit-child-missing", name});
    CAPTURE(child.code);
    CHECK_FALSE(child.crashed);
    CHECK(child.code == code);
}
}  // namespace

TEST_CASE("abi: create_context is GL_LOAD when one GL 3.3 function is missing") {
    // Each run is a fresh process (a NULL function pointer called by the
    // plugin would crash it); the child exits with create_context's status.
    const char* names[] = {"glCreateShader",     // checked by the plugin: the harness's control case
                           "glGenSamplers",      "glSamplerParameteri", "glGenVertexArrays",
                           "glUniformBlockBinding", "glDrawArrays",     "glBindBufferBase",
                           "glCheckFramebufferStatus", "glClearBufferfv", "glDeleteTextures",
                           "glDrawBuffers"};
    for (const char* name : names) check_child_without(name, SSAO_ERROR_GL_LOAD);
}

TEST_CASE("abi: a loader without an optional GL function gets a context that executes without it") {
    // Functions beyond GL 3.3 that the plugin uses where they are there (a
    // GL 4.5 context whose loader hands back NULL for one must not crash):
    // the child creates a context, executes once and exits 0.
    const char* names[] = {"glGetTextureLevelParameteriv", "glGetTextureParameteriv", "glClipControl",
                           "glBlendFuncSeparatei",         "glBlendEquationSeparatei", "glGetFloati_v",
                           "glViewportIndexedfv",          "glScissorIndexedv",       "glQueryCounter",
                           "glGetQueryObjectui64v",        "glPushDebugGroup",        "glObjectLabel",
                           "glGetObjectLabel",             "glProgramUniform1i"};
    for (const char* name : names) check_child_without(name, 0);
}

TEST_CASE("abi: frame info reports what execute read from the projection") {
    GlFixture f;
    const ssao_api& a = api();
    Scene scene(f.gl(), kW, kH);
    struct Case {
        const char* what;
        glm::mat4 m;
        ssao_clip_range clip;
        uint32_t ortho, reverse, infinite;
        float near_d, far_d;
    };
    glm::mat4 rev_inf(0.0f);
    const float g = 1.0f / std::tan(glm::radians(60.0f) * 0.5f);
    rev_inf[0][0] = g;
    rev_inf[1][1] = g;
    rev_inf[2][3] = -1.0f;
    rev_inf[3][2] = 0.05f;
    const Case cases[] = {
        {"perspective", glm::perspective(glm::radians(60.0f), 1.0f, 0.5f, 200.0f), SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 0, 0,
         0, 0.5f, 200.0f},
        {"reverse-Z infinite", rev_inf, SSAO_CLIP_ZERO_TO_ONE, 0, 1, 1, 0.05f, kInf},
        {"infinite", glm::infinitePerspective(glm::radians(60.0f), 1.0f, 0.25f), SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 0, 0, 1,
         0.25f, kInf},
        {"ortho", glm::ortho(-5.0f, 5.0f, -5.0f, 5.0f, 1.0f, 30.0f), SSAO_CLIP_NEGATIVE_ONE_TO_ONE, 1, 0, 0, 1.0f,
         30.0f},
        {"ortho ZO reverse", glm::orthoRH_ZO(-5.0f, 5.0f, -5.0f, 5.0f, 30.0f, 1.0f), SSAO_CLIP_ZERO_TO_ONE, 1, 1, 0,
         1.0f, 30.0f},
    };
    for (const Case& c : cases) {
        const std::string what_ = c.what;
        CAPTURE(what_);
        ssao_inputs in = scene.inputs;
        std::memcpy(in.projection, glm::value_ptr(c.m), sizeof in.projection);
        in.clip_range = c.clip;
        REQUIRE(a.execute(f.ctx, &in, nullptr) == SSAO_OK);
        ssao_frame_info fi = sentinel<ssao_frame_info>();
        REQUIRE(a.get_frame_info(f.ctx, &fi) == SSAO_OK);
        CHECK(fi.orthographic == c.ortho);
        CHECK(fi.reverse_z == c.reverse);
        CHECK(fi.infinite_far == c.infinite);
        CHECK(fi.near_distance == doctest::Approx(c.near_d).epsilon(1e-4));
        if (c.infinite) {
            CHECK(std::isinf(fi.far_distance));
            CHECK(fi.far_distance > 0.0f);
        } else {
            CHECK(fi.far_distance == doctest::Approx(c.far_d).epsilon(1e-3));
        }
    }
}

TEST_CASE("abi: a sphere kernel sees a flat wall as half occluded") {
    // ssao.h: "full sphere, normals only rotate it (Crytek look: flat = 0.5)".
    GlFixture f;
    GladGLContext& gl = f.gl();
    Scene scene(gl, kW, kH);
    ssao_settings s = sized<ssao_settings>();
    s.method = SSAO_METHOD_KERNEL;  // kernel shapes belong to the kernel method
    s.kernel_shape = SSAO_KERNEL_SPHERE;
    s.sample_count = 64;
    s.distribution = SSAO_DISTRIBUTION_UNIFORM;
    set_settings_ok(f, s);
    ssao_output out = sized<ssao_output>();
    REQUIRE(api().execute(f.ctx, &scene.inputs, &out) == SSAO_OK);
    const std::vector<float> ao = read_red(gl, out.texture, kW, kH);
    double mean = 0.0;
    for (float v : ao) mean += v;
    mean /= static_cast<double>(ao.size());
    CHECK(mean > 0.35);
    CHECK(mean < 0.65);
}

TEST_CASE("abi: get_timings has nothing before the first execute and a measured frame later") {
    GlFixture f;
    const ssao_api& a = api();
    GladGLContext& gl = f.gl();
    Scene scene(gl, kW, kH);
    ssao_timings t = sentinel<ssao_timings>();
    REQUIRE(a.get_timings(f.ctx, &t) == SSAO_OK);
    CHECK(t.size == sizeof(ssao_timings));
    CHECK(t.available == 0u);
    bool measured = false;
    for (int frame = 1; frame <= 8 && !measured; ++frame) {
        REQUIRE(a.execute(f.ctx, &scene.inputs, nullptr) == SSAO_OK);
        gl.Finish();
        t = sentinel<ssao_timings>();
        REQUIRE(a.get_timings(f.ctx, &t) == SSAO_OK);
        measured = t.available == 1u;
    }
    REQUIRE(measured);
    CHECK(t.frame >= 1u);
    CHECK(t.frame <= 8u);
    CHECK(t.ao_ms >= 0.0);
    CHECK(t.blur_ms >= 0.0);
    CHECK(t.total_ms >= t.ao_ms);
    CHECK(t.total_ms == doctest::Approx(t.ao_ms + t.blur_ms).epsilon(1e-6));
    CHECK(t.total_ms < 10000.0);
}

namespace {

// Executes with `s` until get_timings (full size) reports a frame measured
// with these settings. `executes` counts the fixture's successful executes,
// which is how the library numbers frames (ssao_timings.frame).
ssao_timings measured_timings(GlFixture& f, const Scene& scene, const ssao_settings& s, uint64_t& executes) {
    set_settings_ok(f, s);
    const uint64_t first = executes + 1;
    for (int i = 0; i < 24; ++i) {
        REQUIRE(api().execute(f.ctx, &scene.inputs, nullptr) == SSAO_OK);
        ++executes;
        f.gl().Finish();
        ssao_timings t = sentinel<ssao_timings>();
        REQUIRE(api().get_timings(f.ctx, &t) == SSAO_OK);
        if (t.available == 1u && t.frame >= first) return t;
    }
    FAIL("no frame was measured");
    return sized<ssao_timings>();
}

}  // namespace

TEST_CASE("abi: get_timings reports one GPU time per pass, in the order the passes ran") {
    GlFixture f;
    Scene scene(f.gl(), 64, 64);
    ssao_settings box = with_blur(SSAO_BLUR_BOX_4X4), off = sized<ssao_settings>();
    off.strength = SSAO_STRENGTH_OFF;
    struct Expect {
        const char* what;
        ssao_settings settings;
        std::vector<uint32_t> kinds;
    };
    const Expect expect[] = {
        {"depth-aware", with_blur(SSAO_BLUR_DEPTH_AWARE),
         {SSAO_PASS_GRID, SSAO_PASS_OCCLUSION, SSAO_PASS_BLUR_X, SSAO_PASS_BLUR_Y}},
        {"box", box, {SSAO_PASS_GRID, SSAO_PASS_OCCLUSION, SSAO_PASS_BLUR_X}},
        {"no blur", with_blur(SSAO_BLUR_NONE), {SSAO_PASS_GRID, SSAO_PASS_OCCLUSION}},
        {"strength off", off, {SSAO_PASS_CLEAR}},
    };
    uint64_t executes = 0;
    for (const Expect& e : expect) {
        const std::string what_ = e.what;
        CAPTURE(what_);
        const ssao_timings t = measured_timings(f, scene, e.settings, executes);
        CHECK(t.size == sizeof(ssao_timings));
        REQUIRE(t.pass_count == e.kinds.size());
        double sum = 0.0, blur = 0.0;
        for (uint32_t i = 0; i < SSAO_MAX_PASSES; ++i) {
            CAPTURE(i);
            if (i < t.pass_count) {
                CHECK(t.pass_kind[i] == e.kinds[i]);
                CHECK(t.pass_ms[i] >= 0.0);
                sum += t.pass_ms[i];
                if (t.pass_kind[i] == SSAO_PASS_BLUR_X || t.pass_kind[i] == SSAO_PASS_BLUR_Y) blur += t.pass_ms[i];
            } else {
                CHECK(t.pass_kind[i] == 0u);  // zero beyond pass_count, not stale values of a longer plan
                CHECK(t.pass_ms[i] == 0.0);
            }
        }
        CHECK(t.reserved == 0u);
        // The stamps are shared: the passes add up to the whole, and the two
        // summary figures are the blur passes and the rest.
        CHECK(sum == doctest::Approx(t.total_ms).epsilon(1e-9));
        CHECK(t.blur_ms == doctest::Approx(blur).epsilon(1e-9));
        CHECK(t.ao_ms == doctest::Approx(t.total_ms - blur).epsilon(1e-9));
    }
}

TEST_CASE("abi: get_timings accepts the 1.0 size (fills the prefix only) and the 1.1 size, nothing else") {
    GlFixture f;
    Scene scene(f.gl(), kW, kH);
    uint64_t executes = 0;
    const ssao_timings full = measured_timings(f, scene, with_blur(SSAO_BLUR_DEPTH_AWARE), executes);
    REQUIRE(full.available == 1u);
    REQUIRE(full.pass_count == 4u);  // grid, visibility, blur x, blur y

    // A host compiled against the 1.0 header: 40 bytes, ending at total_ms.
    constexpr uint32_t kSize10 = 40;
    ssao_timings old = sentinel<ssao_timings>();
    old.size = kSize10;
    const ssao_timings old_before = old;
    REQUIRE(api().get_timings(f.ctx, &old) == SSAO_OK);
    CHECK(old.size == kSize10);  // left as the caller set it
    CHECK(old.available == 1u);
    CHECK(old.frame == full.frame);  // no execute in between: the same frame
    CHECK(old.ao_ms == full.ao_ms);
    CHECK(old.blur_ms == full.blur_ms);
    CHECK(old.total_ms == full.total_ms);
    // Nothing past the 1.0 struct is written (it is not the host's memory).
    CHECK(std::memcmp(reinterpret_cast<const char*>(&old) + kSize10,
                      reinterpret_cast<const char*>(&old_before) + kSize10, sizeof old - kSize10) == 0);

    for (uint32_t size : {0u, 39u, 41u, 44u, 48u, static_cast<uint32_t>(sizeof(ssao_timings) - 8),
                          static_cast<uint32_t>(sizeof(ssao_timings) + 8)}) {
        CAPTURE(size);
        ssao_timings t = sentinel<ssao_timings>();
        t.size = size;
        const ssao_timings before = t;
        CHECK(api().get_timings(f.ctx, &t) == SSAO_ERROR_STRUCT_SIZE);
        CHECK(same_bytes(t, before));
        CHECK(contains(f.last_error(), "ssao_timings"));
    }
}
