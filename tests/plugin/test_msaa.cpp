// MSAA inputs: GL_TEXTURE_2D_MULTISAMPLE depth and
// normal, one sample (inputs.sample_index) read per pixel.
//
// The exact oracle: multisampled copies whose every sample holds the
// single-sample G-buffer (tests/support/msaa_copy.h) must give the AO of that
// G-buffer bit for bit, for both estimators and every resolution, since the
// grid pass copies the picked sample's depth bit for bit and decodes its
// normal exactly as the single-sample path does. A rasterised 4x MSAA scene
// against its single-sample render is the last test case.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "gbuffer.h"
#include "gl_fixture.h"
#include "gl_state_snapshot.h"
#include "msaa_copy.h"
#include "test_scenes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using analytic::GBuffer;
using testscenes::crease_scene;
using testscenes::kFov;

namespace {

constexpr int kW = 40, kH = 32;

glm::dmat4 projection() { return analytic::perspective(kFov, double(kW) / kH, 0.1, 100.0); }

// A second scene, different from the crease at every pixel: a floor seen from lower down.
analytic::Scene floor_scene() {
    analytic::Scene s;
    const glm::dmat4 view = glm::rotate(glm::dmat4(1.0), 0.3, glm::dvec3(1, 0, 0)) *
                            glm::translate(glm::dmat4(1.0), glm::dvec3(0, -1, 0));
    s.add_quad(glm::dvec3(view * glm::dvec4(-50, 0, 50, 1)), glm::dvec3(view * glm::dvec4(100, 0, 0, 0)),
               glm::dvec3(view * glm::dvec4(0, 0, -100, 0)));
    s.add_quad(glm::dvec3(view * glm::dvec4(-0.5, 0, -4, 1)), glm::dvec3(view * glm::dvec4(1, 0, 0, 0)),
               glm::dvec3(view * glm::dvec4(0, 1, 0, 0)));  // a fin standing on it
    return s;
}

ssao_settings settings_for(ssao_method method, ssao_resolution resolution) {
    ssao_settings s = testscenes::make(16, SSAO_BLUR_DEPTH_AWARE);
    s.method = method;
    s.resolution = resolution;
    s.radius = 1.5f;
    s.output_format = SSAO_OUTPUT_R16F;
    return s;
}

// The crease and the floor scene, each alone and together in 4x textures
// whose samples 0 and 2 hold the crease, 1 and 3 the floor.
struct TwoScenes {
    glm::dmat4 proj = projection();
    msaa::Textures alone[2], ms;
    explicit TwoScenes(testgl::Fixture& fx) {
        alone[0] = fx.upload(analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH));
        alone[1] = fx.upload(analytic::render(floor_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH));
        ms = msaa::make(fx.gl(), {alone[0], alone[1]}, kW, kH, 4, GL_DEPTH_COMPONENT32F, GL_RGBA16F);
    }
};

struct Run {
    ssao_status status = SSAO_OK;
    std::vector<float> ao;
    std::string error;
    ssao_output out{};
};

Run execute(testgl::Fixture& fx, const ssao_inputs& in) {
    Run r;
    r.out.size = sizeof r.out;
    r.status = fx.api().execute(fx.ctx(), &in, &r.out);
    r.error = fx.api().last_error(fx.ctx());
    if (r.status == SSAO_OK) r.ao = fx.read_red(r.out.texture, kW, kH);
    return r;
}

}  // namespace

TEST_CASE("4x MSAA inputs whose samples equal the single-sample G-buffer give its AO bit for bit") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = projection();
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH);
    for (GLenum depth_format : {GLenum(GL_DEPTH_COMPONENT32F), GLenum(GL_DEPTH24_STENCIL8), GLenum(GL_DEPTH_COMPONENT16)}) {
        CAPTURE(depth_format);
        const msaa::Textures single = fx.upload(g, depth_format);
        const msaa::Textures ms = msaa::make(gl, {single}, kW, kH, 4, depth_format, GL_RGBA16F);
        for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY})
            for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER}) {
                CAPTURE(method);
                CAPTURE(res);
                fx.settings(settings_for(method, res));
                const Run ref = execute(fx, fx.inputs(single.depth, single.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE));
                REQUIRE(ref.status == SSAO_OK);
                for (uint32_t sample = 0; sample < 4; sample += 3) {
                    ssao_inputs in = fx.inputs(ms.depth, ms.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
                    in.sample_index = sample;
                    const Run got = execute(fx, in);
                    REQUIRE(got.status == SSAO_OK);
                    // The grid pass runs for multisampled inputs even at full resolution.
                    CHECK((got.out.passes_run & SSAO_PASS_DOWNSAMPLE) != 0);
                    int differ = 0;
                    for (size_t i = 0; i < ref.ao.size(); ++i) differ += got.ao[i] != ref.ao[i];
                    if (depth_format != GL_DEPTH24_STENCIL8) {
                        CHECK(differ == 0);
                    } else {
                        // The copy writes a D24 depth back through float (gl_FragDepth),
                        // which llvmpipe may round to the neighbouring D24 step: a
                        // handful of pixels then differ by one R16F step of AO (7 at
                        // quarter resolution, where the grid's noise is not the 4x4 tile).
                        double worst = 0;
                        for (size_t i = 0; i < ref.ao.size(); ++i)
                            worst = std::max(worst, std::abs(double(got.ao[i]) - ref.ao[i]));
                        CHECK(differ <= 8);
                        CHECK(worst <= 1.0 / 1024);
                    }
                }
            }
        gl.DeleteTextures(1, &ms.depth);
        gl.DeleteTextures(1, &ms.normal);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("4x MSAA depth without a normal texture: each sample_index gives its own scene's depth-only AO bit for bit") {
    // Features 1 and 2 together: the grid pass rebuilds each normal from the
    // chosen sample of its neighbours. Samples 0 and 2 hold the crease, 1 and
    // 3 the floor, so a neighbour read from another sample would show.
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const TwoScenes two(fx);
    const glm::dmat4& proj = two.proj;
    const msaa::Textures &ta = two.alone[0], &tb = two.alone[1], &ms = two.ms;
    for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY})
        for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF}) {
            CAPTURE(method);
            CAPTURE(res);
            fx.settings(settings_for(method, res));
            const Run ref_a = execute(fx, fx.inputs(ta.depth, 0, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE));
            const Run ref_b = execute(fx, fx.inputs(tb.depth, 0, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE));
            REQUIRE(ref_a.status == SSAO_OK);
            REQUIRE(ref_b.status == SSAO_OK);
            REQUIRE(ref_a.ao != ref_b.ao);
            for (uint32_t sample = 0; sample < 4; ++sample) {
                CAPTURE(sample);
                ssao_inputs in = fx.inputs(ms.depth, 0, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
                in.sample_index = sample;
                const Run got = execute(fx, in);
                REQUIRE(got.status == SSAO_OK);
                CHECK(got.ao == (sample % 2 == 0 ? ref_a.ao : ref_b.ao));
            }
        }
    for (const msaa::Textures& t : {ms, ta, tb}) {
        gl.DeleteTextures(1, &t.depth);
        gl.DeleteTextures(1, &t.normal);
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("sample_index picks the sample: samples holding two different scenes give each scene's AO") {
    testgl::Fixture fx;
    const TwoScenes two(fx);
    const glm::dmat4& proj = two.proj;
    const msaa::Textures &ta = two.alone[0], &tb = two.alone[1], &ms = two.ms;
    for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF}) {
        CAPTURE(res);
        fx.settings(settings_for(SSAO_METHOD_VISIBILITY, res));
        const Run ref_a = execute(fx, fx.inputs(ta.depth, ta.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE));
        const Run ref_b = execute(fx, fx.inputs(tb.depth, tb.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE));
        REQUIRE(ref_a.status == SSAO_OK);
        REQUIRE(ref_b.status == SSAO_OK);
        int scenes_differ = 0;
        for (size_t i = 0; i < ref_a.ao.size(); ++i) scenes_differ += ref_a.ao[i] != ref_b.ao[i];
        REQUIRE(scenes_differ > static_cast<int>(ref_a.ao.size()) / 4);  // the oracle tells the samples apart
        for (uint32_t sample = 0; sample < 4; ++sample) {
            CAPTURE(sample);
            ssao_inputs in = fx.inputs(ms.depth, ms.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
            in.sample_index = sample;
            const Run got = execute(fx, in);
            REQUIRE(got.status == SSAO_OK);
            const std::vector<float>& want = sample % 2 == 0 ? ref_a.ao : ref_b.ao;
            int differ = 0;
            for (size_t i = 0; i < want.size(); ++i) differ += got.ao[i] != want[i];
            CHECK(differ == 0);
        }
    }
    CHECK(fx.gl_errors().empty());
}

TEST_CASE("MSAA inputs: mixed targets and mismatched sample counts and sample_index out of range and an MS output are refused") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = projection();
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH);
    const msaa::Textures single = fx.upload(g);
    const msaa::Textures ms4 = msaa::make(gl, {single}, kW, kH, 4, GL_DEPTH_COMPONENT32F, GL_RGBA16F);
    // The driver may round a sample count up (llvmpipe: 2 -> 4): the counts are read back.
    const msaa::Textures ms2 = msaa::make(gl, {single}, kW, kH, 2, GL_DEPTH_COMPONENT32F, GL_RGBA16F);
    auto samples_of = [&](GLuint t) {
        GLint n = 0;
        gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, t);
        gl.GetTexLevelParameteriv(GL_TEXTURE_2D_MULTISAMPLE, 0, GL_TEXTURE_SAMPLES, &n);
        gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
        return static_cast<uint32_t>(n);
    };
    const uint32_t n4 = samples_of(ms4.depth), n2 = samples_of(ms2.depth);
    MESSAGE("sample counts: asked 4 got ", n4, ", asked 2 got ", n2);
    fx.settings(settings_for(SSAO_METHOD_VISIBILITY, SSAO_RESOLUTION_FULL));
    const Run good = execute(fx, fx.inputs(ms4.depth, ms4.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE));
    REQUIRE(good.status == SSAO_OK);
    const testgl::Snapshot before = testgl::snapshot(gl);

    struct Case {
        const char* what;
        GLuint depth, normal;
        uint32_t sample_index;
        ssao_status want;
        const char* says;
    };
    const Case cases[] = {
        {"MS depth, 2D normal", ms4.depth, single.normal, 0, SSAO_ERROR_INVALID_TEXTURE, "both must be multisampled"},
        {"2D depth, MS normal", single.depth, ms4.normal, 0, SSAO_ERROR_INVALID_TEXTURE, "both must be multisampled"},
        {"depth and normal of different sample counts", ms4.depth, ms2.normal, 0, SSAO_ERROR_INVALID_TEXTURE, "samples"},
        {"sample_index = the sample count", ms4.depth, ms4.normal, n4, SSAO_ERROR_INVALID_VALUE, "sample_index"},
        {"sample_index far out", ms2.depth, ms2.normal, 1000, SSAO_ERROR_INVALID_VALUE, "sample_index"},
    };
    for (const Case& c : cases) {
        if (c.depth == ms4.depth && c.normal == ms2.normal && n4 == n2) {
            MESSAGE("the driver made both textures ", n4, "-sampled: the mismatched-count case is not testable here");
            continue;
        }
        CAPTURE(std::string(c.what));
        ssao_inputs in = fx.inputs(c.depth, c.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        in.sample_index = c.sample_index;
        const Run r = execute(fx, in);
        CHECK(r.status == c.want);
        CAPTURE(r.error);
        CHECK(r.error.find(c.says) != std::string::npos);
    }
    // A multisampled output texture: the output must be a GL_TEXTURE_2D.
    GLuint ms_out = 0;
    gl.GenTextures(1, &ms_out);
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, ms_out);
    gl.TexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, kW, kH, GL_TRUE);
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    const testgl::Snapshot before_out = testgl::snapshot(gl);
    ssao_inputs in = fx.inputs(ms4.depth, ms4.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    in.output_texture = ms_out;
    const Run r = execute(fx, in);
    CHECK(r.status == SSAO_ERROR_INVALID_TEXTURE);
    CHECK(r.error.find("GL_TEXTURE_2D_MULTISAMPLE") != std::string::npos);
    const testgl::Snapshot after = testgl::snapshot(gl);
    for (const auto& entry : before_out) {
        CAPTURE(entry.first);
        CHECK(after.at(entry.first) == entry.second);
    }
    (void)before;
    // The library's own output still holds the last good frame's AO.
    const auto kept = fx.read_red(good.out.texture, kW, kH);
    CHECK(kept == good.ao);
    CHECK(fx.gl_errors().empty());  // GL 4.5: targets are queried, no failed bind
}

TEST_CASE("with MSAA inputs the multisample bindings of units 0..3 and every listed state are restored") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const auto proj = projection();
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH);
    const msaa::Textures single = fx.upload(g, GL_DEPTH24_STENCIL8);
    const msaa::Textures ms = msaa::make(gl, {single}, kW, kH, 4, GL_DEPTH24_STENCIL8, GL_RGBA16F);
    // The host's own textures on both targets of every unit the library uses.
    GLuint host2d[4] = {}, host_ms[4] = {};
    gl.GenTextures(4, host2d);
    gl.GenTextures(4, host_ms);
    for (int u = 0; u < 4; ++u) {
        gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(u));
        gl.BindTexture(GL_TEXTURE_2D, host2d[u]);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
        gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, host_ms[u]);
        gl.TexImage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 2, GL_RGBA8, 4, 4, GL_TRUE);
    }
    gl.ActiveTexture(GL_TEXTURE2);
    // The depth-stencil mode of the D24S8 input: the host reads stencil.
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, ms.depth);
    gl.TexParameteri(GL_TEXTURE_2D_MULTISAMPLE, GL_DEPTH_STENCIL_TEXTURE_MODE, GL_STENCIL_INDEX);
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, host_ms[2]);
    for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF}) {
        CAPTURE(res);
        fx.settings(settings_for(SSAO_METHOD_KERNEL, res));
        const testgl::Snapshot before = testgl::snapshot(gl);
        ssao_inputs in = fx.inputs(ms.depth, ms.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
        in.sample_index = 1;
        ssao_output out{};
        out.size = sizeof out;
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        CHECK(testgl::changed_state(before, testgl::snapshot(gl)) == "");
        GLint mode = 0;
        gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, ms.depth);
        gl.GetTexParameteriv(GL_TEXTURE_2D_MULTISAMPLE, GL_DEPTH_STENCIL_TEXTURE_MODE, &mode);
        CHECK(mode == GL_STENCIL_INDEX);
        gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, host_ms[2]);
    }
    CHECK(fx.gl_errors().empty());
}

namespace {

// A floor with a box standing on it, flat-shaded (each face its own vertices).
scene::Mesh box_on_floor() {
    scene::Mesh m;
    auto quad = [&](glm::vec3 o, glm::vec3 u, glm::vec3 v) {
        const glm::vec3 n = glm::normalize(glm::cross(u, v));
        const uint32_t b = static_cast<uint32_t>(m.positions.size());
        for (glm::vec3 p : {o, o + u, o + u + v, o + v}) {
            m.positions.push_back(p);
            m.normals.push_back(n);
        }
        for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(b + i);
    };
    quad({-20, 0, 20}, {40, 0, 0}, {0, 0, -40});       // floor, +y
    quad({-0.5f, 0, 0.5f}, {1, 0, 0}, {0, 1, 0});       // front, +z
    quad({0.5f, 0, -0.5f}, {-1, 0, 0}, {0, 1, 0});      // back, -z
    quad({0.5f, 0, 0.5f}, {0, 0, -1}, {0, 1, 0});       // right, +x
    quad({-0.5f, 0, -0.5f}, {0, 0, 1}, {0, 1, 0});      // left, -x
    quad({-0.5f, 1, 0.5f}, {1, 0, 0}, {0, 0, -1});      // top, +y
    return m;
}

}  // namespace

// A rasterised 4x MSAA G-buffer against the single-sample render of the same
// scene. Sample 0 is not at the pixel centre (llvmpipe's 4x pattern puts it
// at (0.375, 0.125) of the pixel), while the library reconstructs each
// pixel's position at the centre: on a plane the depths of sample 0 are the
// plane's depths shifted by a constant sub-pixel offset, which is still a
// plane (depth is affine in screen space on a plane), so away from edges the
// AO only sees a slightly moved plane. No exact compensation is possible
// without the sample positions (the ABI does not take them), so the test
// bounds the difference: tight where the pixel and its neighbours see one
// face, looser where sample 0 may see another face than the centre.
TEST_CASE("a rasterised 4x MSAA G-buffer gives the AO of the single-sample render (tolerance stated)") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    const int w = 64, h = 64;
    const glm::mat4 view = glm::lookAt(glm::vec3(2.2f, 1.8f, 2.8f), glm::vec3(0, 0.3f, 0), glm::vec3(0, 1, 0));
    const glm::mat4 proj = glm::perspective(1.0471976f, 1.0f, 0.1f, 50.0f);
    const scene::Mesh mesh = box_on_floor();
    gbuffer::Desc desc;
    desc.width = w;
    desc.height = h;
    gbuffer::GBuffer single(gl, desc, mesh);
    single.render(view, proj);
    desc.samples = 4;
    gbuffer::GBuffer multi(gl, desc, mesh);
    multi.render(view, proj);
    const std::vector<float> normals = [&] {
        std::vector<float> px(size_t(w) * h * 4);
        gl.BindTexture(GL_TEXTURE_2D, single.normal_texture());
        gl.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, px.data());
        gl.BindTexture(GL_TEXTURE_2D, 0);
        return px;
    }();
    // Interior: the pixel and its 8 neighbours show the same face (equal normals).
    auto interior = [&](int x, int y) {
        if (x < 1 || y < 1 || x >= w - 1 || y >= h - 1) return false;
        const float* c = &normals[(size_t(y) * w + x) * 4];
        if (c[0] == 0 && c[1] == 0 && c[2] == 0) return false;  // sky
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                const float* n = &normals[(size_t(y + dy) * w + (x + dx)) * 4];
                if (n[0] != c[0] || n[1] != c[1] || n[2] != c[2]) return false;
            }
        return true;
    };
    for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY}) {
        CAPTURE(method);
        ssao_settings s = settings_for(method, SSAO_RESOLUTION_FULL);
        s.blur = SSAO_BLUR_NONE;
        s.radius = 0.5f;
        fx.settings(s);
        ssao_inputs in{};
        in.size = sizeof in;
        in.normal_space = SSAO_NORMAL_SPACE_VIEW;
        in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
        std::copy_n(glm::value_ptr(proj), 16, in.projection);
        in.depth_texture = single.depth_texture();
        in.normal_texture = single.normal_texture();
        ssao_output out{};
        out.size = sizeof out;
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        const auto want = fx.read_red(out.texture, w, h);
        in.depth_texture = multi.depth_texture();
        in.normal_texture = multi.normal_texture();
        REQUIRE(fx.api().execute(fx.ctx(), &in, &out) == SSAO_OK);
        const auto got = fx.read_red(out.texture, w, h);
        double interior_worst = 0, interior_sum = 0, edge_sum = 0, edge_worst = 0;
        int interior_count = 0, edge_count = 0, interior_off = 0;
        float lo = 1.0f;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const size_t i = size_t(y) * w + x;
                const double d = std::abs(double(got[i]) - want[i]);
                lo = std::min(lo, want[i]);
                if (interior(x, y)) {
                    interior_worst = std::max(interior_worst, d);
                    interior_sum += d;
                    ++interior_count;
                    interior_off += d > 0.07;
                } else {
                    edge_worst = std::max(edge_worst, d);
                    edge_sum += d;
                    ++edge_count;
                }
            }
        MESSAGE("interior ", interior_count, " px: worst ", interior_worst, " mean ", interior_sum / interior_count,
                " over 0.07: ", interior_off, "; edges ", edge_count, " px: worst ", edge_worst, " mean ",
                edge_sum / std::max(edge_count, 1));
        REQUIRE(interior_count > w * h / 2);
        CHECK(lo < 0.7f);  // the box occludes the floor
        // Interior: a single kernel sample or direction may flip near its
        // threshold (1/16 of AO per sample here), so the bound is on the mean
        // and on how many pixels move by more than one such step.
        CHECK(interior_sum / interior_count <= 0.005);
        CHECK(interior_off <= interior_count / 50);
        CHECK(interior_worst <= 0.3);
        // Edges: sample 0 may see another face than the centre.
        CHECK(edge_sum / std::max(edge_count, 1) <= 0.02);
    }
    CHECK(fx.gl_errors().empty());
}


namespace {

// A driver whose multisampled textures may differ in sample count (llvmpipe
// makes every one 4-sampled): glGetTexLevelParameteriv reports 2 samples for
// the texture named g_two_samples when it is bound.
PFNGLGETTEXLEVELPARAMETERIVPROC g_get_level_parameter = nullptr;
PFNGLGETINTEGERVPROC g_get_integer = nullptr;
GLuint g_two_samples = 0;

void GLAD_API_PTR two_sample_get_level_parameter(GLenum target, GLint level, GLenum pname, GLint* params) {
    g_get_level_parameter(target, level, pname, params);
    GLint bound = 0;
    g_get_integer(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &bound);
    if (target == GL_TEXTURE_2D_MULTISAMPLE && pname == GL_TEXTURE_SAMPLES && GLuint(bound) == g_two_samples)
        *params = 2;
}

ssao_gl_proc SSAO_CALL two_sample_get_proc(void* user, const char* name) {
    if (std::string(name) == "glGetTexLevelParameteriv")
        return reinterpret_cast<ssao_gl_proc>(&two_sample_get_level_parameter);
    return eglctx::Context::get_proc(user, name);
}

}  // namespace

TEST_CASE("MSAA inputs of different sample counts are refused, naming both counts") {
    testgl::Fixture fx;
    auto& gl = fx.gl();
    g_get_level_parameter = gl.GetTexLevelParameteriv;
    g_get_integer = gl.GetIntegerv;
    const auto proj = projection();
    const GBuffer g = analytic::render(crease_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, kW, kH);
    const msaa::Textures single = fx.upload(g);
    const msaa::Textures ms = msaa::make(gl, {single}, kW, kH, 4, GL_DEPTH_COMPONENT32F, GL_RGBA16F);
    const msaa::Textures other = msaa::make(gl, {single}, kW, kH, 4, GL_DEPTH_COMPONENT32F, GL_RGBA16F);
    g_two_samples = other.normal;
    ssao_context_desc desc{};
    desc.size = sizeof desc;
    desc.get_proc_address = &two_sample_get_proc;
    ssao_context* ctx = nullptr;
    REQUIRE(fx.api().create_context(&desc, &ctx) == SSAO_OK);
    ssao_inputs in = fx.inputs(ms.depth, ms.normal, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
    CHECK(fx.api().execute(ctx, &in, nullptr) == SSAO_OK);  // the same count: taken
    in.normal_texture = other.normal;
    CHECK(fx.api().execute(ctx, &in, nullptr) == SSAO_ERROR_INVALID_TEXTURE);
    const std::string why = fx.api().last_error(ctx);
    CHECK(why.find("inputs.normal_texture has 2 samples but the depth texture has 4") != std::string::npos);
    fx.api().destroy_context(ctx);
    CHECK(fx.gl_errors().empty());
}
