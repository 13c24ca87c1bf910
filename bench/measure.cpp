#include "measure.h"

#include "camera.h"
#include "depth_limit.h"
#include "egl_context.h"
#include "floor_pass.h"
#include "gbuffer.h"
#include "gl_util.h"
#include "raytracer.h"
#include "scene.h"
#include "textbook_ssao.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace bench {

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const double pos = q * static_cast<double>(v.size() - 1);
    const size_t i = static_cast<size_t>(pos);
    const double f = pos - static_cast<double>(i);
    return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

void set_times(Row& row, const std::vector<double>& ms) {
    row.median_ms = quantile(ms, 0.5);
    row.p10_ms = quantile(ms, 0.1);
    row.p90_ms = quantile(ms, 0.9);
}

// Top-row-first (reference) to bottom-row-first (GL read-back).
std::vector<float> flip_rows(const std::vector<float>& v, int w, int h) {
    std::vector<float> out(v.size());
    for (int y = 0; y < h; ++y)
        std::copy_n(v.begin() + static_cast<long>(y) * w, static_cast<size_t>(w),
                    out.begin() + static_cast<long>(h - 1 - y) * w);
    return out;
}

// The ground truth and the limit, bottom row first (as the read-back).
struct Truth {
    int width = 0, height = 0;
    std::vector<float> ao, std_error, mask, depth;  // V_R
    std::vector<float> limit, limit_std_error;      // V_limit
};

Truth trace(const scene::Scene& sc, const camera::Camera& cam, int w, int h, float radius, const Options& o,
            const std::string& name) {
    raytrace::Tracer tracer(sc.mesh);
    if (!tracer.ok()) throw std::runtime_error(tracer.error());
    raytrace::RenderOptions ro;
    ro.width = w;
    ro.height = h;
    ro.radius = radius;
    ro.samples = o.reference_samples;
    ro.progress = false;
    raytrace::Image img;
    std::string error;
    if (!tracer.render(cam, ro, img, error)) throw std::runtime_error(error);

    depth_limit::Options lo;
    lo.radius = radius;
    lo.thickness = depth_limit::kDefaultThicknessOfR * radius;
    if (o.limit_directions) lo.directions = o.limit_directions;
    depth_limit::Image lim;
    if (!depth_limit::compute(cam, img, lo, lim, error)) throw std::runtime_error(error);
    std::fprintf(stderr, "  %s %dx%d: reference %d rays/pixel in %.1f s, limit %d directions in %.1f s\n",
                 name.c_str(), w, h, o.reference_samples, img.seconds, lo.directions, lim.seconds);

    Truth t;
    t.width = w;
    t.height = h;
    t.ao = flip_rows(img.ao, w, h);
    t.std_error = flip_rows(img.std_error, w, h);
    t.mask = flip_rows(img.mask, w, h);
    t.depth = flip_rows(img.depth, w, h);
    t.limit = flip_rows(lim.ao, w, h);
    t.limit_std_error = flip_rows(lim.std_error, w, h);
    return t;
}

void fill_errors(Row& row, const std::vector<float>& ao, const Truth& t) {
    metrics::Inputs in;
    in.width = t.width;
    in.height = t.height;
    in.test = &ao;
    in.reference = &t.ao;
    in.sky = &t.mask;
    in.std_error = &t.std_error;
    in.depth = &t.depth;
    metrics::Split split;
    std::string error;
    if (!metrics::compute_split(in, t.limit, &t.limit_std_error, split, error) || split.ours_vs_reference.size() < 4)
        throw std::runtime_error("metrics: " + error);
    row.all = split.ours_vs_reference[0];
    row.interior = split.ours_vs_reference[1];
    row.silhouette = split.ours_vs_reference[2];
    row.border = split.ours_vs_reference[3];
    row.vs_limit = split.ours_vs_limit[0];
    row.has_error = true;
}

Row make_row(const std::string& scene, const std::string& config, Row::Kind kind, int w, int h) {
    Row r;
    r.scene = scene;
    r.config = config;
    r.kind = kind;
    r.width = w;
    r.height = h;
    return r;
}

// The settings a configuration runs with on a scene of radius `radius`.
ssao_settings settings_for(const Config& c, const ssao_api& api, float radius) {
    ssao_settings s = c.s;
    if (c.family == Family::preset) {
        s = ssao_settings{};
        s.size = sizeof s;
        if (api.preset_settings(c.preset, &s) != SSAO_OK) throw std::runtime_error("preset_settings failed");
    }
    s.radius = s.radius < 0 ? -s.radius * radius : radius;
    if (c.thickness_of_radius > 0) s.thickness = c.thickness_of_radius * s.radius;
    s.bias = 0;  // the method's default, relative to this radius
    if (c.family == Family::preset) s.thickness = 0;
    return s;
}

}  // namespace

void measure_scene(const std::string& path, const Options& o, int scale, const ssao_api& api,
                   const std::vector<Config>& configs, bool with_errors, std::vector<Row>& rows) {
    scene::Scene sc;
    std::string error;
    scene::Limits limits;
    limits.allow_outside_files = o.allow_outside_files;
    if (!scene::load(path, sc, error, limits)) throw std::runtime_error(error);
    const int w = o.width * scale, h = o.height * scale;
    const float aspect = static_cast<float>(w) / static_cast<float>(h);
    const camera::Camera cam = camera::choose(sc, aspect);
    // The same radius as ssao-host and ssao-reference use, so all agree on R.
    const auto scene_radius = scene::ao_radius(sc);
    if (!scene_radius) throw std::runtime_error(path + " has no extent to scale the radius to");
    const float radius = scene_radius->radius;
    const std::string name = std::filesystem::path(path).stem().string();

    Truth truth;
    if (with_errors) {
        truth = trace(sc, cam, w, h, radius, o, name);
        Row lim = make_row(name, "depth-only limit (ideal march, T = R/2)", Row::Kind::limit, w, h);
        lim.median_ms = lim.p10_ms = lim.p90_ms = NAN;
        fill_errors(lim, truth.limit, truth);
        rows.push_back(lim);
    }

    eglctx::Options eo;
    auto egl = eglctx::Context::create(eo, error);
    if (!egl) throw std::runtime_error(error);
    GladGLContext& gl = egl->gl();
    gbuffer::Desc desc;
    desc.width = w;
    desc.height = h;
    gbuffer::GBuffer gbuf(gl, desc, sc.mesh);
    const glm::mat4 view = camera::view_matrix(cam), proj = camera::projection_matrix(cam, aspect);
    gbuf.render(view, proj);

    ssao_context_desc cd{};
    cd.size = sizeof cd;
    cd.get_proc_address = &eglctx::Context::get_proc;
    ssao_context* ctx = nullptr;
    if (api.create_context(&cd, &ctx) != SSAO_OK) throw std::runtime_error("create_context failed");
    ssao_inputs in{};
    in.size = sizeof in;
    in.depth_texture = gbuf.depth_texture();
    in.normal_texture = o.normals_from_depth ? 0u : gbuf.normal_texture();
    in.normal_space = SSAO_NORMAL_SPACE_VIEW;
    in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) in.projection[c * 4 + r] = proj[c][r];
    in.clip_range = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;

    for (const Config& c : configs) {
        ssao_settings s = settings_for(c, api, radius);
        if (api.set_settings(ctx, &s) != SSAO_OK) throw std::runtime_error(c.name + ": " + api.last_error(ctx));
        std::vector<double> ms;
        ssao_output out{};
        out.size = sizeof out;
        std::vector<double> wall;
        gl.Finish();
        for (int f = 0; f < o.warmup + o.frames; ++f) {
            const auto t0 = Clock::now();
            if (api.execute(ctx, &in, &out) != SSAO_OK) throw std::runtime_error(api.last_error(ctx));
            gl.Finish();  // the frame's queries are done: read them at once, one sample per frame
            if (f >= o.warmup) wall.push_back(since(t0));
            ssao_timings t{};
            t.size = sizeof t;
            api.get_timings(ctx, &t);
            if (f >= o.warmup && t.available) ms.push_back(t.total_ms);
        }
        Row row = make_row(name, c.name, Row::Kind::plugin, w, h);
        row.family = c.family;
        row.s.size = sizeof row.s;
        api.get_settings(ctx, &row.s);
        set_times(row, ms);
        row.wall_ms = quantile(wall, 0.5);
        if (with_errors) fill_errors(row, gl_util::read_texture(gl, out.texture, out.origin[0], out.origin[1], w, h, 1), truth);
        rows.push_back(row);
        std::fprintf(stderr, "    %-52s %8.3f ms  PSNR %.2f dB (limit: %.2f dB)\n", c.name.c_str(), row.median_ms,
                     row.all.psnr, row.vs_limit.psnr);
    }
    api.destroy_context(ctx);

    // The chapter's pass, same process, same G-buffer normals, same timers.
    {
        textbook::Pass tb(gl, sc.mesh, w, h, radius);
        tb.render_positions(view, proj);
        std::vector<double> ms, wall;
        gl.Finish();
        for (int f = 0; f < o.warmup + o.frames; ++f) {
            const auto t0 = Clock::now();
            tb.run(gbuf.normal_texture(), proj);
            gl.Finish();
            if (f >= o.warmup) wall.push_back(since(t0));
            if (f >= o.warmup) ms.push_back(tb.last_ms());
        }
        Row row = make_row(name, "textbook (chapter: position G-buffer, 64 samples, 4x4 box)", Row::Kind::textbook, w, h);
        set_times(row, ms);
        row.wall_ms = quantile(wall, 0.5);
        if (with_errors) fill_errors(row, tb.read_ao(), truth);
        rows.push_back(row);
        std::fprintf(stderr, "    %-52s %8.3f ms  PSNR %.2f dB\n", "textbook", row.median_ms, row.all.psnr);
    }
    // The bandwidth floor: read depth and normal, write R8, nothing else.
    {
        FloorPass fp(gl, w, h);
        std::vector<double> ms, wall;
        gl.Finish();
        for (int f = 0; f < o.warmup + o.frames; ++f) {
            const auto t0 = Clock::now();
            fp.run(gbuf.depth_texture(), gbuf.normal_texture());
            gl.Finish();
            if (f >= o.warmup) wall.push_back(since(t0));
            if (f >= o.warmup) ms.push_back(fp.last_ms());
        }
        Row row = make_row(name, "bandwidth floor (read depth + normal, write R8)", Row::Kind::floor, w, h);
        set_times(row, ms);
        row.wall_ms = quantile(wall, 0.5);
        rows.push_back(row);
        std::fprintf(stderr, "    %-52s %8.3f ms (wall %.3f ms)\n", "bandwidth floor", row.median_ms, row.wall_ms);
    }
}

}  // namespace bench
