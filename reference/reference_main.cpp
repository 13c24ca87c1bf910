// ssao-reference: ray-traced ground-truth ambient occlusion (Embree 3) for the
// same scene, camera and resolution as ssao-host.
//
// Outputs in --out DIR (written only once everything has been traced; on any
// failure nothing is left behind):
//   reference_ao.exr      channels Y = V_R in [0,1] and A = coverage (1 geometry, 0 sky).
//                         Sky pixels have Y = 1 and A = 0: use A as the sky mask.
//   reference_stderr.exr  channel Y = per-pixel standard error of Y (0 for sky)
//   reference_ao.png      8-bit grey of Y (sky white)
//   with --dump-buffers:
//   reference_depth.exr   channel Z = view depth (-z_view, positive; +inf for sky, as ssao-host's view_depth.exr)
//   reference_normal.exr  channels R,G,B = view-space geometric normal facing the camera (0 for sky)
//   with --limit (the depth-only limit, reference/depth_limit.h):
//   limit_ao.exr          channels Y = V_limit in [0,1] and A = coverage, laid out as reference_ao.exr
//   limit_stderr.exr      channel Y = per-pixel standard error of V_limit (0 for sky)
//   limit_ao.png          8-bit grey of V_limit
// Row 0 of every image is the top row of the picture.
#include "camera.h"
#include "camera_flags.h"
#include "depth_limit.h"
#include "flags.h"
#include "image_io.h"
#include "locate.h"
#include "metrics.h"
#include "provenance.h"
#include "raytracer.h"
#include "scene.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <new>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace {

using flags::fail;
using flags::quoted;

float positive(const std::string& flag, const std::string& text) {
    const double v = flags::number(flag, text);
    if (!(v > 0.0)) fail(flag + " " + text + " must be greater than 0");
    if (v > 1e30) fail(flag + " " + text + " is out of range (0, 1e+30]");  // as ssao-host words it
    flags::check_normal_float(flag, text, v);
    return float(v);
}

struct Options {
    std::string scene_path;
    std::string out_dir = "out";
    int width = 800, height = 600;
    std::optional<float> radius;
    int samples = 1024;
    uint32_t seed = 1;
    int threads = 0;
    bool dump_buffers = false;
    bool limit = false;
    std::optional<double> thickness;   // default: depth_limit::kDefaultThicknessOfR x radius
    std::optional<int> limit_directions;
    bool quiet = false;
    bool allow_outside_files = false;
    camera::Overrides cam;
};

std::string flags_num(double v) {
    std::ostringstream o;
    o << v;
    return o.str();
}

std::string help_text() {
    return std::string() +
    "ssao-reference - ray-traced ambient occlusion (Embree) for the same image ssao-host renders.\n"
    "\n"
    "usage: ssao-reference [SCENE.gltf|SCENE.glb] [flags]\n"
    "  SCENE              glTF scene (default: the bundled spot-on-ground.glb)\n"
    "  --width N          image width in pixels, 1..16384 (default 800, as ssao-host)\n"
    "  --height N         image height in pixels, 1..16384 (default 600, as ssao-host)\n"
    "  --radius R         AO radius in scene units, > 0 (default as ssao-host: the scene's\n"
    "                     extras.ssao.radius, else 0.05 x the bounding-box diagonal)\n"
    "  --samples N        occlusion rays per pixel, 1..1048576 (default 1024)\n"
    "  --seed N           sample-pattern seed, 0..4294967295 (default 1)\n"
    "  --eye x,y,z        camera position (default as ssao-host: the scene's camera, else framed from\n"
    "                     the bounds; without a scene argument, the bundled view of the cow, eye\n"
    "                     2.3,1.6,-2.6 and target 0,0.65,0)\n"
    "  --target x,y,z     point the camera looks at\n"
    "  --fov DEG          vertical field of view in degrees, (0, 180)\n"
    "  --near N           near plane distance, > 0\n"
    "  --far F|inf        far plane distance (inf: infinite far plane, perspective only)\n"
    "  --ortho H          orthographic camera of half-height H (scene units)\n"
    "  --reverse-z        reverse-Z projection (same rays; accepted for parity with ssao-host)\n"
    "  --out DIR          output folder, created if missing (default out)\n"
    "  --dump-buffers     also write reference_depth.exr and reference_normal.exr\n"
    "  --limit            also write the depth-only limit: limit_ao.exr (Y, A as reference_ao.exr),\n"
    "                     limit_stderr.exr and limit_ao.png - the AO of an ideal ray-marcher over\n"
    "                     this image's single depth layer (docs/reference.md, \"The depth-only limit\")\n"
    "  --thickness T|inf  with --limit: a point behind the depth layer by less than T (view depth,\n"
    "                     scene units) is blocked, > 0 (default " + flags_num(depth_limit::kDefaultThicknessOfR) +
    " x R; inf: a height field)\n"
    "  --limit-directions N  with --limit: directions per pixel, a multiple of " +
    std::to_string(depth_limit::kReplicas) + " (default " + std::to_string(depth_limit::kDefaultDirections) + ")\n"
    "  --allow-outside-files  let the scene's buffer URIs name files outside its folder (absolute\n"
    "                     paths, '..', symbolic links leading out); refused by default\n"
    "  --threads N        worker threads (default: all cores)\n"
    "  --quiet            no progress bar\n"
    "  --help, -h         this text\n"
    "  --version          the version\n"
    "\n"
    "Writes DIR/reference_ao.exr (Y = AO, A = coverage: 0 for sky, where Y = 1),\n"
    "DIR/reference_stderr.exr (Y = standard error of the mean per pixel) and DIR/reference_ao.png.\n"
    "AO is V_R: the cosine-weighted fraction of the hemisphere around the face normal with no hit\n"
    "within the radius. Pixel centres, row 0 at the top, rays from inverse(projection * view).\n"
    "reference_ao.exr and limit_ao.exr record the scene, size, camera, radius (and the limit's\n"
    "thickness) in their headers; ssao-error refuses to compare images whose records differ.\n";
}

using Parse = flags::Outcome;

Parse parse(int argc, char** argv, Options& o, std::string& error) {
    const flags::Valued valued = {
        {"--width", [&](const std::string& f, const std::string& v) { o.width = int(flags::integer(f, v, 1, 16384)); }},
        {"--height", [&](const std::string& f, const std::string& v) { o.height = int(flags::integer(f, v, 1, 16384)); }},
        {"--radius", [&](const std::string& f, const std::string& v) { o.radius = positive(f, v); }},
        {"--samples", [&](const std::string& f, const std::string& v) { o.samples = int(flags::integer(f, v, 1, 1 << 20)); }},
        {"--seed", [&](const std::string& f, const std::string& v) { o.seed = uint32_t(flags::integer(f, v, 0, 4294967295LL)); }},
        {"--threads", [&](const std::string& f, const std::string& v) { o.threads = int(flags::integer(f, v, 1, 1024)); }},
        {"--eye", [&](const std::string& f, const std::string& v) { o.cam.eye = flags::vec3(f, v); }},
        {"--target", [&](const std::string& f, const std::string& v) { o.cam.target = flags::vec3(f, v); }},
        {"--fov", [&](const std::string& f, const std::string& v) { o.cam.fov_deg = flags::fov_degrees(f, v); }},
        {"--near", [&](const std::string& f, const std::string& v) { o.cam.znear = positive(f, v); }},
        {"--far", [&](const std::string& f, const std::string& v) { o.cam.zfar = flags::far_plane(f, v); }},
        {"--ortho", [&](const std::string& f, const std::string& v) { o.cam.ortho_half_height = positive(f, v); }},
        {"--thickness", [&](const std::string& f, const std::string& v) {
             const double d = flags::number(f, v, true);
             if (!(d > 0.0)) fail(f + " " + v + " must be greater than 0 (scene units, or inf)");
             o.thickness = d;
         }},
        {"--limit-directions", [&](const std::string& f, const std::string& v) {
             const long long d = flags::integer(f, v, depth_limit::kReplicas, 1 << 20);
             if (d % depth_limit::kReplicas != 0)
                 fail(f + " " + v + " must be a multiple of " + std::to_string(depth_limit::kReplicas));
             o.limit_directions = int(d);
         }},
        {"--out", [&](const std::string& f, const std::string& v) {
             if (v.empty()) fail(f + " needs a folder name");
             o.out_dir = v;
         }},
    };
    const flags::Switches switches = {
        {"--dump-buffers", [&] { o.dump_buffers = true; }},
        {"--limit", [&] { o.limit = true; }},
        {"--quiet", [&] { o.quiet = true; }},
        {"--reverse-z", [&] { o.cam.reverse_z = true; }},
        {"--allow-outside-files", [&] { o.allow_outside_files = true; }},
    };
    return flags::parse(argc, argv, valued, switches, o.scene_path, error, [&] {
        flags::check_camera(o.cam);
        if (!o.limit && o.thickness) fail("--thickness applies only with --limit");
        if (!o.limit && o.limit_directions) fail("--limit-directions applies only with --limit");
        if (double(o.width) * double(o.height) * double(o.samples) > 4e12)
            fail("--width x --height x --samples is absurdly large (more than 4e12 rays)");
    });
}

bool make_dirs(const std::string& path, std::string& error) {
    std::string cur;
    for (size_t i = 0; i <= path.size(); ++i) {
        if (i == path.size() || path[i] == '/') {
            if (!cur.empty() && cur != "/" && cur != ".") {
                struct stat st;
                if (stat(cur.c_str(), &st) == 0) {
                    if (!S_ISDIR(st.st_mode)) {
                        error = "--out " + quoted(path) + ": " + quoted(cur) + " exists and is not a folder.";
                        return false;
                    }
                } else if (mkdir(cur.c_str(), 0777) != 0 && errno != EEXIST) {
                    error = "--out " + quoted(path) + ": cannot create " + quoted(cur) + " (" + std::strerror(errno) + ").";
                    return false;
                }
            }
        }
        if (i < path.size()) cur += path[i];
    }
    if (access(path.c_str(), W_OK) != 0) {
        error = "--out " + quoted(path) + ": the folder is not writable.";
        return false;
    }
    return true;
}

// A runtime failure: run prints "ssao-reference: error: " + what() and exits 1.
struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The scene, the camera and the radius, as ssao-host picks them.
struct Setup {
    scene::Scene sc;
    camera::Camera cam;
    camera::Source camera_source = camera::Source::Framed;
    float radius = 0.5f;
    std::string radius_note = "--radius";
};

Setup load(Options& o) {
    Setup s;
    const bool bundled_scene = o.scene_path.empty();
    if (bundled_scene) o.scene_path = scene::default_path();
    std::string error;
    scene::Limits limits;
    limits.allow_outside_files = o.allow_outside_files;
    if (!scene::load(o.scene_path, s.sc, error, limits)) throw Failure(error);
    const float aspect = float(o.width) / float(o.height);
    try {
        s.cam = camera::initial(s.sc, aspect, o.cam, bundled_scene, &s.camera_source);
    } catch (const camera::Error& e) {
        throw Failure(e.what());
    }
    // --radius, else the scene's hint, else 0.05 x the bounding-box diagonal
    // (else the plugin's default 0.5). A hint that is no radius is refused, as
    // ssao-host refuses it.
    if (const std::string problem = scene::radius_hint_problem(s.sc.hints); !problem.empty()) throw Failure(problem);
    if (o.radius) {
        s.radius = *o.radius;
    } else if (const auto r = scene::ao_radius(s.sc)) {
        s.radius = r->radius;
        s.radius_note = r->source;
    } else {
        s.radius_note = "plugin default";
    }
    return s;
}

void print_setup(const Options& o, const Setup& s) {
    const camera::Camera& cam = s.cam;
    std::printf("scene     %s: %zu triangles, bounds (%g, %g, %g) .. (%g, %g, %g)\n", o.scene_path.c_str(),
                s.sc.mesh.triangle_count(), s.sc.bounds_min.x, s.sc.bounds_min.y, s.sc.bounds_min.z, s.sc.bounds_max.x,
                s.sc.bounds_max.y, s.sc.bounds_max.z);
    std::printf("camera    %s, eye (%g, %g, %g), target (%g, %g, %g), %s, near %g, far %g\n",
                (o.cam.eye || o.cam.target) ? "from the flags" : camera::describe(s.camera_source), cam.eye.x, cam.eye.y,
                cam.eye.z, cam.target.x, cam.target.y, cam.target.z,
                cam.orthographic ? ("orthographic half-height " + std::to_string(cam.ortho_half_height)).c_str()
                                 : ("fov " + std::to_string(glm::degrees(cam.yfov)) + " deg").c_str(),
                cam.znear, cam.zfar);
    std::printf("trace     %dx%d, radius %g (%s), %d rays per pixel, seed %u\n", o.width, o.height, s.radius,
                s.radius_note.c_str(), o.samples, o.seed);
    std::fflush(stdout);
}

// V_R: the ray-traced ground truth (and the depth layer the limit reads).
raytrace::Image trace(const Options& o, const Setup& s) {
    raytrace::Tracer tracer(s.sc.mesh);
    if (!tracer.ok()) throw Failure("the ray tracer could not be built: " + tracer.error() + ".");
    print_setup(o, s);
    raytrace::RenderOptions ro;
    ro.width = o.width;
    ro.height = o.height;
    ro.radius = s.radius;
    ro.samples = o.samples;
    ro.seed = o.seed;
    ro.threads = o.threads;
    ro.progress = !o.quiet;
    raytrace::Image img;
    std::string error;
    if (!tracer.render(s.cam, ro, img, error)) throw Failure(error + ".");
    return img;
}

depth_limit::Options limit_options(const Options& o, const Setup& s) {
    depth_limit::Options lo;
    lo.radius = s.radius;
    lo.thickness = o.thickness ? *o.thickness : depth_limit::kDefaultThicknessOfR * double(s.radius);
    lo.directions = o.limit_directions ? *o.limit_directions : depth_limit::kDefaultDirections;
    lo.seed = o.seed;
    lo.threads = o.threads;
    lo.progress = !o.quiet;
    return lo;
}

// The depth-only limit over the traced image's own depth layer.
depth_limit::Image compute_limit(const Options& o, const Setup& s, const depth_limit::Options& lo,
                                 const raytrace::Image& img) {
    std::printf("limit     depth-only, thickness %g%s, %d directions per pixel (%d rotated sets), exact march\n",
                lo.thickness, o.thickness ? "" : (" (" + flags_num(depth_limit::kDefaultThicknessOfR) + " x R)").c_str(),
                lo.directions, depth_limit::kReplicas);
    std::fflush(stdout);
    depth_limit::Image limit;
    std::string error;
    if (!depth_limit::compute(s.cam, img, lo, limit, error)) throw Failure(error + ".");
    return limit;
}

// Every image; on a failure what was written is removed. Returns the paths.
std::vector<std::string> write_outputs(const Options& o, const Setup& s, const raytrace::Image& img,
                                       const depth_limit::Options& lo, const depth_limit::Image& limit) {
    const std::string dir = o.out_dir;
    std::vector<std::string> written;
    std::string error;
    auto png = [&](const std::string& name, const std::vector<float>& v) {
        const std::string p = dir + "/" + name;
        if (!refio::write_png_grey(p, img.width, img.height, v, error)) return false;
        written.push_back(p);
        return true;
    };
    // What the images were made with, for ssao-error to check (provenance.h).
    const provenance::Fields made_with = provenance::describe(o.scene_path, o.width, o.height, s.cam, s.radius);
    provenance::Fields limit_made_with = made_with;
    if (o.limit) limit_made_with = provenance::describe(o.scene_path, o.width, o.height, s.cam, s.radius, lo.thickness);
    auto exr = [&](const std::string& name, std::vector<refio::Channel> ch, const provenance::Fields& attributes = {}) {
        const std::string p = dir + "/" + name;
        if (!refio::write_exr(p, img.width, img.height, std::move(ch), error, attributes)) return false;
        written.push_back(p);
        return true;
    };
    std::vector<float> nx, ny, nz;
    if (o.dump_buffers) {
        const size_t n = img.ao.size();
        nx.resize(n);
        ny.resize(n);
        nz.resize(n);
        for (size_t i = 0; i < n; ++i) {
            nx[i] = img.normal[i * 3];
            ny[i] = img.normal[i * 3 + 1];
            nz[i] = img.normal[i * 3 + 2];
        }
    }
    bool ok = exr("reference_ao.exr", {{"Y", &img.ao}, {"A", &img.mask}}, made_with) &&
              exr("reference_stderr.exr", {{"Y", &img.std_error}});
    ok = ok && png("reference_ao.png", img.ao);
    if (ok && o.dump_buffers)
        ok = exr("reference_depth.exr", {{"Z", &img.depth}}) &&
             exr("reference_normal.exr", {{"R", &nx}, {"G", &ny}, {"B", &nz}});
    if (ok && o.limit)
        ok = exr("limit_ao.exr", {{"Y", &limit.ao}, {"A", &img.mask}}, limit_made_with) &&
             exr("limit_stderr.exr", {{"Y", &limit.std_error}}) && png("limit_ao.png", limit.ao);
    if (!ok) {
        for (const auto& p : written) std::remove(p.c_str());
        throw Failure(error);
    }
    return written;
}

void report_reference(const Options& o, const raytrace::Image& img) {
    double mean = 0.0, se = 0.0, se_max = 0.0;
    size_t geo = 0;
    for (size_t i = 0; i < img.ao.size(); ++i)
        if (img.mask[i] > 0.5f) {
            mean += img.ao[i];
            se += img.std_error[i];
            se_max = std::max(se_max, double(img.std_error[i]));
            ++geo;
        }
    if (geo) {
        mean /= double(geo);
        se /= double(geo);
    }
    std::printf("result    %zu geometry pixels, %zu sky; mean AO %.4f\n", geo, img.ao.size() - geo, mean);
    std::printf("noise     mean standard error %.5f, max %.5f (bound 0.5/sqrt(N) = %.5f)\n", se, se_max,
                0.5 / std::sqrt(double(o.samples)));
    std::printf("time      %.2f s, %.2f Mrays/s\n", img.seconds, double(img.rays) / std::max(img.seconds, 1e-9) * 1e-6);
}

void report_limit(const raytrace::Image& img, const depth_limit::Image& limit) {
    double lse = 0.0, lse2 = 0.0, lse_max = 0.0, lmean = 0.0;
    size_t geo = 0;
    std::vector<uint8_t> geometry(img.mask.size());
    std::vector<double> errs;
    for (size_t i = 0; i < img.mask.size(); ++i) {
        geometry[i] = img.mask[i] > 0.5f;
        if (!geometry[i]) continue;
        ++geo;
        lmean += limit.ao[i];
        lse += limit.std_error[i];
        lse2 += double(limit.std_error[i]) * limit.std_error[i];
        lse_max = std::max(lse_max, double(limit.std_error[i]));
        errs.push_back(limit.std_error[i]);
    }
    if (geo) {
        lmean /= double(geo);
        lse /= double(geo);
        lse2 /= double(geo);
    }
    const metrics::Stats st = metrics::stats_over(limit.ao, img.ao, geometry, &img.std_error, "all");
    std::printf("limit     mean AO %.4f; noise: standard error mean %.5f, rms %.5f, 99th percentile %.5f, max %.5f\n",
                lmean, lse, std::sqrt(lse2), metrics::percentile(errs, 99.0), lse_max);
    std::printf("limit     vs V_R over all geometry: RMSE %.5f, PSNR %.2f dB, mean error %+.5f\n", st.rmse, st.psnr,
                st.mean_error);
    std::printf("time      limit %.2f s\n", limit.seconds);
}

}  // namespace

// Parse, load, trace (and the limit), write, report.
static int run(int argc, char** argv) {
    Options o;
    std::string error;
    switch (parse(argc, argv, o, error)) {
        case Parse::Help: std::fputs(help_text().c_str(), stdout); return 0;
        case Parse::Version: std::printf("%s\n", flags::version_line("ssao-reference").c_str()); return 0;
        case Parse::Error: flags::print_error("ssao-reference", error); return 2;
        case Parse::Run: break;
    }
    try {
        const Setup setup = load(o);
        if (!make_dirs(o.out_dir, error)) throw Failure(error);
        const raytrace::Image img = trace(o, setup);
        const depth_limit::Options lo = limit_options(o, setup);
        const depth_limit::Image limit = o.limit ? compute_limit(o, setup, lo, img) : depth_limit::Image{};
        const std::vector<std::string> written = write_outputs(o, setup, img, lo, limit);
        report_reference(o, img);
        if (o.limit) report_limit(img, limit);
        for (const auto& p : written) std::printf("wrote     %s\n", p.c_str());
    } catch (const Failure& f) {
        std::fprintf(stderr, "ssao-reference: error: %s\n", f.what());
        return 1;
    }
    return 0;
}

// Images are allocated at the requested size, so a large --width/--height (or
// a huge input) can run out of memory: say so instead of aborting.
int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::fputs("ssao-reference: error: out of memory (the image size or the scene is too large for this machine).\n", stderr);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ssao-reference: error: unexpected failure (%s).\n", e.what());
    }
    return 1;
}
