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
#include "timing.h"

#include <algorithm>
#include <functional>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace bench {

namespace {

void set_times(Row& row, const std::vector<double>& ms) {
    row.median_ms = quantile(ms, 0.5);
    row.p10_ms = quantile(ms, 0.1);
    row.p90_ms = quantile(ms, 0.9);
}

// "0.5", "1", "2": a radius multiple as the progress lines show it.
std::string fmt_scale(float s) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", double(s));
    return b;
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

Truth trace(const raytrace::Tracer& tracer, const camera::Camera& cam, int w, int h, float radius, int samples,
            int directions, const std::string& name) {
    raytrace::RenderOptions ro;
    ro.width = w;
    ro.height = h;
    ro.radius = radius;
    ro.samples = samples;
    ro.progress = false;
    raytrace::Image img;
    std::string error;
    if (!tracer.render(cam, ro, img, error)) throw std::runtime_error(error);

    depth_limit::Options lo;
    lo.radius = radius;
    lo.thickness = depth_limit::kDefaultThicknessOfR * radius;
    if (directions) lo.directions = directions;
    depth_limit::Image lim;
    if (!depth_limit::compute(cam, img, lo, lim, error)) throw std::runtime_error(error);
    std::fprintf(stderr, "  %s %dx%d: reference %d rays/pixel in %.1f s, limit %d directions in %.1f s\n",
                 name.c_str(), w, h, samples, img.seconds, lo.directions, lim.seconds);

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
    std::vector<uint8_t> geometry(t.mask.size());
    for (size_t i = 0; i < geometry.size(); ++i) geometry[i] = t.mask[i] > 0.5f;
    row.cell_pattern = metrics::cell_pattern(ao, t.ao, geometry, t.width, t.height);
    row.cell_spread = metrics::pattern_spread(row.cell_pattern);
    row.bias_occluded = metrics::occluded_bias(ao, t.ao, geometry);
    row.has_error = true;
}

// A timed pass: `prepare` before its frames in each round (the plugin's
// settings), `frame` submits one frame, `gpu_ms` reads that frame's GPU timer
// once glFinish has returned (NaN: none).
struct Timed {
    std::function<void()> prepare, frame;
    std::function<double()> gpu_ms;
    std::vector<double> gpu, wall, cpu_per_round;
};

// Every round runs each pass in turn (warm-up, then timed frames), so a slow
// spell of a shared machine lands on all of them alike.
void time_interleaved(GladGLContext& gl, std::vector<Timed>& passes, const Options& o) {
    for (int r = 0; r < o.rounds; ++r)
        for (Timed& t : passes) {
            if (t.prepare) t.prepare();
            for (int f = 0; f < o.warmup; ++f) {
                t.frame();
                gl.Finish();
            }
            double cpu = 0;
            for (int f = 0; f < o.frames; ++f) {
                const double c0 = process_cpu_ms(), w0 = wall_ms();
                t.frame();
                gl.Finish();
                const double w1 = wall_ms(), c1 = process_cpu_ms();
                t.wall.push_back(w1 - w0);
                cpu += c1 - c0;
                const double g = t.gpu_ms();
                if (std::isfinite(g)) t.gpu.push_back(g);
            }
            t.cpu_per_round.push_back(cpu / o.frames);
        }
}

void set_timing(Row& row, const Timed& t) {
    set_times(row, t.gpu);
    row.wall_ms = quantile(t.wall, 0.5);
    const RoundStats cpu = over_rounds(t.cpu_per_round);
    row.cpu_ms = cpu.median;
    row.cpu_min_ms = cpu.min;
    row.cpu_max_ms = cpu.max;
    row.rounds = cpu.rounds;
}

// The settings a configuration runs with on a scene of radius `radius`
// (max_step_texels: --max-step-texels, 0 = off).
ssao_settings settings_for(const Config& c, const ssao_api& api, float radius, float max_step_texels) {
    ssao_settings s = c.s;
    if (c.family == Family::preset) {
        s = ssao_settings{};
        s.size = sizeof s;
        if (api.preset_settings(c.preset, &s) != SSAO_OK) throw std::runtime_error("preset_settings failed");
    }
    s.radius = s.radius < 0 ? -s.radius * radius : radius;
    if (c.thickness_of_radius > 0) s.thickness = c.thickness_of_radius * s.radius;
    s.bias = 0;  // the method's default, relative to this radius
    s.max_step_texels = max_step_texels;
    return s;
}

// One scene at one view and radius, at one size.
struct Case {
    std::string scene, label;
    View view = View::standard;
    float radius_scale = 1.0f, radius = 0.0f;
    int width = 0, height = 0;
    bool main = false;  // the standard view at the scene's radius: the sweep and the full reference run here
};

Row case_row(const Case& k, const std::string& config, Row::Kind kind) {
    Row r;
    r.scene = k.scene;
    r.config = config;
    r.kind = kind;
    r.view = k.view;
    r.radius_scale = k.radius_scale;
    r.radius = k.radius;
    r.width = k.width;
    r.height = k.height;
    return r;
}

ssao_inputs plugin_inputs(const gbuffer::GBuffer& gbuf, const glm::mat4& proj, bool normals_from_depth) {
    ssao_inputs in{};
    in.size = sizeof in;
    in.depth_texture = gbuf.depth_texture();
    in.normal_texture = normals_from_depth ? 0u : gbuf.normal_texture();
    in.normal_space = SSAO_NORMAL_SPACE_VIEW;
    in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) in.projection[c * 4 + r] = proj[c][r];
    in.clip_range = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
    return in;
}

// The plugin's mean AO over `frames` consecutive frame indices from
// in.frame_index, whose first frame `out` already holds (frames = 1: that
// frame's AO).
std::vector<float> mean_ao(GladGLContext& gl, const ssao_api& api, ssao_context* ctx, const ssao_inputs& in,
                           ssao_output& out, const Case& k, int frames) {
    std::vector<float> sum = gl_util::read_texture(gl, out.texture, out.origin[0], out.origin[1], k.width, k.height, 1);
    ssao_inputs frame = in;
    for (int i = 1; i < frames; ++i) {
        frame.frame_index = in.frame_index + static_cast<uint32_t>(i);
        if (api.execute(ctx, &frame, &out) != SSAO_OK) throw std::runtime_error(api.last_error(ctx));
        const std::vector<float> ao = gl_util::read_texture(gl, out.texture, out.origin[0], out.origin[1], k.width,
                                                            k.height, 1);
        for (size_t j = 0; j < ao.size(); ++j) sum[j] += ao[j];
    }
    if (frames > 1)
        for (float& v : sum) v /= static_cast<float>(frames);
    return sum;
}

// The plugin's configuration c: its row (settings, and errors from one frame
// or from the mean of --average-frames) and how to time it (the context,
// inputs and output must outlive the timing).
Timed plugin_pass(GladGLContext& gl, const ssao_api& api, ssao_context* ctx, const ssao_inputs& in, ssao_output& out,
                  const Config& c, const Case& k, const Truth* truth, const Options& o, std::vector<Row>& rows) {
    const ssao_settings s = settings_for(c, api, k.radius, o.max_step_texels);
    if (api.set_settings(ctx, &s) != SSAO_OK) throw std::runtime_error(c.name + ": " + api.last_error(ctx));
    if (api.execute(ctx, &in, &out) != SSAO_OK) throw std::runtime_error(api.last_error(ctx));
    gl.Finish();
    Row row = case_row(k, c.name, Row::Kind::plugin);
    row.variant = c.thickness_of_radius > 0 || c.s.rotation != SSAO_ROTATION_DEFAULT;
    row.family = c.family;
    row.s.size = sizeof row.s;
    api.get_settings(ctx, &row.s);
    if (truth) fill_errors(row, mean_ao(gl, api, ctx, in, out, k, o.average_frames), *truth);
    rows.push_back(row);
    Timed t;
    t.prepare = [&api, ctx, s, name = c.name] {
        if (api.set_settings(ctx, &s) != SSAO_OK) throw std::runtime_error(name + ": " + api.last_error(ctx));
    };
    t.frame = [&api, ctx, &in, &out] {
        if (api.execute(ctx, &in, &out) != SSAO_OK) throw std::runtime_error(api.last_error(ctx));
    };
    t.gpu_ms = [&api, ctx] {
        ssao_timings tm{};
        tm.size = sizeof tm;
        api.get_timings(ctx, &tm);
        return tm.available ? double(tm.total_ms) : double(NAN);
    };
    return t;
}

void print_rows(const std::vector<Row>& rows, size_t first) {
    for (size_t i = first; i < rows.size(); ++i) {
        const Row& r = rows[i];
        if (r.kind == Row::Kind::limit) continue;
        if (r.has_error)
            std::fprintf(stderr, "    %-52s %8.3f ms CPU (%.3f-%.3f)  PSNR %.2f dB (limit: %.2f dB)\n", r.config.c_str(),
                         r.cpu_ms, r.cpu_min_ms, r.cpu_max_ms, r.all.psnr, r.vs_limit.psnr);
        else
            std::fprintf(stderr, "    %-52s %8.3f ms CPU (%.3f-%.3f)\n", r.config.c_str(), r.cpu_ms, r.cpu_min_ms,
                         r.cpu_max_ms);
    }
}

// What a view of a scene draws: the G-buffer, its matrices and the plugin's inputs.
struct ViewSetup {
    const scene::Scene& sc;
    const gbuffer::GBuffer& gbuf;
    glm::mat4 view, proj;
    ssao_inputs in;
};

// Every configuration (the sweep on the main case), the textbook pass and the
// floor on one case: their rows, then their CPU time interleaved over rounds.
void measure_case(GladGLContext& gl, const ssao_api& api, const Options& o, int scale, const ViewSetup& vs,
                  const Case& k, const Truth* truth, const std::vector<Config>& configs, std::vector<Row>& rows) {
    ssao_context_desc cd{};
    cd.size = sizeof cd;
    cd.get_proc_address = &eglctx::Context::get_proc;
    ssao_context* ctx = nullptr;
    if (api.create_context(&cd, &ctx) != SSAO_OK) throw std::runtime_error("create_context failed");
    ssao_output out{};
    out.size = sizeof out;
    textbook::Pass tb(gl, vs.sc.mesh, k.width, k.height, k.radius);
    tb.render_positions(vs.view, vs.proj);
    FloorPass fp(gl, k.width, k.height);

    const size_t first = rows.size();
    std::vector<Timed> passes;
    for (const Config& c : configs) passes.push_back(plugin_pass(gl, api, ctx, vs.in, out, c, k, truth, o, rows));
    // The chapter's pass, same process, same G-buffer normals, same clocks.
    tb.run(vs.gbuf.normal_texture(), vs.proj);
    gl.Finish();
    Row row = case_row(k, "textbook (chapter: position G-buffer, 64 samples, 4x4 box)", Row::Kind::textbook);
    if (truth) fill_errors(row, tb.read_ao(), *truth);
    rows.push_back(row);
    Timed textbook_timed;
    textbook_timed.frame = [&] { tb.run(vs.gbuf.normal_texture(), vs.proj); };
    textbook_timed.gpu_ms = [&] { return tb.last_ms(); };
    passes.push_back(std::move(textbook_timed));
    // The bandwidth floor: read depth and normal, write R8, nothing else.
    rows.push_back(case_row(k, "bandwidth floor (read depth + normal, write R8)", Row::Kind::floor));
    Timed floor_timed;
    floor_timed.frame = [&] { fp.run(vs.gbuf.depth_texture(), vs.gbuf.normal_texture()); };
    floor_timed.gpu_ms = [&] { return fp.last_ms(); };
    passes.push_back(std::move(floor_timed));
    // A frame at k x the base size costs k^2 as much and varies less:
    // 1/k of the frames per round (at least one) keeps larger sizes affordable.
    Options per_size = o;
    per_size.frames = std::max(1, o.frames / scale);
    per_size.warmup = std::max(1, o.warmup / scale);
    time_interleaved(gl, passes, per_size);
    for (size_t i = 0; i < passes.size(); ++i) set_timing(rows[first + i], passes[i]);
    api.destroy_context(ctx);
    print_rows(rows, first);
}

}  // namespace

LoadedScene load_scene(const std::string& path, const Options& o) {
    LoadedScene loaded{path, {}};
    std::string error;
    scene::Limits limits;
    limits.allow_outside_files = o.allow_outside_files;
    if (!scene::load(path, loaded.sc, error, limits)) throw std::runtime_error(error);
    if (!scene::ao_radius(loaded.sc)) throw std::runtime_error(path + " has no extent to scale the radius to");
    return loaded;
}

void measure_scene(const LoadedScene& scene, const Options& o, int scale, const ssao_api& api,
                   const std::vector<Config>& sweep, const std::vector<Config>& presets, bool with_errors,
                   std::vector<Row>& rows) {
    const scene::Scene& sc = scene.sc;
    std::string error;
    const int w = o.width * scale, h = o.height * scale;
    const float aspect = static_cast<float>(w) / static_cast<float>(h);
    // The same radius as ssao-host and ssao-reference use, so all agree on R.
    const auto scene_radius = scene::ao_radius(sc);
    const std::string name = std::filesystem::path(scene.path).stem().string();
    raytrace::Tracer tracer(sc.mesh);
    if (!tracer.ok()) throw std::runtime_error(tracer.error());
    const std::vector<float> scales = with_errors ? o.radius_scales : std::vector<float>{1.0f};

    eglctx::Options eo;
    auto egl = eglctx::Context::create(eo, error);
    if (!egl) throw std::runtime_error(error);
    GladGLContext& gl = egl->gl();

    for (View v : o.views) {
        const camera::Camera cam = view_camera(sc, aspect, v, tracer);
        gbuffer::Desc desc;
        desc.width = w;
        desc.height = h;
        gbuffer::GBuffer gbuf(gl, desc, sc.mesh);
        const glm::mat4 view = camera::view_matrix(cam), proj = camera::projection_matrix(cam, aspect);
        gbuf.render(view, proj);
        ViewSetup vs{sc, gbuf, view, proj, plugin_inputs(gbuf, proj, o.normals_from_depth)};
        if (o.average_frames > 1) vs.in.frame_index = 1;  // timed as a TAA host runs it
        for (float rs : scales) {
            Case k;
            k.scene = name;
            k.view = v;
            k.radius_scale = rs;
            k.radius = scene_radius->radius * rs;
            k.width = w;
            k.height = h;
            k.main = v == View::standard && rs == 1.0f;
            k.label = name + " " + view_name(v) + " " + fmt_scale(rs) + "R";
            std::fprintf(stderr, "  %s at %dx%d (radius %.3g)\n", k.label.c_str(), w, h, k.radius);
            Truth truth;
            if (with_errors) {
                truth = trace(tracer, cam, w, h, k.radius, k.main ? o.reference_samples : o.extra_samples,
                              k.main ? o.limit_directions : o.extra_directions, k.label);
                Row lim = case_row(k, "depth-only limit (ideal march, T = R/2)", Row::Kind::limit);
                lim.median_ms = lim.p10_ms = lim.p90_ms = lim.wall_ms = NAN;
                lim.cpu_ms = lim.cpu_min_ms = lim.cpu_max_ms = NAN;
                fill_errors(lim, truth.limit, truth);
                rows.push_back(lim);
            }
            std::vector<Config> configs = with_errors && k.main && o.full_sweep ? sweep : std::vector<Config>{};
            configs.insert(configs.end(), presets.begin(), presets.end());
            measure_case(gl, api, o, scale, vs, k, with_errors ? &truth : nullptr, configs, rows);
        }
    }
}

}  // namespace bench
