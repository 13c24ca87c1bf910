// options.h - ssao-bench's command line (the tools' shared parser, host/flags.h).
#pragma once

#include <string>
#include <vector>

namespace bench {

struct Options {
    std::vector<std::string> scenes;
    int width = 320, height = 180;           // base size: the full sweep, errors and presets
    std::vector<int> scales = {1, 2, 4};     // x the base size: presets, textbook and floor timed (scaling table)
    int warmup = 4, frames = 15;
    int reference_samples = 512;
    int limit_directions = 0;                // 0: depth_limit's default
    std::string out = "bench-out";
    std::string plugin;                      // empty: plugin::Library::search_order()
    bool normals_from_depth = false;         // --normals depth: every configuration gets normal_texture = 0
    bool allow_outside_files = false;        // scenes' buffer URIs may leave their folders (host/scene_limits.h)
};

enum class Parse { Run, Help, Version, Error };

Parse parse(int argc, char** argv, Options& o, std::string& error);
std::string help_text();

}  // namespace bench
