#include "options.h"

#include "depth_limit.h"
#include "flags.h"
#include "locate.h"
#include "views.h"

#include <ssao/ssao.h>

#include <algorithm>
#include <set>
#include <sstream>

namespace bench {

namespace {

// The plugin's bound on max_step_texels as the help and the errors print it.
std::string max_step_texels_text() {
    std::ostringstream s;
    s << SSAO_MAX_STEP_TEXELS;
    return s.str();
}

}  // namespace

std::string help_text() {
    return "ssao-bench - what accuracy costs in time: error against ray-traced V_R and against the\n"
           "depth-only limit, process CPU time against the textbook pass and the bandwidth floor, one run.\n"
           "\n"
           "usage: ssao-bench [options] [scene.glb|scene.gltf ...]\n"
           "  --width N --height N   base size, 8..4096 (default 320 x 180): the whole sweep, errors, presets\n"
           "  --scales LIST          multiples of the base size timed for the scaling table, e.g. 1,2,4\n"
           "                         (default 1,2,4: 320x180, 640x360, 1280x720; larger sizes at 1x radius)\n"
           "  --views LIST           views of every scene, from standard,high,close-up (default all three)\n"
           "  --radii LIST           multiples of each scene's AO radius, 0.05..20 (default 0.5,1,2)\n"
           "  --sweep full|presets   full: the whole configuration sweep on the standard view at 1x radius\n"
           "                         (default); presets: the shipped presets only\n"
           "  --rounds N             timing rounds, 3..1000 (default 3): each round times every\n"
           "                         configuration in turn, figures are medians over rounds\n"
           "  --frames N             timed frames per configuration per round (default 5), after\n"
           "  --warmup N             untimed frames per configuration per round (default 2); at k x the\n"
           "                         base size 1/k of each, at least 1\n"
           "  --reference-samples N  rays per pixel of the ground truth, standard view at 1x radius (default 512)\n"
           "  --limit-directions N   directions per pixel of the depth-only limit there, a multiple of " +
           std::to_string(depth_limit::kReplicas) + " (default " + std::to_string(depth_limit::kDefaultDirections) +
           ")\n"
           "  --extra-samples N      rays per pixel on the other views and radii (default 128)\n"
           "  --extra-directions N   limit directions on the other views and radii (default 128)\n"
           "  --out DIR              where results go (default bench-out)\n"
           "  --quick                one timed frame a round, fewer rays and directions, base size only\n"
           "                         (defaults: a flag given beside it wins)\n"
           "  --time-only            the timing part alone: presets, textbook pass and floor at every size\n"
           "                         and view (1x radius), no ground truth, no limit, no errors; GPU-timer\n"
           "                         ratios beside the CPU ones (for a real GPU)\n"
           "  --plugin PATH          libssao.so to load (default: as ssao-host finds it)\n"
           "  --max-step-texels X    every visibility configuration's max_step_texels, (0, " + max_step_texels_text() +
           "] (default: off,\n"
           "                         each configuration's step count fixed)\n"
           "  --normals gbuffer|depth  the plugin's normals: the G-buffer's, or depth: normal_texture = 0, the\n"
           "                         plugin rebuilds them from depth (default gbuffer)\n"
           "  --average-frames N     the plugin's errors from its mean AO over frame indices 1..N, what a TAA\n"
           "                         host converges to, 1..1024 (default 1: one frame, frame index 0); its\n"
           "                         timing then runs frame index 1\n"
           "  --allow-outside-files  let the scenes' buffer URIs name files outside their folders\n"
           "                         (absolute paths, '..', symbolic links leading out); refused by default\n"
           "  --help, -h / --version this text / the version\n"
           "Scenes default to the bundled spot and teapot models and scenes/corner, overhang, creases and\n"
           "clutter.gltf. Time is this process's CPU time per frame (submission to glFinish); the run sets\n"
           "LP_NUM_THREADS=1 (llvmpipe renders on one thread) unless the environment sets it. GPU timers\n"
           "and wall clock are reported beside it; every ratio and target uses CPU time.\n";
}

std::vector<std::string> default_scenes() {
    std::vector<std::string> out;
    for (const std::string& f : scene_files()) out.push_back(locate::bundled(f));
    return out;
}

namespace {

std::vector<int> scale_list(const std::string& flag, const std::string& v) {
    std::vector<int> out;
    size_t start = 0;
    while (start <= v.size()) {
        const size_t comma = v.find(',', start);
        const std::string item = v.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        out.push_back(int(flags::integer(flag, item, 1, 16)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (out.empty() || out.front() != 1) flags::fail(flag + " must start with 1 (the base size), got " + flags::quoted(v));
    return out;
}

std::vector<std::string> split(const std::string& v) {
    std::vector<std::string> out;
    size_t start = 0;
    while (true) {
        const size_t comma = v.find(',', start);
        out.push_back(v.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos) return out;
        start = comma + 1;
    }
}

std::vector<View> view_list(const std::string& flag, const std::string& v) {
    std::vector<View> out;
    for (const std::string& item : split(v)) {
        bool known = false;
        for (View view : all_views())
            if (item == view_name(view)) {
                if (std::find(out.begin(), out.end(), view) == out.end()) out.push_back(view);
                known = true;
            }
        if (!known) flags::fail(flag + " expects views from standard,high,close-up, got " + flags::quoted(item));
    }
    return out;
}

std::vector<float> radius_list(const std::string& flag, const std::string& v) {
    std::vector<float> out;
    for (const std::string& item : split(v)) {
        const double r = flags::number(flag, item);
        if (!(r >= 0.05 && r <= 20.0)) flags::fail(flag + " expects multiples of the radius in 0.05..20, got " + flags::quoted(item));
        out.push_back(static_cast<float>(r));
    }
    return out;
}

}  // namespace

Parse parse(int argc, char** argv, Options& o, std::string& error) {
    auto whole = [](int& out, long long lo, long long hi) {
        return [&out, lo, hi](const std::string& f, const std::string& v) { out = int(flags::integer(f, v, lo, hi)); };
    };
    const flags::Valued valued = {
        {"--width", whole(o.width, 8, 4096)},
        {"--height", whole(o.height, 8, 4096)},
        {"--frames", whole(o.frames, 1, 10000)},
        {"--rounds", whole(o.rounds, 3, 1000)},
        {"--extra-samples", whole(o.extra_samples, 16, 1 << 20)},
        {"--extra-directions", [&](const std::string& f, const std::string& v) {
             o.extra_directions = int(flags::integer(f, v, depth_limit::kReplicas, 1 << 16));
             if (o.extra_directions % depth_limit::kReplicas != 0)
                 flags::fail(f + " must be a multiple of " + std::to_string(depth_limit::kReplicas));
         }},
        {"--views", [&](const std::string& f, const std::string& v) { o.views = view_list(f, v); }},
        {"--radii", [&](const std::string& f, const std::string& v) { o.radius_scales = radius_list(f, v); }},
        {"--sweep", [&](const std::string& f, const std::string& v) {
             if (v != "full" && v != "presets") flags::fail(f + " expects one of full|presets, got " + flags::quoted(v));
             o.full_sweep = v == "full";
         }},
        {"--warmup", whole(o.warmup, 0, 10000)},
        {"--reference-samples", whole(o.reference_samples, 16, 1 << 20)},
        {"--limit-directions", [&](const std::string& f, const std::string& v) {
             o.limit_directions = int(flags::integer(f, v, depth_limit::kReplicas, 1 << 16));
             if (o.limit_directions % depth_limit::kReplicas != 0)
                 flags::fail(f + " must be a multiple of " + std::to_string(depth_limit::kReplicas));
         }},
        {"--scales", [&](const std::string& f, const std::string& v) { o.scales = scale_list(f, v); }},
        {"--out", [&](const std::string& f, const std::string& v) {
             if (v.empty()) flags::fail(f + " needs a folder name");
             o.out = v;
         }},
        {"--plugin", [&](const std::string& f, const std::string& v) {
             if (v.empty()) flags::fail(f + " expects a path to libssao.so");
             o.plugin = v;
         }},
        {"--max-step-texels", [&](const std::string& f, const std::string& v) {
             const double x = flags::number(f, v);
             if (!(x > 0.0 && x <= SSAO_MAX_STEP_TEXELS))
                 flags::fail(f + " must be in (0, " + max_step_texels_text() + "], got " + flags::quoted(v));
             flags::check_normal_float(f, v, x);
             o.max_step_texels = static_cast<float>(x);
         }},
        {"--average-frames", whole(o.average_frames, 1, 1024)},
        {"--normals", [&](const std::string& f, const std::string& v) {
             if (v != "gbuffer" && v != "depth") flags::fail(f + " expects one of gbuffer|depth, got " + flags::quoted(v));
             o.normals_from_depth = v == "depth";
         }},
    };
    // --quick sets defaults: a flag given beside it wins wherever it stands.
    std::set<std::string> given;
    flags::Valued recorded;
    for (const auto& [flag, take] : valued)
        recorded[flag] = [&given, take = take](const std::string& f, const std::string& v) {
            given.insert(f);
            take(f, v);
        };
    bool quick = false;
    const flags::Switches switches = {
        {"--allow-outside-files", [&] { o.allow_outside_files = true; }},
        {"--time-only", [&] { o.time_only = true; }},
        {"--quick", [&] { quick = true; }},
    };
    const Parse parsed = flags::parse(argc, argv, recorded, switches,
                                      [&](const std::string& a) { o.scenes.push_back(a); }, error);
    if (quick) {
        const auto unless_given = [&](const char* flag, auto& field, auto value) {
            if (!given.count(flag)) field = value;
        };
        unless_given("--frames", o.frames, 1);
        unless_given("--warmup", o.warmup, 1);
        unless_given("--rounds", o.rounds, 3);
        unless_given("--reference-samples", o.reference_samples, 128);
        unless_given("--limit-directions", o.limit_directions, 64);
        unless_given("--extra-samples", o.extra_samples, 32);
        unless_given("--extra-directions", o.extra_directions, 16);
        unless_given("--scales", o.scales, std::vector<int>{1});
    }
    if (o.scenes.empty()) o.scenes = default_scenes();
    return parsed;
}

}  // namespace bench
