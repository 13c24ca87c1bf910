// options.h - ssao-bench's command line (the tools' shared parser, host/flags.h).
#pragma once

#include "flags.h"
#include "views.h"

#include <string>
#include <vector>

namespace bench {

struct Options {
    std::vector<std::string> scenes;
    int width = 320, height = 180;           // base size: the full sweep, errors and presets
    std::vector<int> scales = {1, 2, 4};     // x the base size: presets, textbook and floor timed (scaling table)
    // Timing: `rounds` rounds, each running every configuration in turn for
    // `warmup` untimed and `frames` timed frames (bench/timing.h); at k x the
    // base size 1/k of each (at least 1).
    int warmup = 2, frames = 5, rounds = 3;
    int reference_samples = 512;             // rays per pixel of V_R, standard view at 1x radius
    int limit_directions = 0;                // 0: depth_limit's default (standard view at 1x radius)
    int extra_samples = 128;                 // the same for every other view and radius
    int extra_directions = 128;
    std::vector<View> views = all_views();
    std::vector<float> radius_scales = bench::radius_scales();
    bool full_sweep = true;                  // false (--sweep presets): presets, textbook, floor and limit only
    // --time-only: the presets, the textbook pass and the floor timed at every
    // size and view (1x radius), nothing traced and no errors: the timing part
    // alone, for a real GPU where the tracing on the CPU would dominate the run.
    bool time_only = false;
    std::string out = "bench-out";
    std::string plugin;                      // empty: plugin::Library::search_order()
    bool normals_from_depth = false;         // --normals depth: every configuration gets normal_texture = 0
    float max_step_texels = 0.0f;            // --max-step-texels: every configuration's; 0 = off
    // --average-frames N > 1: the plugin's errors from the mean of its AO over
    // frame indices 1..N (rotation and jitter move with it: what a TAA host
    // converges to), and its timing with frame index 1 (so with the variants
    // a moving index runs); 1: one frame at frame index 0.
    int average_frames = 1;
    bool allow_outside_files = false;        // scenes' buffer URIs may leave their folders (host/scene_limits.h)
    std::string lp_num_threads;              // LP_NUM_THREADS the run had (set by main unless the user set it)
};

using Parse = flags::Outcome;

Parse parse(int argc, char** argv, Options& o, std::string& error);
std::string help_text();

// The bundled scenes a run measures when none is named.
std::vector<std::string> default_scenes();

}  // namespace bench
