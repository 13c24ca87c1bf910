// ssao-bench - what accuracy costs in time. For each scene it ray-traces the
// ground truth (Embree, V_R with R = the plugin's radius), renders the host's
// G-buffer, then for every configuration of a sweep measures the plugin's GPU
// time (median of its own timer queries over many frames after warm-up) and
// its error against the reference; the chapter's textbook pass runs in the
// same process as the anchor. Writes CSV, Markdown, a gnuplot plot of error
// against time with the Pareto front, and the presets it suggests.
// A benchmark, not a test: nothing here asserts, it measures and reports.
#include "camera.h"
#include "egl_context.h"
#include "flags.h"
#include "gbuffer.h"
#include "gl_util.h"
#include "locate.h"
#include "metrics.h"
#include "plugin_loader.h"
#include "raytracer.h"
#include "scene.h"
#include "textbook_ssao.h"

#include <ssao/ssao.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct Options {
    std::vector<std::string> scenes;
    int width = 160, height = 120;
    int warmup = 4, frames = 15;
    int reference_samples = 512;
    std::vector<int> resolution_scales = {1, 2};  // x the base size, default config + textbook only
    std::string out = "bench-out";
    std::string plugin;  // empty: plugin::Library::search_order()
};

struct Config {
    std::string name;
    ssao_settings s{};
};

struct Row {
    std::string scene, config;
    int width = 0, height = 0;
    ssao_settings s{};
    bool textbook = false;
    double median_ms = 0, p10_ms = 0, p90_ms = 0;
    metrics::Stats all, interior, silhouette, border;
};

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const double pos = q * (v.size() - 1);
    const size_t i = static_cast<size_t>(pos);
    const double f = pos - i;
    return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

ssao_settings base() {
    ssao_settings s{};
    s.size = sizeof s;
    return s;
}

const char* blur_name(ssao_blur b) {
    switch (b) {
        case SSAO_BLUR_DEPTH_AWARE: return "depth-aware";
        case SSAO_BLUR_BOX_4X4: return "box";
        case SSAO_BLUR_GAUSSIAN: return "gaussian";
        case SSAO_BLUR_NONE: return "none";
        default: return "default";
    }
}

// One axis at a time from the defaults, plus the samples x blur grid.
std::vector<Config> sweep() {
    std::vector<Config> c;
    for (ssao_kernel_distribution d : {SSAO_DISTRIBUTION_ACCELERATING, SSAO_DISTRIBUTION_UNIFORM})
        for (uint32_t n : {4u, 8u, 16u, 32u, 64u})
            for (ssao_blur b : {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_NONE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN}) {
                Config k{std::to_string(n) + " samples, blur " + blur_name(b) +
                             (d == SSAO_DISTRIBUTION_UNIFORM ? ", uniform" : ""),
                         base()};
                k.s.sample_count = n;
                k.s.blur = b;
                k.s.distribution = d;
                c.push_back(k);
            }
    auto one = [&](const std::string& name, auto edit) {
        Config k{name, base()};
        edit(k.s);
        c.push_back(k);
    };
    one("16 samples, sphere kernel", [](ssao_settings& s) { s.kernel_shape = SSAO_KERNEL_SPHERE; });
    one("16 samples, separable kernel", [](ssao_settings& s) { s.kernel_shape = SSAO_KERNEL_SEPARABLE; });
    one("32 samples, separable kernel", [](ssao_settings& s) { s.kernel_shape = SSAO_KERNEL_SEPARABLE; s.sample_count = 32; });
    one("16 samples, hash rotation", [](ssao_settings& s) { s.rotation = SSAO_ROTATION_HASH; });
    one("16 samples, no rotation", [](ssao_settings& s) { s.rotation = SSAO_ROTATION_NONE; });
    one("16 samples, blur radius 1", [](ssao_settings& s) { s.blur_radius = 1; });
    one("16 samples, blur radius 4", [](ssao_settings& s) { s.blur_radius = 4; });
    one("32 samples, uniform, blur radius 4", [](ssao_settings& s) { s.distribution = SSAO_DISTRIBUTION_UNIFORM; s.sample_count = 32; s.blur_radius = 4; });
    one("16 samples, radius x0.5", [](ssao_settings& s) { s.radius = -0.5f; });  // relative, resolved per scene
    one("16 samples, radius x2", [](ssao_settings& s) { s.radius = -2.0f; });
    return c;
}

const char* kHelp =
    "usage: ssao-bench [options] [scene.glb ...]\n"
    "  --width N --height N   base resolution, 8..4096 (default 160 x 120)\n"
    "  --frames N             timed frames per configuration (default 15), after\n"
    "  --warmup N             untimed frames (default 4)\n"
    "  --reference-samples N  rays per pixel of the ground truth (default 512)\n"
    "  --out DIR              where results go (default bench-out)\n"
    "  --quick                fewer frames and rays, base resolution only\n"
    "  --plugin PATH          libssao.so to load (default: as ssao-host finds it)\n"
    "  --help, -h / --version this text / the version\n"
    "Scenes default to the bundled spot and teapot models and scenes/corner.gltf.\n";

enum class Parse { Run, Help, Version, Error };

// The shared parser (host/flags.h): --flag value and --flag=value alike.
Parse parse(int argc, char** argv, Options& o, std::string& error) {
    auto whole = [](int& out, long long lo, long long hi) {
        return [&out, lo, hi](const std::string& f, const std::string& v) { out = int(flags::integer(f, v, lo, hi)); };
    };
    const flags::Valued valued = {
        {"--width", whole(o.width, 8, 4096)},
        {"--height", whole(o.height, 8, 4096)},
        {"--frames", whole(o.frames, 1, 10000)},
        {"--warmup", whole(o.warmup, 0, 10000)},
        {"--reference-samples", whole(o.reference_samples, 16, 1 << 20)},
        {"--out", [&](const std::string& f, const std::string& v) {
             if (v.empty()) flags::fail(f + " needs a folder name");
             o.out = v;
         }},
        {"--plugin", [&](const std::string& f, const std::string& v) {
             if (v.empty()) flags::fail(f + " expects a path to libssao.so");
             o.plugin = v;
         }},
    };
    const flags::Switches switches = {
        {"--quick", [&] { o.frames = 5; o.warmup = 2; o.reference_samples = 128; o.resolution_scales = {1}; }},
    };
    try {
        switch (flags::walk(argc, argv, valued, switches, [&](const std::string& a) { o.scenes.push_back(a); })) {
            case flags::Outcome::Help: return Parse::Help;
            case flags::Outcome::Version: return Parse::Version;
            case flags::Outcome::Run: break;
        }
    } catch (const flags::Error& e) {
        error = e.message;
        return Parse::Error;
    }
    if (o.scenes.empty()) {
        o.scenes = {locate::bundled("models/spot-on-ground.glb"), locate::bundled("models/teapot-on-ground.glb"),
                    locate::bundled("scenes/corner.gltf")};
    }
    return Parse::Run;
}

// Top-row-first (reference) to bottom-row-first (GL read-back).
std::vector<float> flip_rows(const std::vector<float>& v, int w, int h, int channels = 1) {
    std::vector<float> out(v.size());
    for (int y = 0; y < h; ++y)
        std::copy_n(v.begin() + static_cast<long>(y) * w * channels, static_cast<size_t>(w) * channels,
                    out.begin() + static_cast<long>(h - 1 - y) * w * channels);
    return out;
}

struct Reference {
    raytrace::Image image;  // bottom row first after flipping
};

void fill_errors(Row& row, const std::vector<float>& ao, const Reference& ref) {
    metrics::Inputs in;
    in.width = ref.image.width;
    in.height = ref.image.height;
    in.test = &ao;
    in.reference = &ref.image.ao;
    in.sky = &ref.image.mask;
    in.std_error = &ref.image.std_error;
    in.depth = &ref.image.depth;
    std::vector<metrics::Stats> stats;
    std::string error;
    if (!metrics::compute(in, stats, error) || stats.size() < 4) throw std::runtime_error("metrics: " + error);
    row.all = stats[0];
    row.interior = stats[1];
    row.silhouette = stats[2];
    row.border = stats[3];
}

struct Measured {
    std::vector<Row> rows;
};

void run_scene(const std::string& path, const Options& o, int scale, const ssao_api& api, Measured& m,
               bool full_sweep) {
    scene::Scene sc;
    std::string error;
    if (!scene::load(path, sc, error)) throw std::runtime_error(error);
    const int w = o.width * scale, h = o.height * scale;
    const float aspect = static_cast<float>(w) / h;
    const camera::Camera cam = camera::choose(sc, aspect);
    // The same radius as ssao-host and ssao-reference use, so all agree on R.
    const auto scene_radius = scene::ao_radius(sc);
    if (!scene_radius) throw std::runtime_error(path + " has no extent to scale the radius to");
    const float radius = scene_radius->radius;
    const std::string name = std::filesystem::path(path).stem().string();

    // Ground truth.
    raytrace::Tracer tracer(sc.mesh);
    if (!tracer.ok()) throw std::runtime_error(tracer.error());
    raytrace::RenderOptions ro;
    ro.width = w;
    ro.height = h;
    ro.radius = radius;
    ro.samples = o.reference_samples;
    ro.progress = false;
    Reference ref;
    if (!tracer.render(cam, ro, ref.image, error)) throw std::runtime_error(error);
    ref.image.ao = flip_rows(ref.image.ao, w, h);
    ref.image.std_error = flip_rows(ref.image.std_error, w, h);
    ref.image.mask = flip_rows(ref.image.mask, w, h);
    ref.image.depth = flip_rows(ref.image.depth, w, h);
    std::fprintf(stderr, "  %s %dx%d: reference %d rays/pixel in %.1f s\n", name.c_str(), w, h, o.reference_samples,
                 ref.image.seconds);

    // G-buffer and plugin.
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
    in.normal_texture = gbuf.normal_texture();
    in.normal_space = SSAO_NORMAL_SPACE_VIEW;
    in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) in.projection[c * 4 + r] = proj[c][r];
    in.clip_range = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;

    std::vector<Config> configs;
    if (full_sweep) configs = sweep();
    else configs.push_back({"16 samples, blur depth-aware", base()});
    for (Config& c : configs) {
        ssao_settings s = c.s;
        s.radius = s.radius < 0 ? -s.radius * radius : radius;
        if (api.set_settings(ctx, &s) != SSAO_OK) throw std::runtime_error(api.last_error(ctx));
        std::vector<double> ms;
        ssao_output out{};
        out.size = sizeof out;
        for (int f = 0; f < o.warmup + o.frames; ++f) {
            if (api.execute(ctx, &in, &out) != SSAO_OK) throw std::runtime_error(api.last_error(ctx));
            gl.Finish();  // the frame's queries are done: read them at once, one sample per frame
            ssao_timings t{};
            t.size = sizeof t;
            api.get_timings(ctx, &t);
            if (f >= o.warmup && t.available) ms.push_back(t.total_ms);
        }
        Row row;
        row.scene = name;
        row.config = c.name;
        row.width = w;
        row.height = h;
        row.s.size = sizeof row.s;
        api.get_settings(ctx, &row.s);
        row.median_ms = quantile(ms, 0.5);
        row.p10_ms = quantile(ms, 0.1);
        row.p90_ms = quantile(ms, 0.9);
        const std::vector<float> ao = gl_util::read_texture(gl, out.texture, out.origin[0], out.origin[1], w, h, 1);
        fill_errors(row, ao, ref);
        m.rows.push_back(row);
        std::fprintf(stderr, "    %-40s %8.3f ms  RMSE %.4f\n", c.name.c_str(), row.median_ms, row.all.rmse);
    }
    api.destroy_context(ctx);

    // The chapter's pass, same process, same G-buffer normals, same timers.
    textbook::Pass tb(gl, sc.mesh, w, h, radius);
    tb.render_positions(view, proj);
    std::vector<double> ms;
    for (int f = 0; f < o.warmup + o.frames; ++f) {
        tb.run(gbuf.normal_texture(), proj);
        if (f >= o.warmup) ms.push_back(tb.last_ms());
    }
    Row row;
    row.scene = name;
    row.config = "textbook (chapter: position G-buffer, 64 samples, 4x4 box)";
    row.textbook = true;
    row.width = w;
    row.height = h;
    row.median_ms = quantile(ms, 0.5);
    row.p10_ms = quantile(ms, 0.1);
    row.p90_ms = quantile(ms, 0.9);
    fill_errors(row, tb.read_ao(), ref);
    m.rows.push_back(row);
    std::fprintf(stderr, "    %-40s %8.3f ms  RMSE %.4f\n", "textbook", row.median_ms, row.all.rmse);
}

std::string fmt(double v, int digits = 4) {
    char b[64];
    std::snprintf(b, sizeof b, "%.*f", digits, v);
    return b;
}

// Per configuration over the scenes at the base size: mean time ratio to the
// textbook of the same scene, mean RMSE.
struct Summary {
    std::string config;
    double time_ratio = 0, rmse = 0, ms = 0;
    bool textbook = false, pareto = false;
    ssao_settings s{};
};

std::vector<Summary> summarise(const std::vector<Row>& rows, int base_w) {
    std::map<std::string, double> textbook_ms;
    for (const Row& r : rows)
        if (r.textbook && r.width == base_w) textbook_ms[r.scene] = r.median_ms;
    std::vector<Summary> out;
    std::map<std::string, size_t> index;
    std::map<std::string, int> counts;
    for (const Row& r : rows) {
        if (r.width != base_w) continue;
        if (!index.count(r.config)) {
            index[r.config] = out.size();
            Summary s;
            s.config = r.config;
            s.textbook = r.textbook;
            s.s = r.s;
            out.push_back(s);
        }
        Summary& s = out[index[r.config]];
        s.time_ratio += r.median_ms / textbook_ms[r.scene];
        s.rmse += r.all.rmse;
        s.ms += r.median_ms;
        counts[r.config]++;
    }
    for (Summary& s : out) {
        const int n = counts[s.config];
        s.time_ratio /= n;
        s.rmse /= n;
        s.ms /= n;
    }
    for (Summary& a : out) {
        a.pareto = true;
        for (const Summary& b : out)
            if (&a != &b && b.time_ratio <= a.time_ratio && b.rmse <= a.rmse &&
                (b.time_ratio < a.time_ratio || b.rmse < a.rmse))
                a.pareto = false;
    }
    return out;
}

void write_outputs(const Options& o, const Measured& m) {
    std::filesystem::create_directories(o.out);
    {
        std::ofstream csv(o.out + "/bench.csv");
        csv << "scene,config,width,height,samples,kernel,distribution,rotation,blur,blur_radius,radius,"
               "median_ms,p10_ms,p90_ms,rmse,psnr,mean_error,p99_abs_error,rmse_interior,rmse_silhouette,"
               "rmse_border,reference_noise_rms\n";
        for (const Row& r : m.rows)
            csv << r.scene << ",\"" << r.config << "\"," << r.width << "," << r.height << ","
                << (r.textbook ? 64 : r.s.sample_count) << "," << (r.textbook ? 1 : r.s.kernel_shape) << ","
                << (r.textbook ? 1 : r.s.distribution) << "," << (r.textbook ? 1 : r.s.rotation) << ","
                << (r.textbook ? 2 : r.s.blur) << "," << r.s.blur_radius << "," << r.s.radius << "," << r.median_ms
                << "," << r.p10_ms << "," << r.p90_ms << "," << r.all.rmse << "," << r.all.psnr << ","
                << r.all.mean_error << "," << r.all.p99_abs_error << "," << r.interior.rmse << ","
                << r.silhouette.rmse << "," << r.border.rmse << "," << r.all.noise_rms << "\n";
    }
    const std::vector<Summary> sum = summarise(m.rows, o.width);
    {
        std::ofstream dat(o.out + "/bench.dat");
        dat << "# time_ratio rmse pareto textbook\n";
        for (const Summary& s : sum) dat << s.time_ratio << " " << s.rmse << " " << s.pareto << " " << s.textbook << "\n";
        std::ofstream front(o.out + "/front.dat");
        std::vector<Summary> f;
        for (const Summary& s : sum)
            if (s.pareto) f.push_back(s);
        std::sort(f.begin(), f.end(), [](const Summary& a, const Summary& b) { return a.time_ratio < b.time_ratio; });
        for (const Summary& s : f) front << s.time_ratio << " " << s.rmse << "\n";
    }
    std::ostringstream md;
    md << "| configuration | GPU time vs textbook | mean ms | RMSE vs ray-traced | Pareto |\n|---|---:|---:|---:|:---:|\n";
    std::vector<Summary> sorted = sum;
    std::sort(sorted.begin(), sorted.end(), [](const Summary& a, const Summary& b) { return a.time_ratio < b.time_ratio; });
    for (const Summary& s : sorted)
        md << "| " << s.config << " | " << fmt(s.time_ratio, 3) << " | " << fmt(s.ms, 2) << " | " << fmt(s.rmse, 4)
           << " | " << (s.pareto ? "yes" : "") << " |\n";
    md << "\nPer scene and resolution (median ms over frames, RMSE over all / interior / silhouette / border pixels):\n\n"
       << "| scene | size | configuration | median ms | RMSE | interior | silhouette | border | mean signed | p99 abs | ref. noise |\n"
       << "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const Row& r : m.rows)
        if (r.textbook || r.config.rfind("16 samples, blur depth-aware", 0) == 0 || r.width != o.width)
            md << "| " << r.scene << " | " << r.width << "x" << r.height << " | " << r.config << " | "
               << fmt(r.median_ms, 2) << " | " << fmt(r.all.rmse) << " | " << fmt(r.interior.rmse) << " | "
               << fmt(r.silhouette.rmse) << " | " << fmt(r.border.rmse) << " | " << fmt(r.all.mean_error) << " | "
               << fmt(r.all.p99_abs_error) << " | " << fmt(r.all.noise_rms) << " |\n";
    std::ofstream(o.out + "/bench.md") << md.str();

    // Presets from the front (fastest first): low = the fastest front point;
    // medium (the default preset) = the fastest front point whose error is at
    // most 2/3 of the textbook's; high = the most accurate within the
    // textbook's time; ultra = the most accurate of all.
    std::vector<Summary> front;
    double textbook_rmse = 0;
    for (const Summary& s : sorted) {
        if (s.pareto && !s.textbook) front.push_back(s);
        if (s.textbook) textbook_rmse = s.rmse;
    }
    auto best_within = [&](double ratio) {
        const Summary* best = nullptr;
        for (const Summary& s : front)
            if (s.time_ratio <= ratio && (!best || s.rmse < best->rmse)) best = &s;
        return best;
    };
    auto fastest_below = [&](double rmse) {
        for (const Summary& s : front)
            if (s.rmse <= rmse) return &s;
        return static_cast<const Summary*>(nullptr);
    };
    std::ostringstream pr;
    if (!front.empty()) {
        const Summary* picks[4] = {&front.front(), fastest_below(textbook_rmse * 2.0 / 3.0), best_within(1.0),
                                   best_within(1e30)};
        const char* names[4] = {"low", "medium", "high", "ultra"};
        for (int i = 0; i < 4; ++i)
            if (picks[i])
                pr << names[i] << ": " << picks[i]->config << " (time x" << fmt(picks[i]->time_ratio, 3)
                   << " of textbook, RMSE " << fmt(picks[i]->rmse) << ")\n";
    }
    const Summary* tb = nullptr;
    const Summary* def = nullptr;
    for (const Summary& s : sum) {
        if (s.textbook) tb = &s;
        if (s.config == "16 samples, blur depth-aware") def = &s;
    }
    for (const Summary& s : sum)
        if (s.config == "4 samples, blur box, uniform" && tb)
            pr << "4 samples, uniform, box vs textbook: RMSE " << fmt(s.rmse) << " vs " << fmt(tb->rmse) << ", time x"
               << fmt(s.time_ratio, 3) << "\n";
    if (tb && def)
        pr << "zeroed settings (16 samples, accelerating, depth-aware) vs textbook: RMSE " << fmt(def->rmse) << " vs " << fmt(tb->rmse) << ", time x"
           << fmt(def->time_ratio, 3) << (def->rmse < tb->rmse && def->time_ratio <= 0.25 ? " (target met)\n" : " (target missed)\n");
    std::ofstream(o.out + "/presets.txt") << pr.str();
    std::printf("%s\n%s", md.str().c_str(), pr.str().c_str());

    // The plot: gnuplot (Debian's gnuplot-nox) draws it when installed.
    double ymax = textbook_rmse;
    for (const Summary& s : front) ymax = std::max(ymax, s.rmse);
    ymax *= 1.6;
    std::ofstream gp(o.out + "/plot.gp");
    gp << "set terminal pngcairo size 900,600\nset output 'error_vs_time.png'\n"
       << "set yrange [0:" << ymax << "]\n"
          "set title 'SSAO error against GPU time (mean over scenes; points above the top edge are off the chart)'\n"
          "set xlabel 'GPU time relative to the textbook pass'\nset ylabel 'RMSE against ray-traced AO'\n"
          "set logscale x\nset grid\nset key top right\n"
          "plot 'bench.dat' using ($4==0 ? $1 : 1/0):2 with points pt 7 ps 1 lc rgb '#4477aa' title 'configurations', \\\n"
          "     'front.dat' using 1:2 with linespoints pt 6 ps 2 lw 2 lc rgb '#cc3311' title 'Pareto front', \\\n"
          "     'bench.dat' using ($4==1 ? $1 : 1/0):2 with points pt 5 ps 2 lc rgb '#000000' title 'textbook pass'\n";
    gp.close();
    const std::string cmd = "cd '" + o.out + "' && gnuplot plot.gp 2>/dev/null";
    if (std::system("command -v gnuplot >/dev/null 2>&1") == 0 && std::system(cmd.c_str()) == 0)
        std::printf("plot: %s/error_vs_time.png\n", o.out.c_str());
    else
        std::printf("plot: gnuplot not found; %s/plot.gp draws it (apt-get install gnuplot-nox)\n", o.out.c_str());
    std::printf("results: %s/bench.csv, %s/bench.md, %s/presets.txt\n", o.out.c_str(), o.out.c_str(), o.out.c_str());
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    std::string error;
    switch (parse(argc, argv, o, error)) {
        case Parse::Error: std::fprintf(stderr, "ssao-bench: %s\n", error.c_str()); return 2;
        case Parse::Help: std::fputs(kHelp, stdout); return 0;
        case Parse::Version: std::printf("%s\n", flags::version_line("ssao-bench").c_str()); return 0;
        case Parse::Run: break;
    }
    try {
        plugin::Library lib;
        if (!lib.open_default(o.plugin, error)) throw std::runtime_error(error);
        Measured m;
        for (size_t i = 0; i < o.scenes.size(); ++i)
            for (int scale : o.resolution_scales) {
                std::fprintf(stderr, "scene %s at %dx scale\n", o.scenes[i].c_str(), scale);
                run_scene(o.scenes[i], o, scale, lib.api(), m, scale == 1);
            }
        write_outputs(o, m);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ssao-bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
