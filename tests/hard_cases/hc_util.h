// hc_util.h - helpers for the hard-case tests: one execute with any depth and
// normal format, normal space, viewport padding and normal override; checks
// that every output pixel is finite and in [0,1]; exact depth steps of each
// format; the shader's view-position reconstruction emulated in float; a few
// projections the shared support does not have.
#pragma once

#include "gl_fixture.h"

#include <ssao/ssao.h>

#include <glm/glm.hpp>

#include <functional>
#include <string>
#include <vector>

namespace hc {

inline constexpr double kFov = 1.0471975512;  // 60 degrees

struct RunOptions {
    GLenum depth_format = GL_DEPTH_COMPONENT32F;
    GLenum normal_format = GL_RGBA16F;
    ssao_normal_space normal_space = SSAO_NORMAL_SPACE_VIEW;
    glm::dmat4 view_matrix{1.0};                  // for world-space normals
    const std::vector<glm::vec3>* normals = nullptr;  // overrides the G-buffer's normals
    int pad_x = 0, pad_y = 0;                     // embed the G-buffer at this offset in a larger texture
    int pad_right = 0, pad_top = 0;               // extra texels right of / above the viewport
    bool depth_only = false;                      // normal_texture = 0: the plugin rebuilds normals from depth
};

struct Out {
    ssao_status status = SSAO_OK;
    std::vector<float> ao;   // viewport-sized, row-major from the bottom row
    ssao_output output{};
    double ms = 0.0;         // execute + glFinish wall time
};

Out run(testgl::Fixture& fx, const analytic::GBuffer& g, const glm::dmat4& proj, ssao_clip_range clip,
        const RunOptions& o = {});

// The G-buffer's depth and normals at (x, y) in tw x th textures of the given
// formats. The texels around it hold geometry-like garbage, a near depth and
// a skewed normal, so anything read outside the viewport would show.
testgl::Textures inset_textures(testgl::Fixture& fx, const analytic::GBuffer& g, int x, int y, int tw, int th,
                                GLenum depth_format = GL_DEPTH_COMPONENT32F, GLenum normal_format = GL_RGBA16F);

// A host output texture, R32F tw x th with nearest filtering, every texel
// `value` (one AO never takes, so that a texel execute wrote shows).
GLuint sentinel_texture(GladGLContext& gl, int tw, int th, float value);

// The G-buffer with its normals rotated from view to world space by the
// inverse of `view` (the rotation part), as a host with world normals holds them.
analytic::GBuffer with_world_normals(analytic::GBuffer g, const glm::dmat4& view);

// CHECKs that every value is finite and in [0,1]; returns how many were not.
int check_unit_finite(const std::vector<float>& ao, const char* what = "");

// Resolved-to-be settings for a hard case: R16F output, everything else default.
ssao_settings make(uint32_t samples, ssao_blur blur, ssao_rotation rotation, float radius, ssao_method method);

// Every hard case holds for both estimators. HC_EACH_METHOD(m)
// declares `ssao_method m` and opens one doctest subcase per estimator;
// doctest re-enters the test case once per subcase, so everything after this
// line runs once with m = SSAO_METHOD_KERNEL and once with
// m = SSAO_METHOD_VISIBILITY, and a failure names the subcase.
#define HC_EACH_METHOD(m)                                           \
    ssao_method m = SSAO_METHOD_KERNEL;                             \
    SUBCASE("method kernel") { m = SSAO_METHOD_KERNEL; }            \
    SUBCASE("method visibility") { m = SSAO_METHOD_VISIBILITY; }    \
    CAPTURE(m)

// Projections beyond the shared support's.
glm::dmat4 ortho_zo(double half_w, double half_h, double n, double f);          // [0,1], near -> 0
glm::dmat4 ortho_reverse(double half_w, double half_h, double n, double f);     // [0,1], near -> 1
glm::dmat4 reverse_z_gl(double fovy, double aspect, double n, double f);    // GL [-1,1], near -> ndc 1, far -> -1
glm::dmat4 frustum(double l, double r, double b, double t, double n, double f); // GL [-1,1], off-centre
// Shifts the image by (px, py) whole or fractional pixels of a w x h viewport.
glm::dmat4 pixel_shift(const glm::dmat4& proj, double px, double py, int w, int h);

// The view z at which the ray through the centre of pixel (x, y) meets the
// tangent plane of the surface at pixel (x0, y0) (its position and normal in
// g), for a G-buffer rendered through proj: what the depth-aware blur expects
// at a tap. The centre's own z when the ray runs parallel to the plane.
double tangent_plane_z(const analytic::GBuffer& g, const glm::dmat4& proj, int x0, int y0, int x, int y);
// The depth-aware blur's weight of the tap at pixel (x, y) for the centre
// (x0, y0), from its definition (blur.frag depth_weight): 1 - |dz| / tolerance
// clamped to [0, 1], the tolerance relative_tolerance |z0|. Where the centre's
// tangent plane is not parallel to the image (its normal has an x or y), dz is
// the tap's view z less the view z that plane puts under the tap and the
// tolerance shrinks by SSAO_PLANE_TOLERANCE; else dz is the tap's view z less
// the centre's. With both planes known, the miss of the tap's own plane under
// the centre is added to dz (the two-way test of the full-resolution blur,
// the only one this oracle models).
double blur_depth_weight(const analytic::GBuffer& g, const glm::dmat4& proj, double relative_tolerance, int x0, int y0,
                         int x, int y);

// The depth-buffer value of view distance t along -z.
double depth_at(const glm::dmat4& proj, ssao_clip_range clip, double t);
// Bits of a depth format (16, 24, 32 = float).
int format_bits(GLenum depth_format);
// The view-distance change of one step of the format at distance t (exact,
// in double): |t(d + step) - t(d)| with step = 1/(2^bits-1) or one float ulp
// (for D32F with a [-1,1] clip range: at least half an ulp of NDC z).
double depth_step(const glm::dmat4& proj, ssao_clip_range clip, GLenum depth_format, double t);
// The rule-of-thumb estimate of the same (docs/hard-cases.md, "Depth precision").
double design_step(GLenum depth_format, bool reverse_zo, double n, double t);
// The depth value the format stores for d (round to nearest unorm / float).
double quantise(double d, GLenum depth_format);

// The shader's view_position (shaders/common.glsl) emulated in float: the
// inverse projection computed in double and stored as float, NDC from the
// pixel centre in float, one float matrix-vector product and division.
glm::vec3 shader_view_position(const glm::dmat4& proj, ssao_clip_range clip, int px, int py, int w, int h,
                               float depth);

// What a GL rasteriser stores in a float depth buffer with the [-1,1] clip
// range: NDC z is a float, then depth = ndc * 0.5 + 0.5 in float. (The
// analytic G-buffer rounds the exact depth once; this adds the NDC rounding.)
void gl_window_depth(analytic::GBuffer& g, ssao_clip_range clip, GLenum depth_format);

// Row-major index helper.
inline size_t at(int x, int y, int w) { return static_cast<size_t>(y) * w + x; }

double mean(const std::vector<float>& v, const std::function<bool(size_t)>& mask = {});

}  // namespace hc

namespace hc {

// World -> view for the crease scenes: 2 units (times scale) above the floor,
// pitched 25 degrees down, camera at `eye_offset` in the world.
glm::dmat4 crease_view(double scale = 1.0, glm::dvec3 eye_offset = glm::dvec3(0.0));
// World-space floor y = 0 and wall z = -6 (times scale), optionally two boxes,
// all moved by `offset`.
analytic::Scene crease_world(double scale = 1.0, bool boxes = true, glm::dvec3 offset = glm::dvec3(0.0));
// The scene's quads mapped into view space.
analytic::Scene to_view(const analytic::Scene& world, const glm::dmat4& view);
// The crease scene (times scale, with or without its boxes) in view space,
// seen from crease_view(scale).
analytic::Scene crease_scene(double scale = 1.0, bool boxes = true);
// Two quads and a box floating in the sky, and a ledge (view space): a scene
// whose geometry borders the sky everywhere.
analytic::Scene sky_scene();
// The crease scene with its boxes rendered w x h with `proj`: the setup most
// cases start from.
analytic::GBuffer crease_gbuffer(const glm::dmat4& proj, ssao_clip_range clip, int w, int h);

// The setup most hard cases start from: a fixture and the crease scene's
// G-buffer, W x H under `proj`. A case declared with TEST_CASE_FIXTURE on one
// of the setups below sees fx, W, H, proj and g as its own.
struct CreaseSetup {
    testgl::Fixture fx;
    const int W, H;
    const glm::dmat4 proj;
    const analytic::GBuffer g;
    CreaseSetup(int w, int h, const glm::dmat4& projection, ssao_clip_range clip);
};
// 64 x 48, reverse-Z [0,1], near 0.1, far 100.
struct CreaseReverseZ : CreaseSetup {
    CreaseReverseZ();
};
// 64 x 48, GL [-1,1], near 0.1, far 100.
struct CreaseGl : CreaseSetup {
    CreaseGl();
};

// Compares two AO images over a mask: counts and worst difference.
struct Diff {
    size_t compared = 0, over_1e3 = 0, over_one_sample = 0;
    double worst = 0, mean_abs = 0;
};
Diff diff(const std::vector<float>& a, const std::vector<float>& b, const std::function<bool(size_t)>& mask,
          double one_sample);

}  // namespace hc
