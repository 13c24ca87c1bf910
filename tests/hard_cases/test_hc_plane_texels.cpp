// The grid pass's plane texels below full resolution (what every march step
// of the visibility pass reads): view z in red, the tangent plane as depth
// over the screen in green and blue (perspective: 1/z affine in the viewport
// position, orthographic: z), the cosine between the eye ray and the plane in
// alpha, 0 for a normal the march must not use as a tangent plane. Checked
// against the analytic scene: the plane a texel holds puts the true depth
// under the pixels of the same face around it.
#include <doctest/doctest.h>

#include "conventions.h"
#include "hc_util.h"

#include <algorithm>
#include <cmath>
#include <string>

using analytic::GBuffer;

namespace {

// The library's texture labelled `label` (resources.cpp labels every
// intermediate), or 0.
GLuint labelled_texture(GladGLContext& gl, const std::string& label) {
    for (GLuint id = 1; id < 4096; ++id) {
        if (!gl.IsTexture(id)) continue;
        char name[64] = {};
        GLsizei length = 0;
        gl.GetObjectLabel(GL_TEXTURE, id, sizeof name, &length, name);
        if (std::string(name, static_cast<size_t>(length)) == label) return id;
    }
    return 0;
}

std::vector<glm::vec4> read_rgba(GladGLContext& gl, GLuint texture, int w, int h) {
    std::vector<glm::vec4> texels(static_cast<size_t>(w) * h);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.GetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(glm::vec4)),
                       texels.data());
    return texels;
}

// common.glsl grid_pixel at half resolution.
glm::ivec2 picked_pixel(int tx, int ty, int w, int h) {
    const int o = (tx + ty) & 1;
    return {std::min(tx * 2 + o, w - 1), std::min(ty * 2 + o, h - 1)};
}

// The depth the plane texel puts under viewport position u.
double plane_depth(const glm::vec4& texel, glm::dvec2 u0, glm::dvec2 u, bool ortho) {
    const double g_du = double(texel.y) * (u.x - u0.x) + double(texel.z) * (u.y - u0.y);
    return ortho ? double(texel.x) + g_du : double(texel.x) / (1.0 + g_du);
}

struct Tally {
    int planes = 0, predictions = 0, sky = 0, flagged = 0;
};

// Runs the visibility pass at half resolution on `g` (normals `normals` if
// given) and CHECKs every plane texel; `broken` marks the pixels whose
// normals the grid pass must flag.
Tally check_plane_texels(testgl::Fixture& fx, const GBuffer& g, const hc::Convention& c,
                         const std::vector<glm::vec3>* normals, const std::vector<bool>& broken) {
    ssao_settings s = hc::make(8, SSAO_BLUR_NONE, SSAO_ROTATION_HASH, 0.5f, SSAO_METHOD_VISIBILITY);
    s.resolution = SSAO_RESOLUTION_HALF;
    fx.settings(s);
    hc::RunOptions o;
    o.depth_format = c.format;
    o.normals = normals;
    o.normal_format = GL_RGBA32F;  // the plane from the exact normal: the checks see the pass, not half floats
    REQUIRE(hc::run(fx, g, c, o).status == SSAO_OK);
    GladGLContext& gl = fx.gl();
    const GLuint tex = labelled_texture(gl, "ssao: intermediate 0");
    REQUIRE(tex != 0);
    const int W = g.width, H = g.height, gw = (W + 1) / 2, gh = (H + 1) / 2;
    const std::vector<glm::vec4> texels = read_rgba(gl, tex, gw, gh);
    Tally tally;
    for (int ty = 0; ty < gh; ++ty)
        for (int tx = 0; tx < gw; ++tx) {
            const glm::vec4 texel = texels[hc::at(tx, ty, gw)];
            const glm::ivec2 p = picked_pixel(tx, ty, W, H);
            CAPTURE(tx);
            CAPTURE(ty);
            if (g.sky(p.x, p.y)) {
                CHECK(texel.x == 3.0e38f);  // SKY_Z
                ++tally.sky;
                continue;
            }
            const size_t ip = hc::at(p.x, p.y, W);
            const glm::dvec3 X = g.position[ip];
            const glm::dvec3 n = glm::dvec3(g.normal[ip]);
            CHECK(std::abs(texel.x - X.z) <= 1e-3 * std::abs(X.z) + 1e-4);
            if (broken[ip]) {
                CHECK(texel.w == 0.0f);
                ++tally.flagged;
                continue;
            }
            // The cosine between the pixel's eye ray and its plane (the
            // analytic scene's normals face the camera).
            const double cosine = c.ortho ? n.z : std::abs(glm::dot(n, X)) / glm::length(X);
            CHECK(std::abs(texel.w - cosine) <= 1e-4);
            if (cosine < 0.05) continue;  // nearly edge-on: depth precision decides, not the plane
            ++tally.planes;
            const glm::dvec2 u0 = glm::dvec2(p) + 0.5;
            for (int dy = -3; dy <= 3; ++dy)
                for (int dx = -3; dx <= 3; ++dx) {
                    const int qx = p.x + dx, qy = p.y + dy;
                    if (qx < 0 || qy < 0 || qx >= W || qy >= H || g.sky(qx, qy)) continue;
                    const size_t iq = hc::at(qx, qy, W);
                    const glm::dvec3 Xq = g.position[iq];
                    // The same face: the same normal, and Xq on p's plane.
                    if (glm::length(glm::dvec3(g.normal[iq]) - n) > 1e-6) continue;
                    if (std::abs(glm::dot(n, Xq - X)) > 1e-6 * (1.0 + glm::length(Xq))) continue;
                    const double z = plane_depth(texel, u0, glm::dvec2(qx, qy) + 0.5, c.ortho);
                    CAPTURE(dx);
                    CAPTURE(dy);
                    CHECK(std::abs(z - Xq.z) <= 2e-3 * std::abs(Xq.z) + 1e-4);
                    ++tally.predictions;
                }
        }
    return tally;
}

}  // namespace

TEST_CASE("half resolution: each plane texel holds its face's tangent plane, the sky its marker, a broken normal a flag") {
    testgl::Fixture fx;
    const int W = 64, H = 48;
    const auto cases =
        hc::perspective_conventions(double(W) / H, 0.1, 100.0,
                                    {"GL [-1,1] D32F", "[0,1] D32F", "reverse-Z infinite D32F"}) +
        hc::ortho_conventions(4.0, 3.0, 0.1, 50.0, {"ortho GL [-1,1] D32F", "ortho reverse [0,1] D32F"});
    const analytic::Scene scene = hc::crease_scene();
    for (const hc::Convention& c : cases) {
        const std::string cname = c.name;
        CAPTURE(cname);
        const GBuffer g = analytic::render(scene, c.proj, c.clip, W, H);
        std::vector<bool> none(g.normal.size(), false);
        const Tally good = check_plane_texels(fx, g, c, nullptr, none);
        CHECK(good.planes > 300);
        CHECK(good.predictions > 5000);
        CHECK(good.flagged == 0);

        // Every third pixel's normal broken (zero) and every fifth turned away from the camera.
        std::vector<glm::vec3> normals = g.normal;
        std::vector<bool> broken(normals.size(), false);
        for (size_t i = 0; i < normals.size(); ++i) {
            if (std::isnan(g.position[i].x)) continue;
            if (i % 3 == 0) normals[i] = glm::vec3(0.0f);
            else if (i % 5 == 0) normals[i] = -normals[i];
            else continue;
            broken[i] = true;
        }
        const Tally bad = check_plane_texels(fx, g, c, &normals, broken);
        CHECK(bad.flagged > 100);
    }
    CHECK(fx.gl_errors().empty());
}
