// measure.h - one scene at one size: for every view and radius the ground
// truth (ray-traced V_R), the depth-only limit over the same depth layer, the
// host's G-buffer, and for each configuration its process CPU time, GPU time
// and wall time (interleaved over rounds, bench/timing.h) and its error
// against both; the textbook pass and the bandwidth floor are timed beside
// them, the same way.
#pragma once

#include "metrics.h"
#include "scene.h"
#include "options.h"
#include "sweep.h"
#include "views.h"

#include <ssao/ssao.h>

#include <string>
#include <vector>

namespace bench {

struct Row {
    std::string scene, config;
    View view = View::standard;
    float radius_scale = 1.0f;     // x the scene's AO radius
    float radius = 0.0f;           // the radius this row ran at (scene units)
    Family family = Family::kernel;
    enum class Kind { plugin, textbook, floor, limit } kind = Kind::plugin;
    int width = 0, height = 0;
    ssao_settings s{};             // resolved (plugin rows)
    double median_ms = 0, p10_ms = 0, p90_ms = 0;  // GPU timestamps over all timed frames; NaN for the limit
    // Median wall time from submission to glFinish returning. On llvmpipe the
    // CPU is the device, and a pass's closing timestamp does not wait for its
    // rasteriser, so this is the cost a user sees there; on a GPU it adds the
    // round trip.
    double wall_ms = 0;
    // This process's CPU time per frame over the same interval: the median
    // over rounds of each round's mean, and the lowest and highest round.
    double cpu_ms = 0, cpu_min_ms = 0, cpu_max_ms = 0;
    int rounds = 0;
    bool has_error = false;        // errors measured (base size only)
    metrics::Stats all, interior, silhouette, border;  // against V_R
    metrics::Stats vs_limit;       // against the depth-only limit (all pixels)
    double cell_spread = 0;        // metrics::cell_spread of the error against V_R (the fixed pattern)
    std::vector<double> cell_pattern;  // metrics::cell_pattern of that error (8 x 8), for the patterns cases share
    double bias_occluded = 0;      // metrics::occluded_bias: where V_R < 0.5 (contact shadows, creases)
    bool variant = false;  // a sweep configuration with a setting no preset carries: its own thickness or rotation
};

// A scene the benchmark can measure: loaded, with an extent to scale the
// radius to. Throws std::runtime_error naming the file.
struct LoadedScene {
    std::string path;
    scene::Scene sc;
};
LoadedScene load_scene(const std::string& path, const Options& o);

// Measures every view in o.views of one scene at o.width/height x scale and
// appends the rows. with_errors (the base size): every radius in
// o.radius_scales, with the reference and the limit traced and the errors
// filled; otherwise the 1x radius only, timing alone. `sweep` runs on the
// standard view at 1x radius with errors; `presets`, the textbook pass and the
// floor on every view and radius.
void measure_scene(const LoadedScene& scene, const Options& o, int scale, const ssao_api& api,
                   const std::vector<Config>& sweep, const std::vector<Config>& presets, bool with_errors,
                   std::vector<Row>& rows);

}  // namespace bench
