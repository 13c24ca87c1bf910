// ssao-host --debug-view (debug_view_text.h): one more execute with the view,
// written to debug_view.png. RAW_AO's picture is the --blur none picture;
// BLUR_WEIGHTS's is white on a flat scene and not beside a silhouette; an
// unknown name is a usage error; the normal views are RGB pictures of the
// normals the pass reads (the G-buffer's, or rebuilt from depth).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#include <tinyexr.h>

#include "debug_view_text.h"
#include "run_program.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const std::string kHost = SSAO_HOST_EXE;
const std::string kNested = SSAO_SOURCE_DIR "/tests/host/data/nested.gltf";
const std::string kWork = SSAO_TEST_WORK_DIR;

using testrun::Run;
using testrun::read_file;
using testrun::shell_quote;

std::string fresh_dir(const std::string& name) { return testrun::fresh_dir(kWork, name); }

// ssao-host with `args` under a 60 s timeout.
Run run_host(const std::vector<std::string>& args) { return testrun::run(kHost, args, kWork + "/logs"); }

struct Png {
    int w = 0, h = 0, channels = 0;
    std::vector<unsigned char> px;
};
Png load_png(const std::string& path) {
    Png p;
    unsigned char* data = stbi_load(path.c_str(), &p.w, &p.h, &p.channels, 0);
    REQUIRE_MESSAGE(data != nullptr, "cannot read " << path);
    p.px.assign(data, data + static_cast<size_t>(p.w) * static_cast<size_t>(p.h) * static_cast<size_t>(p.channels));
    stbi_image_free(data);
    return p;
}

// view_depth.exr's first channel (sky = +inf).
std::vector<float> load_depth(const std::string& path) {
    float* rgba = nullptr;
    int w = 0, h = 0;
    const char* err = nullptr;
    if (LoadEXR(&rgba, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
        if (err) FreeEXRErrorMessage(err);
        FAIL("cannot read " << path);
    }
    std::vector<float> v(static_cast<size_t>(w) * static_cast<size_t>(h));
    for (size_t i = 0; i < v.size(); ++i) v[i] = rgba[i * 4];
    std::free(rgba);
    return v;
}

// The nested scene's ground seen straight down (orthographic) away from its
// box: one flat plane at one depth filling the picture.
std::vector<std::string> flat_scene(const std::string& dir) {
    return {kNested, "--out", dir, "--width", "64", "--height", "48", "--eye", "-5,10,5", "--target", "-5,0,5",
            "--ortho", "2", "--only", "ao"};
}

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& more) {
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

}  // namespace

TEST_CASE("--debug-view raw-ao: the picture is the --blur none picture, for every estimator and blur") {
    for (const char* method : {"kernel", "visibility"})
        for (const char* blur : {"depth-aware", "box", "gaussian"}) {
            CAPTURE(method);
            CAPTURE(blur);
            const std::string a = fresh_dir("raw_a"), b = fresh_dir("raw_b");
            const std::vector<std::string> common = {"--width", "96", "--height", "72", "--preset", "ultra",
                                                     "--method", method, "--only", "ao"};
            const Run ra = run_host(with({"--out", a, "--blur", blur, "--debug-view", "raw-ao"}, common));
            const Run rb = run_host(with({"--out", b, "--blur", "none"}, common));
            INFO("stdout: " << ra.out << "\nstderr: " << ra.err << rb.err);
            REQUIRE(ra.exit_code == 0);
            REQUIRE(rb.exit_code == 0);
            CHECK(ra.out.find("debug view: raw-ao") != std::string::npos);
            const Png view = load_png(a + "/debug_view.png"), none = load_png(b + "/ao.png");
            CHECK(view.channels == 1);
            CHECK(view.w == 96);
            CHECK(view.px == none.px);
            // Not a blank picture: the scene has AO, and the run's own AO is the blurred one.
            const Png blurred = load_png(a + "/ao.png");
            CHECK(blurred.px != view.px);
            CHECK(*std::min_element(view.px.begin(), view.px.end()) < 200);
        }
}

TEST_CASE("--debug-view blur-weights: white on a flat scene, not beside a silhouette, white without depth test") {
    // A flat ground straight down: every blur tap passes the depth test.
    for (const char* blur : {"depth-aware", "box", "gaussian", "none"})
        for (const char* preset : {"ultra", "medium"}) {
            CAPTURE(blur);
            CAPTURE(preset);
            const std::string dir = fresh_dir("weights_flat");
            const Run r = run_host(with(flat_scene(dir), {"--preset", preset, "--blur", blur, "--debug-view", "blur-weights"}));
            INFO("stdout: " << r.out << "\nstderr: " << r.err);
            REQUIRE(r.exit_code == 0);
            const Png p = load_png(dir + "/debug_view.png");
            CHECK(p.channels == 1);
            CHECK(std::all_of(p.px.begin(), p.px.end(), [](unsigned char v) { return v == 255; }));
        }
    // The bundled scene has silhouettes: the depth-aware blur rejects taps
    // there; at full resolution the gaussian and the box never do.
    for (const char* blur : {"depth-aware", "box", "gaussian"}) {
        CAPTURE(blur);
        const std::string dir = fresh_dir("weights_scene");
        const Run r = run_host({"--out", dir, "--width", "96", "--height", "72", "--preset", "ultra", "--blur", blur,
                                "--only", "ao", "--debug-view", "blur-weights"});
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        REQUIRE(r.exit_code == 0);
        const Png p = load_png(dir + "/debug_view.png");
        const size_t grey = static_cast<size_t>(std::count_if(p.px.begin(), p.px.end(), [](unsigned char v) { return v < 255; }));
        if (std::string(blur) == "depth-aware")
            CHECK(grey > 0);
        else
            CHECK(grey == 0);
    }
}

TEST_CASE("--debug-view: an unknown name is a usage error (exit 2, one line naming the flag and the choices)") {
    for (const char* bad : {"bogus", "", "RAW-AO", "raw_ao"}) {
        CAPTURE(bad);
        const std::string dir = fresh_dir("bad");
        const Run r = run_host({"--out", dir, "--width", "32", "--height", "32", "--debug-view", bad});
        CHECK(r.exit_code == 2);
        int own_lines = 0;  // one line of ssao-host's own (drivers may add theirs)
        std::istringstream lines(r.err);
        for (std::string line; std::getline(lines, line);) own_lines += line.rfind("ssao-host", 0) == 0;
        CHECK(own_lines == 1);
        CHECK(r.err.find("--debug-view") != std::string::npos);
        CHECK(r.err.find(debug_view_text::choices()) != std::string::npos);
        CHECK(fs::is_empty(dir));  // nothing written
    }
    const Run missing = run_host({"--debug-view"});
    CHECK(missing.exit_code == 2);
    // --help names the flag and every view.
    const Run help = run_host({"--help"});
    CHECK(help.exit_code == 0);
    CHECK(help.out.find("--debug-view " + debug_view_text::choices()) != std::string::npos);
}

TEST_CASE("--debug-view none (the default) runs no extra execute and writes no debug_view.png") {
    for (bool explicit_none : {false, true}) {
        CAPTURE(explicit_none);
        const std::string dir = fresh_dir("none");
        std::vector<std::string> args = {"--out", dir, "--width", "32", "--height", "24", "--only", "ao"};
        if (explicit_none) args = with(args, {"--debug-view", "none"});
        const Run r = run_host(args);
        REQUIRE(r.exit_code == 0);
        CHECK(!fs::exists(dir + "/debug_view.png"));
        CHECK(r.out.find("debug view") == std::string::npos);
    }
}

TEST_CASE("--debug-view normals views: RGB pictures of the normals, n*0.5+0.5") {
    // The G-buffer's normals at full resolution: the host's own normals.png.
    {
        const std::string dir = fresh_dir("normals_scene");
        const Run r = run_host({"--out", dir, "--width", "96", "--height", "72", "--preset", "ultra", "--no-sheet",
                                "--debug-view", "normals"});
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        REQUIRE(r.exit_code == 0);
        const Png view = load_png(dir + "/debug_view.png"), host = load_png(dir + "/normals.png");
        const std::vector<float> depth = load_depth(dir + "/view_depth.exr");
        REQUIRE(view.channels == 3);
        REQUIRE(host.channels == 3);
        REQUIRE(view.px.size() == host.px.size());
        // The pass reads the G-buffer's 8-bit normals and makes them unit
        // length; the host's picture quantises its own float normals. Both
        // round x and y to within a few levels, but where a surface is seen
        // at a grazing angle (z small) renormalising turns that into a large
        // step in z: z is compared only where it is not grazing.
        int off = 0, surface = 0;
        for (size_t i = 0; i < depth.size(); ++i) {
            if (!std::isfinite(depth[i])) continue;  // sky: the host writes black, the view is unspecified
            ++surface;
            const int dx = std::abs(int(view.px[i * 3]) - int(host.px[i * 3]));
            const int dy = std::abs(int(view.px[i * 3 + 1]) - int(host.px[i * 3 + 1]));
            const int dz = std::abs(int(view.px[i * 3 + 2]) - int(host.px[i * 3 + 2]));
            const bool grazing = host.px[i * 3 + 2] < 128 + 64;  // view-space z below 0.5
            off += dx > 3 || dy > 3 || (!grazing && dz > 3);
        }
        CHECK(surface > 1000);
        CHECK(off == 0);
    }
    // A flat ground seen straight down: view-space normal (0,0,1) both ways.
    for (const char* view_name : {"normals", "reconstructed-normals"}) {
        CAPTURE(view_name);
        const std::string dir = fresh_dir("normals_flat");
        const Run r = run_host(with(flat_scene(dir), {"--preset", "ultra", "--debug-view", view_name}));
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        REQUIRE(r.exit_code == 0);
        const Png p = load_png(dir + "/debug_view.png");
        REQUIRE(p.channels == 3);
        int off = 0;
        for (size_t i = 0; i < p.px.size(); i += 3)
            off += std::abs(int(p.px[i]) - 128) > 1 || std::abs(int(p.px[i + 1]) - 128) > 1 || p.px[i + 2] < 254;
        CHECK(off == 0);
    }
}
