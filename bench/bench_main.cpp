// ssao-bench - what accuracy costs in time. For each scene it ray-traces the
// ground truth (Embree, V_R with R = the plugin's radius) and the depth-only
// limit over the same depth layer, renders the host's G-buffer, then for every
// configuration of a sweep measures the plugin's GPU time (median of its own
// timer queries over many frames after warm-up) and its error against both;
// the chapter's textbook pass and the bandwidth floor run in the same process
// as the anchors. The presets are also timed at larger sizes (the scaling
// table). A benchmark, not a test: nothing here asserts, it measures and reports.
#include "flags.h"
#include "measure.h"
#include "options.h"
#include "plugin_loader.h"
#include "report.h"
#include "sweep.h"

#include <cstdio>
#include <stdexcept>

int main(int argc, char** argv) {
    bench::Options o;
    std::string error;
    switch (bench::parse(argc, argv, o, error)) {
        case bench::Parse::Error: std::fprintf(stderr, "ssao-bench: error: %s\n", error.c_str()); return 2;
        case bench::Parse::Help: std::fputs(bench::help_text().c_str(), stdout); return 0;
        case bench::Parse::Version: std::printf("%s\n", flags::version_line("ssao-bench").c_str()); return 0;
        case bench::Parse::Run: break;
    }
    try {
        plugin::Library lib;
        if (!lib.open_default(o.plugin, error)) throw std::runtime_error(error);
        std::vector<bench::Config> base = bench::sweep();
        const std::vector<bench::Config> presets = bench::shipped_presets();
        base.insert(base.end(), presets.begin(), presets.end());
        std::vector<bench::Row> rows;
        for (const std::string& scene : o.scenes)
            for (int scale : o.scales) {
                std::fprintf(stderr, "scene %s at %dx%d\n", scene.c_str(), o.width * scale, o.height * scale);
                bench::measure_scene(scene, o, scale, lib.api(), scale == 1 ? base : presets, scale == 1, rows);
            }
        bench::write_report(o, rows);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ssao-bench: error: %s\n", e.what());
        return 1;
    }
    return 0;
}
