#include "normals_view_util.h"

#include "conventions.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nfd {

std::vector<Convention> conventions(double aspect, double hh) {
    const double n = 0.1, f = 100.0;
    const auto all =
        hc::perspective_conventions(aspect, n, f,
                                    {"GL [-1,1] D32F", "GL [-1,1] D24", "GL [-1,1] D24S8", "GL [-1,1] D16",
                                     "[0,1] D32F", "reverse-Z [0,1] D32F", "reverse-Z [0,1] D32FS8",
                                     "reverse-Z infinite D32F", "GL infinite D32F", "GL infinite D24",
                                     "reverse-Z [-1,1] D32F"}) +
        hc::ortho_conventions(hh * aspect, hh, n, f,
                              {"ortho GL [-1,1] D32F", "ortho GL [-1,1] D16", "ortho [0,1] D32F",
                               "ortho reverse [0,1] D32F"});
    std::vector<Convention> out;
    for (const hc::Convention& c : all)
        out.push_back({c.name, c.proj, c.clip, c.format, c.ortho, c.ortho ? hh : std::tan(hc::kFov / 2)});
    return out;
}

ViewResult run_view(testgl::Fixture& fx, const analytic::GBuffer& g, const glm::dmat4& proj, ssao_clip_range clip,
                    GLenum depth_format, const ViewOptions& o) {
    ViewResult r;
    const int P = o.pad, W = g.width + 2 * P, H = g.height + 2 * P;
    // The padding would show in the border pixels' normals if it were read.
    const testgl::Textures t =
        hc::inset_textures(fx, o.normal_space == SSAO_NORMAL_SPACE_WORLD ? hc::with_world_normals(g, o.view_matrix) : g,
                           P, P, W, H, depth_format, o.normal_format);
    auto& gl = fx.gl();
    const GLuint dt = t.depth;
    const GLuint nt = o.depth_only ? 0u : t.normal;
    GLuint out = 0;
    gl.GenTextures(1, &out);
    gl.BindTexture(GL_TEXTURE_2D, out);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, W, H, 0, GL_RGBA, GL_FLOAT, nullptr);
    gl.BindTexture(GL_TEXTURE_2D, 0);

    ssao_settings s{};
    s.size = sizeof s;
    s.debug_view = o.view;
    fx.settings(s);
    ssao_inputs in = fx.inputs(dt, nt, proj, clip);
    in.normal_space = o.normal_space;
    in.normal_packing = testgl::packing_of(o.normal_format);
    if (o.normal_space == SSAO_NORMAL_SPACE_WORLD) analytic::to_floats(o.view_matrix, in.view_matrix);
    in.output_texture = out;
    testgl::set_viewport(in, P, P, g.width, g.height);
    ssao_output res{};
    res.size = sizeof res;
    r.status = fx.api().execute(fx.ctx(), &in, &res);
    if (r.status == SSAO_OK) {
        r.passes_run = res.passes_run;
        std::vector<float> px(static_cast<size_t>(W) * H * 4);
        gl.BindTexture(GL_TEXTURE_2D, out);
        gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
        gl.GetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, px.data());
        gl.BindTexture(GL_TEXTURE_2D, 0);
        for (int y = 0; y < g.height; ++y)
            for (int x = 0; x < g.width; ++x) {
                const float* c = &px[hc::at(x + P, y + P, W) * 4];
                r.n.push_back(glm::vec3(c[0], c[1], c[2]) * 2.0f - 1.0f);
                r.alpha.push_back(c[3]);
            }
    }
    gl.DeleteTextures(1, &out);
    return r;
}

analytic::GBuffer sphere_gbuffer(const glm::dmat4& proj, ssao_clip_range clip, int w, int h, glm::dvec3 c, double r,
                                 double wall_z) {
    analytic::GBuffer g;
    g.width = w;
    g.height = h;
    const float sky = analytic::render(analytic::Scene{}, proj, clip, 1, 1).depth[0];
    const glm::dmat4 inv = glm::inverse(proj);
    auto unproject = [&](double nx, double ny, double nz) {
        const glm::dvec4 v = inv * glm::dvec4(nx, ny, nz, 1.0);
        return glm::dvec3(v) / v.w;
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double nx = (x + 0.5) / w * 2 - 1, ny = (y + 0.5) / h * 2 - 1;
            // Two points of the pixel's ray at finite NDC depths (the far
            // plane may be at infinity); the hit closest to the camera is
            // the one with the largest z.
            const glm::dvec3 a = unproject(nx, ny, 0.25), b = unproject(nx, ny, 0.5);
            const glm::dvec3 dir = glm::normalize(b - a);
            glm::dvec3 hit(nan), n(0.0);
            const glm::dvec3 oc = a - c;
            const double bq = glm::dot(oc, dir), cq = glm::dot(oc, oc) - r * r, disc = bq * bq - cq;
            if (disc >= 0) {
                const double t1 = -bq - std::sqrt(disc), t2 = -bq + std::sqrt(disc);
                const glm::dvec3 p1 = a + t1 * dir, p2 = a + t2 * dir;
                hit = p1.z > p2.z ? p1 : p2;
                n = glm::normalize(hit - c);
            } else if (wall_z < 0 && std::abs(dir.z) > 1e-12) {
                hit = a + dir * ((wall_z - a.z) / dir.z);
                n = glm::dvec3(0, 0, 1);
            }
            if (std::isnan(hit.x)) {
                g.depth.push_back(sky);
                g.normal.push_back(glm::vec3(0.0f));
            } else {
                g.depth.push_back(static_cast<float>(hc::depth_at(proj, clip, -hit.z)));
                g.normal.push_back(glm::vec3(n));
            }
            g.position.push_back(hit);
        }
    return g;
}

double angle(glm::dvec3 a, glm::dvec3 b) {
    const double la = glm::length(a), lb = glm::length(b);
    if (la == 0 && lb == 0) return 0;
    if (la == 0 || lb == 0) return M_PI;
    // atan2 of |cross| and dot: accurate for small angles too.
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

double pixel_size(const Convention& c, double t, int height) {
    return (c.ortho ? 2 * c.half_height : 2 * t * c.half_height) / height;
}

}  // namespace nfd
