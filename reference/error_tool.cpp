// ssao-error: compares an AO image with the ray-traced reference.
//
//   ssao-error TEST.exr REF [--ref-stderr FILE] [--ref-depth FILE] [--limit FILE] [--band K] [--csv FILE]
//              [--label TEXT]
//
// REF is reference_ao.exr or the folder ssao-reference wrote (then
// reference_stderr.exr, reference_depth.exr and limit_ao.exr are picked up from
// it when present). With the depth-only limit (ssao-reference --limit) every
// error is also split into limit vs V_R (what no depth-only method can avoid)
// and TEST vs limit (what the tested estimator adds). The tested AO is read from channel Y, else R, else the file's first
// channel. Sky is excluded: reference pixels with A = 0 (or, without A, a
// non-finite reference depth). Every value compared must be AO: finite and in
// [0, 1] up to aocheck::kAoTolerance, in the reference (wherever A is not 0)
// and in the test (where the reference has geometry); otherwise, or with no
// pixel to compare, ssao-error exits 1 with one line.
// Prints RMSE, PSNR (peak 1), mean signed error, 99th percentile and max of
// |error| over the masks all / interior / silhouette band / screen-border band,
// with the reference's own noise floor; --csv appends the same rows to FILE.
#include "ao_checks.h"
#include "flags.h"
#include "image_io.h"
#include "metrics.h"
#include "provenance.h"

#include <algorithm>
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
    "                    (finite, within 0.001; otherwise ssao-error refuses it, as it does a reference)\n"
    "  REF               reference_ao.exr from ssao-reference, or the folder it wrote\n"
    "  --ref-stderr FILE reference standard-error EXR (default: REF folder's reference_stderr.exr)\n"
    "  --ref-depth FILE  reference view-depth EXR for the silhouette band (default: REF folder's\n"
    "                    reference_depth.exr; without it, edges come from sky and AO steps)\n"
    "  --limit FILE      the depth-only limit (limit_ao.exr from ssao-reference --limit; default: REF\n"
    "                    folder's limit_ao.exr): also report limit vs V_R (what no depth-only method\n"
    "                    can avoid) and TEST vs limit (what the tested estimator adds)\n"
    "  --band K          width in pixels of the silhouette and screen-border bands, 0..256 (default 3)\n"
    "  --csv FILE        append one row per mask to FILE (header written when FILE is new)\n"
    "  --label TEXT      first CSV column (default: TEST's path)\n"
    "  --allow-mismatch  compare even when the images' headers say they were made with different\n"
    "                    scenes, sizes, cameras or radii (refused by default)\n"
    "  --help, -h        this text\n"
    "  --version         the version\n"
    "\n"
    "Masks (sky always excluded): all; silhouette = within K px of a depth discontinuity or sky edge;\n"
    "border = within K px of the image edge; interior = the rest. 'ref noise' is the mean reference\n"
    "standard error and 'noise rms' the RMSE its noise alone would give: errors near it are noise.\n"
    "\n"
    "ssao-host and ssao-reference record in their EXR headers what an image was made with (ssao:scene,\n"
    "size, projection, near, far, depth, eye, target, up, radius, thickness). ssao-error compares the\n"
    "fields both images carry (TEST and the limit against the reference; thickness, which the\n"
    "reference has not, is recorded but not compared) and refuses a difference, naming the field; an\n"
    "image without them (an older file, another program) is compared unchecked, with a note.\n";

bool is_dir(const std::string& p) {
    struct stat st;
    return stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}
bool is_file(const std::string& p) {
    struct stat st;
    return stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

int usage_error(const std::string& m) {
    std::fprintf(stderr, "ssao-error: error: %s (see --help).\n", m.c_str());
    return 2;
}

}  // namespace

static int run(int argc, char** argv) {
    std::vector<std::string> positional;
    std::string stderr_path, depth_path, limit_path, csv_path, label;
    int band = 3;
    bool allow_mismatch = false;
    // The shared parser (host/flags.h): --flag value and --flag=value alike.
    const flags::Valued valued = {
        {"--ref-stderr", [&](const std::string&, const std::string& v) { stderr_path = v; }},
        {"--ref-depth", [&](const std::string&, const std::string& v) { depth_path = v; }},
        {"--limit", [&](const std::string&, const std::string& v) { limit_path = v; }},
        {"--csv", [&](const std::string&, const std::string& v) { csv_path = v; }},
        {"--label", [&](const std::string&, const std::string& v) { label = v; }},
        {"--band", [&](const std::string& f, const std::string& v) { band = int(flags::integer(f, v, 0, 256)); }},
    };
    try {
        const flags::Switches switches = {{"--allow-mismatch", [&] { allow_mismatch = true; }}};
        switch (flags::walk(argc, argv, valued, switches, [&](const std::string& a) { positional.push_back(a); })) {
            case flags::Outcome::Help: std::fputs(kHelp, stdout); return 0;
            case flags::Outcome::Version: std::printf("%s\n", flags::version_line("ssao-error").c_str()); return 0;
            case flags::Outcome::Run: break;
        }
    } catch (const flags::Error& e) {
        std::fprintf(stderr, "ssao-error: error: %s.\n", e.message.c_str());  // the message names --help already
        return 2;
    }
    if (positional.size() != 2) return usage_error("expected two images, TEST.exr and REF, got " + std::to_string(positional.size()));
    const std::string test_path = positional[0];
    std::string ref_path = positional[1];
    if (is_dir(ref_path)) {
        const std::string dir = ref_path;
        ref_path = dir + "/reference_ao.exr";
        if (stderr_path.empty() && is_file(dir + "/reference_stderr.exr")) stderr_path = dir + "/reference_stderr.exr";
        if (depth_path.empty() && is_file(dir + "/reference_depth.exr")) depth_path = dir + "/reference_depth.exr";
        if (limit_path.empty() && is_file(dir + "/limit_ao.exr")) limit_path = dir + "/limit_ao.exr";
    }
    if (label.empty()) label = test_path;

    std::string error, channel;
    int tw = 0, th = 0, rw = 0, rh = 0, w = 0, h = 0;
    std::vector<float> test, ref, cover, se, depth;
    if (!refio::read_exr_channel(test_path, {"Y", "R", "AO"}, test, tw, th, error, &channel)) {
        std::fprintf(stderr, "ssao-error: error: %s\n", error.c_str());
        return 1;
    }
    if (!refio::read_exr_channel(ref_path, {"Y"}, ref, rw, rh, error)) {
        std::fprintf(stderr, "ssao-error: error: %s\n", error.c_str());
        return 1;
    }
    if (tw != rw || th != rh) {
        std::fprintf(stderr, "ssao-error: error: %s is %dx%d but the reference %s is %dx%d.\n", test_path.c_str(), tw, th,
                     ref_path.c_str(), rw, rh);
        return 1;
    }
    const bool has_cover = refio::exr_has_channel(ref_path, "A");
    if (has_cover && !refio::read_exr_channel(ref_path, {"A"}, cover, w, h, error)) {
        std::fprintf(stderr, "ssao-error: error: %s\n", error.c_str());
        return 1;
    }
    if (!stderr_path.empty()) {
        if (!refio::read_exr_channel(stderr_path, {"Y"}, se, w, h, error)) {
            std::fprintf(stderr, "ssao-error: error: %s\n", error.c_str());
            return 1;
        }
        if (w != rw || h != rh) {
            std::fprintf(stderr, "ssao-error: error: %s is %dx%d, not %dx%d like the reference.\n", stderr_path.c_str(), w, h, rw, rh);
            return 1;
        }
    }
    if (!depth_path.empty()) {
        if (!refio::read_exr_channel(depth_path, {"Z", "Y", "R"}, depth, w, h, error)) {
            std::fprintf(stderr, "ssao-error: error: %s\n", error.c_str());
            return 1;
        }
        if (w != rw || h != rh) {
            std::fprintf(stderr, "ssao-error: error: %s is %dx%d, not %dx%d like the reference.\n", depth_path.c_str(), w, h, rw, rh);
            return 1;
        }
    }

    // The limit: same size, and the same coverage (it must come from the same scene and camera).
    std::vector<float> limit, limit_cover, limit_se;
    if (!limit_path.empty()) {
        if (!refio::read_exr_channel(limit_path, {"Y"}, limit, w, h, error)) {
            std::fprintf(stderr, "ssao-error: error: %s\n", error.c_str());
            return 1;
        }
        if (w != rw || h != rh) {
            std::fprintf(stderr, "ssao-error: error: %s is %dx%d, not %dx%d like the reference.\n", limit_path.c_str(), w, h, rw, rh);
            return 1;
        }
        if (has_cover && refio::exr_has_channel(limit_path, "A")) {
            if (!refio::read_exr_channel(limit_path, {"A"}, limit_cover, w, h, error)) {
                std::fprintf(stderr, "ssao-error: error: %s\n", error.c_str());
                return 1;
            }
            size_t differ = 0;
            for (size_t i = 0; i < cover.size(); ++i) differ += (cover[i] > 0.5f) != (limit_cover[i] > 0.5f);
            if (differ > 0) {
                std::fprintf(stderr,
                             "ssao-error: error: %s covers other pixels than the reference (%zu differ): it is not from the "
                             "same scene and camera.\n",
                             limit_path.c_str(), differ);
                return 1;
            }
        }
        const std::string se_path = limit_path.substr(0, limit_path.rfind('/') + 1) + "limit_stderr.exr";
        if (limit_path.size() >= 12 && limit_path.compare(limit_path.size() - 12, 12, "limit_ao.exr") == 0 &&
            is_file(se_path) && (!refio::read_exr_channel(se_path, {"Y"}, limit_se, w, h, error) || w != rw || h != rh))
            limit_se.clear();  // the noise column is optional: without it, "-"
    }

    // The images must show the same thing: compare what their headers record.
    std::vector<std::string> bare;   // images that record nothing: compared unchecked
    {
        const std::string prefix = provenance::kPrefix;
        refio::Attributes test_made, ref_made, limit_made;
        if (!refio::read_exr_attributes(test_path, prefix, test_made, error) ||
            !refio::read_exr_attributes(ref_path, prefix, ref_made, error) ||
            (!limit_path.empty() && !refio::read_exr_attributes(limit_path, prefix, limit_made, error))) {
            std::fprintf(stderr, "ssao-error: error: %s\n", error.c_str());
            return 1;
        }
        struct Pair {
            const std::string* a_path;
            const refio::Attributes* a;
            const std::string* b_path;
            const refio::Attributes* b;
        };
        // Both against the reference, so TEST and the limit agree too on every
        // field all three carry. Thickness is not compared: the reference has
        // none, and the split measures an estimator's own thickness against
        // the limit's T (a different one is a finding, not a mistake).
        std::vector<Pair> pairs = {{&test_path, &test_made, &ref_path, &ref_made}};
        if (!limit_path.empty()) pairs.push_back({&limit_path, &limit_made, &ref_path, &ref_made});
        for (const Pair& p : pairs) {
            if (p.a->empty() || p.b->empty()) {
                for (const auto& [path, made] : {std::make_pair(p.a_path, p.a), std::make_pair(p.b_path, p.b)})
                    if (made->empty() && std::find(bare.begin(), bare.end(), *path) == bare.end()) bare.push_back(*path);
                continue;
            }
            const auto d = provenance::compare(*p.a, *p.b);
            if (d && !allow_mismatch) {
                std::fprintf(stderr,
                             "ssao-error: error: %s and %s were made with a different %s: %s vs %s (--allow-mismatch "
                             "compares them anyway).\n",
                             flags::printable(*p.a_path, 160).c_str(), flags::printable(*p.b_path, 160).c_str(),
                             flags::printable(d->field, 160).c_str(), flags::printable(d->a, 160).c_str(),
                             flags::printable(d->b, 160).c_str());
                return 1;
            }
            if (d)
                std::printf("mismatch   %s: %s vs %s, compared anyway (--allow-mismatch)\n",
                            flags::printable(d->field, 160).c_str(), flags::printable(d->a, 160).c_str(),
                            flags::printable(d->b, 160).c_str());
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

    // Only AO is compared: a NaN, infinite or out-of-range value in either
    // image would make every figure meaningless, and so would an empty mask.
    std::vector<uint8_t> covered;
    if (has_cover) {
        covered.resize(cover.size());
        for (size_t i = 0; i < cover.size(); ++i) covered[i] = cover[i] > 0.5f;
    }
    auto refuse = [](const std::string& path, const std::string& why) {
        std::fprintf(stderr, "ssao-error: error: %s: %s; it is not an AO image in [0, 1].\n", path.c_str(), why.c_str());
        return 1;
    };
    if (const std::string why = aocheck::check_values(ref, rw, has_cover ? &covered : nullptr); !why.empty())
        return refuse(ref_path, why);
    metrics::Masks masks;
    if (!metrics::build_masks(in, masks, error)) {
        std::fprintf(stderr, "ssao-error: error: %s.\n", error.c_str());
        return 1;
    }
    if (std::find(masks.geometry.begin(), masks.geometry.end(), uint8_t(1)) == masks.geometry.end()) {
        std::fprintf(stderr, "ssao-error: error: %s has no pixel to compare: all of it is sky (A = 0%s).\n", ref_path.c_str(),
                     depth.empty() ? "" : ", or no finite depth");
        return 1;
    }
    if (const std::string why = aocheck::check_values(test, tw, &masks.geometry); !why.empty())
        return refuse(test_path, why);
    if (!limit.empty())
        if (const std::string why = aocheck::check_values(limit, rw, &masks.geometry); !why.empty())
            return refuse(limit_path, why);
    std::vector<metrics::Stats> stats;
    metrics::Split split;
    if (!metrics::compute(in, stats, error) ||
        (!limit.empty() && !metrics::compute_split(in, limit, limit_se.empty() ? nullptr : &limit_se, split, error))) {
        std::fprintf(stderr, "ssao-error: error: %s.\n", error.c_str());
        return 1;
    }

    std::printf("test       %s (channel %s), %dx%d\n", test_path.c_str(), channel.c_str(), tw, th);
    std::printf("reference  %s%s%s\n", ref_path.c_str(), se.empty() ? ", no standard-error image" : "",
                depth.empty() ? ", silhouettes from sky/AO edges" : ", silhouettes from its depth");
    if (!limit.empty()) std::printf("limit      %s\n", limit_path.c_str());
    for (const std::string& path : bare)
        std::printf("note       %s records no scene and camera (older file or another program): not checked\n",
                    path.c_str());
    std::printf("bands      %d px\n\n", band);
    std::fputs(metrics::table(stats).c_str(), stdout);
    if (!limit.empty()) {
        std::printf("\nsplit by the depth-only limit: limit vs V_R is what no depth-only method can avoid,\n"
                    "ours vs limit what the tested estimator adds (mean = mean signed error)\n\n");
        std::fputs(metrics::split_table(split).c_str(), stdout);
    }

    if (!csv_path.empty()) {
        const bool fresh = !is_file(csv_path);
        std::ofstream csv(csv_path, std::ios::app);
        if (!csv) {
            std::fprintf(stderr, "ssao-error: error: cannot write %s.\n", csv_path.c_str());
            return 1;
        }
        if (fresh) csv << metrics::csv_header();
        csv << (limit.empty() ? metrics::csv_rows(stats, label) : metrics::csv_rows(split, label));
        if (!csv) {
            std::fprintf(stderr, "ssao-error: error: cannot write %s.\n", csv_path.c_str());
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
        std::fputs("ssao-error: error: out of memory (the images are too large for this machine).\n", stderr);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "ssao-error: error: unexpected failure (%s).\n", e.what());
    }
    return 1;
}
