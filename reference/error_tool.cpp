// ssao-error: compares an AO image with the ray-traced reference.
//
//   ssao-error TEST.exr REF [--ref-stderr FILE] [--ref-depth FILE] [--band K] [--csv FILE] [--label TEXT]
//
// REF is reference_ao.exr or the folder ssao-reference wrote (then
// reference_stderr.exr and reference_depth.exr are picked up from it when
// present). The tested AO is read from channel Y, else R, else the file's first
// channel. Sky is excluded: reference pixels with A = 0 (or a non-finite Y).
// Prints RMSE, PSNR (peak 1), mean signed error, 99th percentile and max of
// |error| over the masks all / interior / silhouette band / screen-border band,
// with the reference's own noise floor; --csv appends the same rows to FILE.
#include "image_io.h"
#include "metrics.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <new>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace {

const char* kHelp =
    "ssao-error - error of an AO image against the ray-traced reference.\n"
    "\n"
    "usage: ssao-error TEST.exr REF [flags]\n"
    "  TEST.exr          AO under test (channel Y, else R, else the first channel), values in [0,1]\n"
    "  REF               reference_ao.exr from ssao-reference, or the folder it wrote\n"
    "  --ref-stderr FILE reference standard-error EXR (default: REF folder's reference_stderr.exr)\n"
    "  --ref-depth FILE  reference view-depth EXR for the silhouette band (default: REF folder's\n"
    "                    reference_depth.exr; without it, edges come from sky and AO steps)\n"
    "  --band K          width in pixels of the silhouette and screen-border bands, 0..256 (default 3)\n"
    "  --csv FILE        append one row per mask to FILE (header written when FILE is new)\n"
    "  --label TEXT      first CSV column (default: TEST's path)\n"
    "  --help            this text\n"
    "\n"
    "Masks (sky always excluded): all; silhouette = within K px of a depth discontinuity or sky edge;\n"
    "border = within K px of the image edge; interior = the rest. 'ref noise' is the mean reference\n"
    "standard error and 'noise rms' the RMSE its noise alone would give: errors near it are noise.\n";

bool is_dir(const std::string& p) {
    struct stat st;
    return stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}
bool is_file(const std::string& p) {
    struct stat st;
    return stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

int usage_error(const std::string& m) {
    std::fprintf(stderr, "ssao-error: %s (see --help).\n", m.c_str());
    return 2;
}

}  // namespace

static int run(int argc, char** argv) {
    std::vector<std::string> positional;
    std::string stderr_path, depth_path, csv_path, label;
    int band = 3;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        std::string value;
        bool has_value = false;
        const size_t eq = a.find('=');
        if (a.rfind("--", 0) == 0 && eq != std::string::npos) {
            value = a.substr(eq + 1);
            a = a.substr(0, eq);
            has_value = true;
        }
        if (a == "--help" || a == "-h") {
            std::fputs(kHelp, stdout);
            return 0;
        }
        if (a == "--ref-stderr" || a == "--ref-depth" || a == "--band" || a == "--csv" || a == "--label") {
            if (!has_value) {
                if (i + 1 >= argc) return usage_error(a + " needs a value");
                value = argv[++i];
            }
            if (a == "--ref-stderr") stderr_path = value;
            else if (a == "--ref-depth") depth_path = value;
            else if (a == "--csv") csv_path = value;
            else if (a == "--label") label = value;
            else {
                char* end = nullptr;
                errno = 0;
                const long v = std::strtol(value.c_str(), &end, 10);
                if (value.empty() || *end != '\0' || errno == ERANGE || v < 0 || v > 256)
                    return usage_error("--band expects a whole number 0..256, got '" + value + "'");
                band = int(v);
            }
            continue;
        }
        if (a.size() > 1 && a[0] == '-') return usage_error("unknown flag '" + a + "'");
        positional.push_back(a);
    }
    if (positional.size() != 2) return usage_error("expected two images, TEST.exr and REF, got " + std::to_string(positional.size()));
    const std::string test_path = positional[0];
    std::string ref_path = positional[1];
    if (is_dir(ref_path)) {
        const std::string dir = ref_path;
        ref_path = dir + "/reference_ao.exr";
        if (stderr_path.empty() && is_file(dir + "/reference_stderr.exr")) stderr_path = dir + "/reference_stderr.exr";
        if (depth_path.empty() && is_file(dir + "/reference_depth.exr")) depth_path = dir + "/reference_depth.exr";
    }
    if (label.empty()) label = test_path;

    std::string error, channel;
    int tw = 0, th = 0, rw = 0, rh = 0, w = 0, h = 0;
    std::vector<float> test, ref, cover, se, depth;
    if (!refio::read_exr_channel(test_path, {"Y", "R", "AO"}, test, tw, th, error, &channel)) {
        std::fprintf(stderr, "ssao-error: %s\n", error.c_str());
        return 1;
    }
    if (!refio::read_exr_channel(ref_path, {"Y"}, ref, rw, rh, error)) {
        std::fprintf(stderr, "ssao-error: %s\n", error.c_str());
        return 1;
    }
    if (tw != rw || th != rh) {
        std::fprintf(stderr, "ssao-error: %s is %dx%d but the reference %s is %dx%d.\n", test_path.c_str(), tw, th,
                     ref_path.c_str(), rw, rh);
        return 1;
    }
    const bool has_cover = refio::exr_has_channel(ref_path, "A");
    if (has_cover && !refio::read_exr_channel(ref_path, {"A"}, cover, w, h, error)) {
        std::fprintf(stderr, "ssao-error: %s\n", error.c_str());
        return 1;
    }
    if (!stderr_path.empty()) {
        if (!refio::read_exr_channel(stderr_path, {"Y"}, se, w, h, error)) {
            std::fprintf(stderr, "ssao-error: %s\n", error.c_str());
            return 1;
        }
        if (w != rw || h != rh) {
            std::fprintf(stderr, "ssao-error: %s is %dx%d, not %dx%d like the reference.\n", stderr_path.c_str(), w, h, rw, rh);
            return 1;
        }
    }
    if (!depth_path.empty()) {
        if (!refio::read_exr_channel(depth_path, {"Z", "Y", "R"}, depth, w, h, error)) {
            std::fprintf(stderr, "ssao-error: %s\n", error.c_str());
            return 1;
        }
        if (w != rw || h != rh) {
            std::fprintf(stderr, "ssao-error: %s is %dx%d, not %dx%d like the reference.\n", depth_path.c_str(), w, h, rw, rh);
            return 1;
        }
    }

    metrics::Inputs in;
    in.width = rw;
    in.height = rh;
    in.test = &test;
    in.reference = &ref;
    in.sky = has_cover ? &cover : nullptr;
    in.std_error = se.empty() ? nullptr : &se;
    in.depth = depth.empty() ? nullptr : &depth;
    in.band = band;
    std::vector<metrics::Stats> stats;
    if (!metrics::compute(in, stats, error)) {
        std::fprintf(stderr, "ssao-error: %s.\n", error.c_str());
        return 1;
    }

    std::printf("test       %s (channel %s), %dx%d\n", test_path.c_str(), channel.c_str(), tw, th);
    std::printf("reference  %s%s%s\n", ref_path.c_str(), se.empty() ? ", no standard-error image" : "",
                depth.empty() ? ", silhouettes from sky/AO edges" : ", silhouettes from its depth");
    std::printf("bands      %d px\n\n", band);
    std::fputs(metrics::table(stats).c_str(), stdout);
    if (!stats.empty() && stats[0].non_finite > 0)
        std::printf("\nwarning: %zu geometry pixels of the tested image are NaN or infinite (not compared).\n",
                    stats[0].non_finite);

    if (!csv_path.empty()) {
        const bool fresh = !is_file(csv_path);
        std::ofstream csv(csv_path, std::ios::app);
        if (!csv) {
            std::fprintf(stderr, "ssao-error: cannot write %s.\n", csv_path.c_str());
            return 1;
        }
        if (fresh) csv << metrics::csv_header();
        csv << metrics::csv_rows(stats, label);
        if (!csv) {
            std::fprintf(stderr, "ssao-error: cannot write %s.\n", csv_path.c_str());
            return 1;
        }
    }
    return 0;
}

// Images are allocated at the requested size, so a large --width/--height (or
// a huge input) can run out of memory: say so instead of aborting.
int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::fputs("ssao-error: out of memory (the images are too large for this machine).\n", stderr);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ssao-error: unexpected failure (%s).\n", e.what());
    }
    return 1;
}
