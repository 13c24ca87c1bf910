// The hard cases with MSAA inputs: every depth
// convention and format, odd sizes with the viewport inside larger textures,
// sky, world-space unorm normals, for both estimators at full and half
// resolution. The G-buffer is copied into 4x multisampled textures whose every
// sample holds it (tests/support/msaa_copy.h), so the oracle is exact: the AO
// of the single-sample inputs, bit for bit (D24: see the tolerance below), which the other hard-case files
// check against their own oracles. Each output is also checked finite and in
// [0,1].
#include <doctest/doctest.h>

#include "hc_util.h"
#include "msaa_copy.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

// A floor (finite: sky beyond it) and a wall meeting it, seen from above and in front.
analytic::Scene crease_with_sky() {
    analytic::Scene s;
    const glm::dmat4 view = glm::rotate(glm::dmat4(1.0), 0.35, glm::dvec3(1, 0, 0)) *
                            glm::translate(glm::dmat4(1.0), glm::dvec3(0.3, -1.5, 0));
    auto add = [&](glm::dvec3 o, glm::dvec3 u, glm::dvec3 v) {
        s.add_quad(glm::dvec3(view * glm::dvec4(o, 1.0)), glm::dvec3(view * glm::dvec4(u, 0.0)),
                   glm::dvec3(view * glm::dvec4(v, 0.0)));
    };
    add({-3, 0, 2}, {6, 0, 0}, {0, 0, -7});   // floor
    add({-3, 0, -5}, {6, 0, 0}, {0, 1.2, 0});  // a low wall at its far end
    return s;
}

struct Convention {
    const char* name;
    glm::dmat4 proj;
    ssao_clip_range clip;
    GLenum depth_format;
    GLenum normal_format;
    int w, h, pad_x, pad_y;
};

// Single-sample and 4x textures of the same G-buffer, embedded at (pad_x, pad_y)
// in textures 5 texels larger each way (filled with a depth and a normal that
// would show if anything outside the viewport were read).
struct Inputs {
    msaa::Textures single, multi;
    int tw = 0, th = 0;
};

Inputs make_inputs(testgl::Fixture& fx, const analytic::GBuffer& g, const Convention& c) {
    Inputs t;
    t.tw = c.w + c.pad_x + 5;
    t.th = c.h + c.pad_y + 5;
    t.single = hc::inset_textures(fx, g, c.pad_x, c.pad_y, t.tw, t.th, c.depth_format, c.normal_format);
    t.multi = msaa::make(fx.gl(), {t.single}, t.tw, t.th, 4, c.depth_format, c.normal_format);
    return t;
}

std::vector<float> run(testgl::Fixture& fx, const Convention& c, GLuint depth, GLuint normal, uint32_t sample) {
    ssao_inputs in = fx.inputs(depth, normal, c.proj, c.clip);
    in.normal_packing = testgl::packing_of(c.normal_format);
    testgl::set_viewport(in, c.pad_x, c.pad_y, c.w, c.h);
    in.sample_index = sample;
    ssao_output out{};
    out.size = sizeof out;
    const ssao_status st = fx.api().execute(fx.ctx(), &in, &out);
    CAPTURE(fx.api().last_error(fx.ctx()));
    REQUIRE(st == SSAO_OK);
    return fx.read_red(out.texture, c.w, c.h);
}

}  // namespace

TEST_CASE("hard cases with 4x MSAA inputs: every convention gives the single-sample AO bit for bit") {
    HC_EACH_METHOD(method);
    testgl::Fixture fx;
    const double a = 48.0 / 36.0;
    const Convention conventions[] = {
        {"perspective [-1,1] D32F", analytic::perspective(hc::kFov, a, 0.1, 100.0), SSAO_CLIP_NEGATIVE_ONE_TO_ONE,
         GL_DEPTH_COMPONENT32F, GL_RGBA16F, 48, 36, 0, 0},
        {"reverse-Z [0,1] D32F", analytic::reverse_z(hc::kFov, a, 0.1, 100.0), SSAO_CLIP_ZERO_TO_ONE,
         GL_DEPTH_COMPONENT32F, GL_RGBA16F, 48, 36, 0, 0},
        {"reverse-Z infinite far", analytic::reverse_z_infinite(hc::kFov, a, 0.1), SSAO_CLIP_ZERO_TO_ONE,
         GL_DEPTH_COMPONENT32F, GL_RGBA16F, 48, 36, 0, 0},
        {"infinite far [-1,1] D24S8", analytic::infinite(hc::kFov, a, 0.1), SSAO_CLIP_NEGATIVE_ONE_TO_ONE,
         GL_DEPTH24_STENCIL8, GL_RGBA16F, 48, 36, 0, 0},
        {"orthographic D16", analytic::orthographic(3.0 * a, 3.0, 0.1, 20.0), SSAO_CLIP_NEGATIVE_ONE_TO_ONE,
         GL_DEPTH_COMPONENT16, GL_RGBA16F, 48, 36, 0, 0},
        {"D32FS8, RGBA8 normals, odd 37x23 viewport inside larger textures",
         analytic::perspective(hc::kFov, 37.0 / 23.0, 0.1, 100.0), SSAO_CLIP_NEGATIVE_ONE_TO_ONE,
         GL_DEPTH32F_STENCIL8, GL_RGBA8, 37, 23, 3, 2},
        {"off-centre frustum, D24", hc::frustum(-0.05, 0.09, -0.04, 0.06, 0.1, 50.0), SSAO_CLIP_NEGATIVE_ONE_TO_ONE,
         GL_DEPTH_COMPONENT24, GL_RGBA16F, 41, 29, 1, 4},
    };
    const analytic::Scene scene = crease_with_sky();
    for (const Convention& c : conventions) {
        CAPTURE(std::string(c.name));
        const analytic::GBuffer g = analytic::render(scene, c.proj, c.clip, c.w, c.h);
        const Inputs t = make_inputs(fx, g, c);
        for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF}) {
            CAPTURE(res);
            ssao_settings s = hc::make(12, SSAO_BLUR_DEPTH_AWARE, SSAO_ROTATION_DEFAULT, 0.6f, method);
            s.resolution = res;
            fx.settings(s);
            const std::vector<float> want = run(fx, c, t.single.depth, t.single.normal, 0);
            CHECK(hc::check_unit_finite(want, c.name) == 0);
            const std::vector<float> got = run(fx, c, t.multi.depth, t.multi.normal, 3);
            int differ = 0;
            double worst = 0.0;
            for (size_t i = 0; i < want.size(); ++i) {
                differ += got[i] != want[i];
                worst = std::max(worst, std::abs(double(got[i]) - want[i]));
            }
            if (c.depth_format == GL_DEPTH_COMPONENT24 || c.depth_format == GL_DEPTH24_STENCIL8) {
                // The copy writes a D24 depth back through float (gl_FragDepth),
                // which llvmpipe may round to the neighbouring D24 step: a
                // handful of pixels may then differ by about one R16F step.
                CHECK(differ <= 4);
                CHECK(worst <= 1.0 / 512);
            } else {
                CHECK(differ == 0);
            }
        }
        fx.gl().DeleteTextures(1, &t.multi.depth);
        fx.gl().DeleteTextures(1, &t.multi.normal);
    }
    CHECK(fx.gl_errors().empty());
}
