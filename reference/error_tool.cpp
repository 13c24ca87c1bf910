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
#include <optional>
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
    flags::print_error("ssao-error", m + " (see --help)");
    return 2;
}

// A runtime failure: main prints "ssao-error: error: " + what() and exits 1.
struct Failure : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Args {
    std::string test_path, ref_path, stderr_path, depth_path, limit_path, csv_path, label;
    int band = 3;
    bool allow_mismatch = false;
};

// The flags (the shared parser, host/flags.h: --flag value and --flag=value
// alike). Returns an exit code when the run ends here (help, version, usage).
std::optional<int> parse_args(int argc, char** argv, Args& a) {
    std::vector<std::string> positional;
    const flags::Valued valued = {
        {"--ref-stderr", [&](const std::string&, const std::string& v) { a.stderr_path = v; }},
        {"--ref-depth", [&](const std::string&, const std::string& v) { a.depth_path = v; }},
        {"--limit", [&](const std::string&, const std::string& v) { a.limit_path = v; }},
        {"--csv", [&](const std::string& f, const std::string& v) {
             if (v.empty()) flags::fail(f + " expects a file");
             a.csv_path = v;
         }},
        {"--label", [&](const std::string&, const std::string& v) { a.label = v; }},
        {"--band", [&](const std::string& f, const std::string& v) { a.band = int(flags::integer(f, v, 0, 256)); }},
    };
    const flags::Switches switches = {{"--allow-mismatch", [&] { a.allow_mismatch = true; }}};
    std::string error;
    switch (flags::parse(argc, argv, valued, switches, [&](const std::string& p) { positional.push_back(p); }, error)) {
        case flags::Outcome::Help: std::fputs(kHelp, stdout); return 0;
        case flags::Outcome::Version: std::printf("%s\n", flags::version_line("ssao-error").c_str()); return 0;
        case flags::Outcome::Error:
            flags::print_error("ssao-error", error);  // the message names --help already
            return 2;
        case flags::Outcome::Run: break;
    }
    if (positional.size() != 2) return usage_error("expected two images, TEST.exr and REF, got " + std::to_string(positional.size()));
    a.test_path = positional[0];
    a.ref_path = positional[1];
    // A folder: ssao-reference's, with the companions it wrote when present.
    if (is_dir(a.ref_path)) {
        const std::string dir = a.ref_path;
        a.ref_path = dir + "/reference_ao.exr";
        if (a.stderr_path.empty() && is_file(dir + "/reference_stderr.exr")) a.stderr_path = dir + "/reference_stderr.exr";
        if (a.depth_path.empty() && is_file(dir + "/reference_depth.exr")) a.depth_path = dir + "/reference_depth.exr";
        if (a.limit_path.empty() && is_file(dir + "/limit_ao.exr")) a.limit_path = dir + "/limit_ao.exr";
    }
    if (a.label.empty()) a.label = a.test_path;
    return std::nullopt;
}

struct Images {
    std::string channel;  // the test image's channel that was read
    int tw = 0, th = 0, rw = 0, rh = 0;
    bool has_cover = false;
    std::vector<float> test, ref, cover, se, depth, limit, limit_cover, limit_se;
};

void read_channel(const std::string& path, const std::vector<std::string>& channels, std::vector<float>& out, int& w,
                  int& h, std::string* channel = nullptr) {
    std::string error;
    if (!refio::read_exr_channel(path, channels, out, w, h, error, channel)) throw Failure(error);
}

// A companion image of the reference's size.
void read_companion(const std::string& path, const std::vector<std::string>& channels, std::vector<float>& out,
                    const Images& im) {
    int w = 0, h = 0;
    read_channel(path, channels, out, w, h);
    if (w != im.rw || h != im.rh)
        throw Failure(path + " is " + std::to_string(w) + "x" + std::to_string(h) + ", not " + std::to_string(im.rw) +
                      "x" + std::to_string(im.rh) + " like the reference.");
}

// The limit: same size, and the same coverage (it must come from the same
// scene and camera); its noise image beside it is optional.
void read_limit(const Args& a, Images& im) {
    read_companion(a.limit_path, {"Y"}, im.limit, im);
    if (im.has_cover && refio::exr_has_channel(a.limit_path, "A")) {
        read_companion(a.limit_path, {"A"}, im.limit_cover, im);
        size_t differ = 0;
        for (size_t i = 0; i < im.cover.size(); ++i) differ += (im.cover[i] > 0.5f) != (im.limit_cover[i] > 0.5f);
        if (differ > 0)
            throw Failure(a.limit_path + " covers other pixels than the reference (" + std::to_string(differ) +
                          " differ): it is not from the same scene and camera.");
    }
    const std::string& lp = a.limit_path;
    const std::string se_path = lp.substr(0, lp.rfind('/') + 1) + "limit_stderr.exr";
    std::string error;
    int w = 0, h = 0;
    if (lp.size() >= 12 && lp.compare(lp.size() - 12, 12, "limit_ao.exr") == 0 && is_file(se_path) &&
        (!refio::read_exr_channel(se_path, {"Y"}, im.limit_se, w, h, error) || w != im.rw || h != im.rh))
        im.limit_se.clear();  // the noise column is optional: without it, "-"
}

Images read_images(const Args& a) {
    Images im;
    read_channel(a.test_path, {"Y", "R", "AO"}, im.test, im.tw, im.th, &im.channel);
    read_channel(a.ref_path, {"Y"}, im.ref, im.rw, im.rh);
    if (im.tw != im.rw || im.th != im.rh)
        throw Failure(a.test_path + " is " + std::to_string(im.tw) + "x" + std::to_string(im.th) + " but the reference " +
                      a.ref_path + " is " + std::to_string(im.rw) + "x" + std::to_string(im.rh) + ".");
    im.has_cover = refio::exr_has_channel(a.ref_path, "A");
    int w = 0, h = 0;
    if (im.has_cover) read_channel(a.ref_path, {"A"}, im.cover, w, h);
    if (!a.stderr_path.empty()) read_companion(a.stderr_path, {"Y"}, im.se, im);
    if (!a.depth_path.empty()) read_companion(a.depth_path, {"Z", "Y", "R"}, im.depth, im);
    if (!a.limit_path.empty()) read_limit(a, im);
    return im;
}

// The images must show the same thing: what their headers record is
// compared. Returns the images that record nothing (compared unchecked).
std::vector<std::string> check_provenance(const Args& a) {
    std::vector<std::string> bare;
    std::string error;
    const std::string prefix = provenance::kPrefix;
    refio::Attributes test_made, ref_made, limit_made;
    if (!refio::read_exr_attributes(a.test_path, prefix, test_made, error) ||
        !refio::read_exr_attributes(a.ref_path, prefix, ref_made, error) ||
        (!a.limit_path.empty() && !refio::read_exr_attributes(a.limit_path, prefix, limit_made, error)))
        throw Failure(error);
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
    std::vector<Pair> pairs = {{&a.test_path, &test_made, &a.ref_path, &ref_made}};
    if (!a.limit_path.empty()) pairs.push_back({&a.limit_path, &limit_made, &a.ref_path, &ref_made});
    for (const Pair& p : pairs) {
        if (p.a->empty() || p.b->empty()) {
            for (const auto& [path, made] : {std::make_pair(p.a_path, p.a), std::make_pair(p.b_path, p.b)})
                if (made->empty() && std::find(bare.begin(), bare.end(), *path) == bare.end()) bare.push_back(*path);
            continue;
        }
        const auto d = provenance::compare(*p.a, *p.b);
        if (d && !a.allow_mismatch)
            throw Failure(flags::printable(*p.a_path, 160) + " and " + flags::printable(*p.b_path, 160) +
                          " were made with a different " + flags::printable(d->field, 160) + ": " +
                          flags::printable(d->a, 160) + " vs " + flags::printable(d->b, 160) +
                          " (--allow-mismatch compares them anyway).");
        if (d)
            std::printf("mismatch   %s: %s vs %s, compared anyway (--allow-mismatch)\n",
                        flags::printable(d->field, 160).c_str(), flags::printable(d->a, 160).c_str(),
                        flags::printable(d->b, 160).c_str());
    }
    return bare;
}

struct Results {
    std::vector<metrics::Stats> stats;
    metrics::Split split;
};

// Only AO is compared: a NaN, infinite or out-of-range value in either image
// would make every figure meaningless, and so would an empty mask.
Results compare(const Args& a, const Images& im) {
    metrics::Inputs in;
    in.width = im.rw;
    in.height = im.rh;
    in.test = &im.test;
    in.reference = &im.ref;
    in.sky = im.has_cover ? &im.cover : nullptr;
    in.std_error = im.se.empty() ? nullptr : &im.se;
    in.depth = im.depth.empty() ? nullptr : &im.depth;
    in.band = a.band;
    std::vector<uint8_t> covered;
    if (im.has_cover) {
        covered.resize(im.cover.size());
        for (size_t i = 0; i < im.cover.size(); ++i) covered[i] = im.cover[i] > 0.5f;
    }
    auto refuse = [](const std::string& path, const std::string& why) {
        throw Failure(path + ": " + why + "; it is not an AO image in [0, 1].");
    };
    if (const std::string why = aocheck::check_values(im.ref, im.rw, im.has_cover ? &covered : nullptr); !why.empty())
        refuse(a.ref_path, why);
    std::string error;
    metrics::Masks masks;
    if (!metrics::build_masks(in, masks, error)) throw Failure(error + ".");
    if (std::find(masks.geometry.begin(), masks.geometry.end(), uint8_t(1)) == masks.geometry.end())
        throw Failure(a.ref_path + " has no pixel to compare: all of it is sky (A = 0" +
                      (im.depth.empty() ? "" : ", or no finite depth") + ").");
    if (const std::string why = aocheck::check_values(im.test, im.tw, &masks.geometry); !why.empty())
        refuse(a.test_path, why);
    if (!im.limit.empty())
        if (const std::string why = aocheck::check_values(im.limit, im.rw, &masks.geometry); !why.empty())
            refuse(a.limit_path, why);
    Results r;
    if (!metrics::compute(in, r.stats, error) ||
        (!im.limit.empty() &&
         !metrics::compute_split(in, im.limit, im.limit_se.empty() ? nullptr : &im.limit_se, r.split, error)))
        throw Failure(error + ".");
    return r;
}

void print_report(const Args& a, const Images& im, const Results& r, const std::vector<std::string>& bare) {
    std::printf("test       %s (channel %s), %dx%d\n", a.test_path.c_str(), im.channel.c_str(), im.tw, im.th);
    std::printf("reference  %s%s%s\n", a.ref_path.c_str(), im.se.empty() ? ", no standard-error image" : "",
                im.depth.empty() ? ", silhouettes from sky/AO edges" : ", silhouettes from its depth");
    if (!im.limit.empty()) std::printf("limit      %s\n", a.limit_path.c_str());
    for (const std::string& path : bare)
        std::printf("note       %s records no scene and camera (older file or another program): not checked\n",
                    path.c_str());
    std::printf("bands      %d px\n\n", a.band);
    std::fputs(metrics::table(r.stats).c_str(), stdout);
    if (!im.limit.empty()) {
        std::printf("\nsplit by the depth-only limit: limit vs V_R is what no depth-only method can avoid,\n"
                    "ours vs limit what the tested estimator adds (mean = mean signed error)\n\n");
        std::fputs(metrics::split_table(r.split).c_str(), stdout);
    }
}

// --csv's file, opened for appending before anything is compared or printed,
// so that a path it cannot write fails first, with the reason. fresh: it is
// new or empty (a failed run leaves it empty), so the rows need the header.
std::ofstream open_csv(const Args& a, bool& fresh) {
    struct stat st;
    fresh = !is_file(a.csv_path) || (stat(a.csv_path.c_str(), &st) == 0 && st.st_size == 0);
    std::ofstream csv(a.csv_path, std::ios::app);
    if (!csv) throw Failure("cannot write " + a.csv_path + " (" + std::strerror(errno) + ").");
    return csv;
}

void append_csv(std::ofstream& csv, bool fresh, const Args& a, const Images& im, const Results& r) {
    if (fresh) csv << metrics::csv_header();
    csv << (im.limit.empty() ? metrics::csv_rows(r.stats, a.label) : metrics::csv_rows(r.split, a.label));
    csv.flush();
    if (!csv) throw Failure("cannot write " + a.csv_path + ".");
}

// Parse, read, check the headers, compare, report.
int run(int argc, char** argv) {
    Args a;
    if (const std::optional<int> done = parse_args(argc, argv, a)) return *done;
    try {
        const Images im = read_images(a);
        const std::vector<std::string> bare = check_provenance(a);
        bool fresh = false;
        std::ofstream csv;
        if (!a.csv_path.empty()) csv = open_csv(a, fresh);
        const Results r = compare(a, im);
        print_report(a, im, r, bare);
        if (csv.is_open()) append_csv(csv, fresh, a, im, r);
    } catch (const Failure& f) {
        std::fprintf(stderr, "ssao-error: error: %s\n", f.what());
        return 1;
    }
    return 0;
}

}  // namespace

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
