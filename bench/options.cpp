#include "options.h"

#include "depth_limit.h"
#include "flags.h"
#include "locate.h"

namespace bench {

std::string help_text() {
    return "ssao-bench - what accuracy costs in time: error against ray-traced V_R and against the\n"
           "depth-only limit, GPU time against the textbook pass and the bandwidth floor, one run.\n"
           "\n"
           "usage: ssao-bench [options] [scene.glb|scene.gltf ...]\n"
           "  --width N --height N   base size, 8..4096 (default 320 x 180): the whole sweep, errors, presets\n"
           "  --scales LIST          multiples of the base size timed for the scaling table, e.g. 1,2,4\n"
           "                         (default 1,2,4: 320x180, 640x360, 1280x720)\n"
           "  --frames N             timed frames per configuration (default 15), after\n"
           "  --warmup N             untimed frames (default 4)\n"
           "  --reference-samples N  rays per pixel of the ground truth (default 512)\n"
           "  --limit-directions N   directions per pixel of the depth-only limit, a multiple of " +
           std::to_string(depth_limit::kReplicas) + " (default " + std::to_string(depth_limit::kDefaultDirections) +
           ")\n"
           "  --out DIR              where results go (default bench-out)\n"
           "  --quick                fewer frames, rays and directions, base size only\n"
           "  --plugin PATH          libssao.so to load (default: as ssao-host finds it)\n"
           "  --normals gbuffer|depth  the plugin's normals: the G-buffer's, or depth: normal_texture = 0, the\n"
           "                         plugin rebuilds them from depth (default gbuffer)\n"
           "  --allow-outside-files  let the scenes' buffer URIs name files outside their folders\n"
           "                         (absolute paths, '..', symbolic links leading out); refused by default\n"
           "  --help, -h / --version this text / the version\n"
           "Scenes default to the bundled spot and teapot models and scenes/corner.gltf.\n";
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

}  // namespace

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
        {"--normals", [&](const std::string& f, const std::string& v) {
             if (v != "gbuffer" && v != "depth") flags::fail(f + " expects one of gbuffer|depth, got " + flags::quoted(v));
             o.normals_from_depth = v == "depth";
         }},
    };
    const flags::Switches switches = {
        {"--allow-outside-files", [&] { o.allow_outside_files = true; }},
        {"--quick", [&] {
             o.frames = 5;
             o.warmup = 2;
             o.reference_samples = 128;
             o.limit_directions = 64;
             o.scales = {1};
         }},
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

}  // namespace bench
