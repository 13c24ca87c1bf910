// measure.h - one scene at one size: the ground truth (ray-traced V_R), the
// depth-only limit over the same depth layer, the host's G-buffer, and for
// each configuration the plugin's GPU time and its error against both; the
// textbook pass and the bandwidth floor are timed beside them.
#pragma once

#include "metrics.h"
#include "options.h"
#include "sweep.h"

#include <ssao/ssao.h>

#include <string>
#include <vector>

namespace bench {

struct Row {
    std::string scene, config;
    Family family = Family::kernel;
    enum class Kind { plugin, textbook, floor, limit } kind = Kind::plugin;
    int width = 0, height = 0;
    ssao_settings s{};             // resolved (plugin rows)
    double median_ms = 0, p10_ms = 0, p90_ms = 0;  // GPU timestamps; NaN for the limit
    // Median wall time from submission to glFinish returning. On llvmpipe the
    // CPU is the device, and a pass's closing timestamp does not wait for its
    // rasteriser, so this is the cost a user sees there; on a GPU it adds the
    // round trip.
    double wall_ms = 0;
    bool has_error = false;        // errors measured (base size only)
    metrics::Stats all, interior, silhouette, border;  // against V_R
    metrics::Stats vs_limit;       // against the depth-only limit (all pixels)
};

// Measures `configs` (empty at the larger sizes: presets only) and appends the
// rows. with_errors: trace the reference and the limit and fill the errors.
void measure_scene(const std::string& path, const Options& o, int scale, const ssao_api& api,
                   const std::vector<Config>& configs, bool with_errors, std::vector<Row>& rows);

}  // namespace bench
