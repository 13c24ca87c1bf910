// The sky skipped by a depth test (docs/api.md "Skipping the sky"): a pass
// that skipped a pixel it should have shaded would leave the sky's value
// (1) there. On a scene whose geometry borders the sky everywhere, placed at
// an offset inside larger textures and written into the host's output at
// that offset (the copy of the host's depth is taken from the viewport's
// rectangle and tested at the output's), every convention and depth format
// and every resolution give the AO of the same G-buffer alone, in overwrite
// and in multiply mode, and nothing outside the viewport is written. Both
// plans run: a software rasteriser's, which copies the host's depth to test
// the output, and a GPU's, which does not (plugin/renderer.h; the context
// here is told a GPU's GL_RENDERER).
#include <doctest/doctest.h>

#include "conventions.h"
#include "hc_util.h"
#include "test_scenes.h"

#include <cmath>
#include <initializer_list>
#include <string>

using analytic::GBuffer;

namespace {

constexpr float kSentinel = 0.5f;  // the host's output before execute: never AO's value next to the sky

// The host's output read back, and how far its viewport rectangle is from
// `want` (viewport-sized, scaled by `scale`); texels outside it must keep the sentinel.
struct Compared {
    float worst = 0.0f;
    int outside_written = 0;
    int geometry_dark = 0;  // geometry pixels the G-buffer alone gives AO < 0.98
};

Compared compare_inset(testgl::Fixture& fx, GLuint out, int tw, int th, int ox, int oy, const GBuffer& g,
                       const std::vector<float>& want, float scale) {
    const std::vector<float> all = fx.read_red(out, tw, th);
    Compared c;
    for (int y = 0; y < th; ++y)
        for (int x = 0; x < tw; ++x) {
            const float v = all[hc::at(x, y, tw)];
            const int vx = x - ox, vy = y - oy;
            if (vx < 0 || vy < 0 || vx >= g.width || vy >= g.height) {
                c.outside_written += v != kSentinel;
                continue;
            }
            const float w = want[hc::at(vx, vy, g.width)];
            c.worst = std::max(c.worst, std::abs(v - scale * w));
            c.geometry_dark += !g.sky(vx, vy) && w < 0.98f;
        }
    return c;
}

}  // namespace

TEST_CASE("sky test: an inset viewport written into the host's output at its offset gives the AO of the G-buffer "
          "alone, in every convention and depth format, overwrite and multiply, a GPU's plan and llvmpipe's") {
  for (const testgl::RendererKind& kind : testgl::kRendererKinds) {
    const std::string renderer = kind.gl_renderer;
    CAPTURE(renderer);
    testgl::Fixture fx;
    fx.recreate_context_as(kind.gl_renderer);
    GladGLContext& gl = fx.gl();
    const int W = 48, H = 40, ox = 5, oy = 3, TW = W + 9, TH = H + 7;
    const auto cases = hc::perspective_conventions(double(W) / H, 0.1, 100.0,
                                                   {"GL [-1,1] D16", "GL [-1,1] D24", "GL [-1,1] D24S8", "[0,1] D32F",
                                                    "reverse-Z [0,1] D32FS8", "reverse-Z infinite D32F"}) +
                       hc::ortho_conventions(4.0, 3.3, 0.1, 50.0, {"ortho reverse [0,1] D32F"});
    for (const hc::Convention& c : cases) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer g = analytic::render(hc::sky_scene(), c.proj, c.clip, W, H);
        const testgl::Textures inset = hc::inset_textures(fx, g, ox, oy, TW, TH, c.format);
        int dark = 0;  // occluded geometry pixels over the convention's runs
        for (ssao_method method : {SSAO_METHOD_KERNEL, SSAO_METHOD_VISIBILITY})
            for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER})
                for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE}) {
                    CAPTURE(method);
                    CAPTURE(res);
                    CAPTURE(blur);
                    ssao_settings s = hc::make(8, blur, SSAO_ROTATION_HASH, 0.8f, method);
                    s.resolution = res;
                    fx.settings(s);
                    hc::RunOptions alone_options;
                    alone_options.depth_format = c.format;
                    const hc::Out alone = hc::run(fx, g, c.proj, c.clip, alone_options);
                    REQUIRE(alone.status == SSAO_OK);
                    for (ssao_output_mode mode : {SSAO_OUTPUT_MODE_OVERWRITE, SSAO_OUTPUT_MODE_MULTIPLY}) {
                        CAPTURE(mode);
                        const GLuint out = hc::sentinel_texture(gl, TW, TH, kSentinel);
                        ssao_inputs in = fx.inputs(inset.depth, inset.normal, c.proj, c.clip);
                        testgl::set_viewport(in, ox, oy, W, H);
                        in.output_texture = out;
                        in.output_mode = mode;
                        ssao_output o{};
                        o.size = sizeof o;
                        REQUIRE(fx.api().execute(fx.ctx(), &in, &o) == SSAO_OK);
                        const float scale = mode == SSAO_OUTPUT_MODE_MULTIPLY ? kSentinel : 1.0f;
                        const Compared d = compare_inset(fx, out, TW, TH, ox, oy, g, alone.ao, scale);
                        // The library's own output is R16F, the host's R32F: one half-float step apart at most.
                        CHECK(d.worst <= 1e-3f);
                        CHECK(d.outside_written == 0);
                        dark += d.geometry_dark;
                        gl.DeleteTextures(1, &out);
                    }
                }
        // The scene has occluded geometry next to the sky, which a misplaced
        // test would have left at 1 (orthographic sees the ledge edge-on).
        if (!c.ortho) CHECK(dark > 200);
    }
    // One copy of the host's depth per execute on llvmpipe, none on a GPU.
    CHECK((testgl::Fixture::blits_as_renamed() > 0) == kind.software);
    CHECK(fx.gl_errors().empty());
  }
}

// What a pass skips at the sky is written with the sky's value every frame
// (plan.h SkyFill), so texels an earlier frame left there never reach the
// output: the sky scene after a frame whose wall covered the sky, right
// behind the geometry (its texels would pass the depth tests of their
// neighbours), gives exactly the AO of a fresh context.
TEST_CASE("sky test: texels an earlier frame left where the sky now is never reach the output, a GPU's plan and "
          "llvmpipe's") {
    const int W = 48, H = 40;
    const auto proj = analytic::perspective(testscenes::kFov, double(W) / H, 0.1, 100.0);
    const GBuffer sky = analytic::render(hc::sky_scene(), proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    analytic::Scene walled = hc::sky_scene();
    walled.add_quad({-60, -60, -6.05}, {120, 0, 0}, {0, 120, 0});
    const GBuffer wall = analytic::render(walled, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE, W, H);
    for (const testgl::RendererKind& kind : testgl::kRendererKinds) {
        const std::string renderer = kind.gl_renderer;
        CAPTURE(renderer);
        testgl::Fixture fx;
        for (ssao_resolution res : {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER})
            for (ssao_blur blur : {SSAO_BLUR_NONE, SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_GAUSSIAN}) {
                CAPTURE(res);
                CAPTURE(blur);
                ssao_settings s = hc::make(8, blur, SSAO_ROTATION_HASH, 0.8f, SSAO_METHOD_VISIBILITY);
                s.resolution = res;
                fx.recreate_context_as(kind.gl_renderer);
                fx.settings(s);
                REQUIRE(hc::run(fx, wall, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE).status == SSAO_OK);
                const hc::Out after_wall = hc::run(fx, sky, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
                fx.recreate_context_as(kind.gl_renderer);
                fx.settings(s);
                const hc::Out fresh = hc::run(fx, sky, proj, SSAO_CLIP_NEGATIVE_ONE_TO_ONE);
                REQUIRE(after_wall.status == SSAO_OK);
                REQUIRE(fresh.status == SSAO_OK);
                int differ = 0;
                for (size_t i = 0; i < fresh.ao.size(); ++i) differ += after_wall.ao[i] != fresh.ao[i];
                CHECK(differ == 0);
            }
        CHECK(fx.gl_errors().empty());
    }
}
