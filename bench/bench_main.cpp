// ssao-bench - what accuracy costs in time. For each scene it ray-traces the
// ground truth (Embree, V_R with R = the plugin's radius) and the depth-only
// limit over the same depth layer, renders the host's G-buffer, then for every
// configuration measures the process CPU time per frame (configurations
// interleaved over rounds), the GPU timers and the wall clock, and its error
// against both; the chapter's textbook pass and the bandwidth floor run in the
// same process as the anchors. The whole sweep runs on the standard view at
// the scene's radius; the presets, the anchors and the references on every
// view (standard, high, close-up) and radius (0.5x, 1x, 2x). The presets are
// also timed at larger sizes (the scaling table). A benchmark, not a test: nothing here asserts, it measures and reports.
#include "flags.h"
#include "measure.h"
#include "options.h"
#include "plugin_loader.h"
#include "report.h"
#include "sweep.h"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace {

// Traces and measures every scene at every size, then writes the report.
int run(bench::Options& o) {
    // llvmpipe reads LP_NUM_THREADS when the driver loads (the first EGL
    // context): one rasteriser thread makes the process's CPU time per frame
    // the work of the pass, not of idle threads woken and waited for.
    if (const char* lp = std::getenv("LP_NUM_THREADS"); lp && *lp)
        o.lp_num_threads = lp;
    else {
        setenv("LP_NUM_THREADS", "1", 1);
        o.lp_num_threads = "1";
    }
    plugin::Library lib;
    std::string error;
    if (!lib.open_default(o.plugin, error)) throw std::runtime_error(error);
    // What can fail before minutes of measuring does: every scene, then the
    // output folder (made only for a run that can measure).
    std::vector<bench::LoadedScene> scenes;
    for (const std::string& path : o.scenes) scenes.push_back(bench::load_scene(path, o));
    bench::prepare_output(o);
    const std::vector<bench::Config> sweep = bench::sweep();
    const std::vector<bench::Config> presets = bench::shipped_presets();
    std::vector<bench::Row> rows;
    for (const bench::LoadedScene& scene : scenes)
        for (int scale : o.scales) {
            std::fprintf(stderr, "scene %s at %dx%d\n", scene.path.c_str(), o.width * scale, o.height * scale);
            bench::measure_scene(scene, o, scale, lib.api(), sweep, presets, scale == 1 && !o.time_only, rows);
        }
    bench::write_report(o, rows);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    bench::Options o;
    std::string error;
    const bench::Parse parsed = bench::parse(argc, argv, o, error);
    return flags::finish_main("ssao-bench", parsed, error, [] { return bench::help_text(); }, [&] { return run(o); });
}
