// ssao-host's fade, radius in pixels and frame index, end to end: the glTF extras
// hints fade_start / fade_end / radius_pixels reach the settings the host
// uses and its flags override them; the fade shows in ao.exr against the
// host's own view_depth.exr; --frame-index is bit-stable and 0 is today's
// output; --accumulate averages the frame noise away.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>
#include <tinyexr.h>

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
const std::string kData = SSAO_SOURCE_DIR "/tests/host/data";
const std::string kWork = SSAO_TEST_WORK_DIR "/fade";

using testrun::Run;
using testrun::read_file;

std::string fresh_dir(const std::string& name) { return testrun::fresh_dir(kWork, name); }

// ssao-host with `args` under a 60 s timeout; stdout and stderr captured.
Run run_host(const std::vector<std::string>& args) { return testrun::run(kHost, args, kWork); }

std::vector<float> load_exr(const std::string& path) {
    float* rgba = nullptr;
    const char* err = nullptr;
    int w = 0, h = 0;
    if (LoadEXR(&rgba, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
        const std::string why = err ? err : "?";
        if (err) FreeEXRErrorMessage(err);
        FAIL("cannot read " << path << ": " << why);
    }
    std::vector<float> v(static_cast<size_t>(w) * static_cast<size_t>(h));
    for (size_t i = 0; i < v.size(); ++i) v[i] = rgba[i * 4];
    std::free(rgba);
    return v;
}

// tests/host/data/hinted.gltf with more keys in its extras "ssao" object.
std::string hinted_with(const std::string& name, const std::string& extra_keys) {
    std::string doc = read_file(kData + "/hinted.gltf");
    const std::string anchor = "\"blur\": \"box\"";
    const size_t at = doc.find(anchor);
    REQUIRE(at != std::string::npos);
    doc.insert(at + anchor.size(), ", " + extra_keys);
    const std::string path = fresh_dir("scenes_" + name) + "/scene.gltf";
    std::ofstream(path, std::ios::binary) << doc;
    return path;
}

double rmse(const std::vector<float>& a, const std::vector<float>& b) {
    double s = 0;
    for (size_t i = 0; i < a.size(); ++i) s += (double(a[i]) - b[i]) * (double(a[i]) - b[i]);
    return std::sqrt(s / double(a.size()));
}

const std::vector<std::string> kSmall = {"--width", "48", "--height", "48", "--only", "ao"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

}  // namespace

TEST_CASE("fade and radius-in-pixels hints in glTF extras set the settings, and flags override them") {
    const std::string scene =
        hinted_with("hints", "\"fade_start\": 2.5, \"fade_end\": 9, \"radius_pixels\": 12");
    const std::string dir = fresh_dir("hints");
    const Run r = run_host(with({scene, "--out", dir}, kSmall));
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("ssao 1.2: fade 2.5..9, radius pixels 12, frame index 0, accumulate 1") != std::string::npos);
    // The other hints still apply beside them.
    CHECK(r.out.find("8 directions x 4 steps") != std::string::npos);
    CHECK(r.out.find("radius 0.75 (scene hint)") != std::string::npos);
    const Run f = run_host(with({scene, "--out", dir, "--fade-start", "1", "--fade-end", "4", "--radius-pixels", "5"}, kSmall));
    INFO("stdout: " << f.out << "\nstderr: " << f.err);
    REQUIRE(f.exit_code == 0);
    CHECK(f.out.find("ssao 1.2: fade 1..4, radius pixels 5,") != std::string::npos);
    // --fade-end 0 turns a hinted fade off (its start too); --radius-pixels 0 the pixel radius.
    const Run off = run_host(with({scene, "--out", dir, "--fade-end", "0", "--radius-pixels", "0"}, kSmall));
    INFO("stdout: " << off.out << "\nstderr: " << off.err);
    REQUIRE(off.exit_code == 0);
    CHECK(off.out.find("ssao 1.2:") == std::string::npos);  // nothing of 1.2 on
    // A scene without these hints prints no 1.2 line.
    const Run plain = run_host(with({kData + "/hinted.gltf", "--out", dir}, kSmall));
    REQUIRE(plain.exit_code == 0);
    CHECK(plain.out.find("ssao 1.2:") == std::string::npos);
}

TEST_CASE("bad fade and radius-pixels hints or flags: a clear error, exit status 1 or 2, no files") {
    const std::string backwards = hinted_with("backwards", "\"fade_start\": 9, \"fade_end\": 2");
    const std::string dir = fresh_dir("bad");
    const Run r = run_host(with({backwards, "--out", dir}, kSmall));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("fade_end must be greater than fade_start") != std::string::npos);
    const std::string negative = hinted_with("negative", "\"radius_pixels\": -3");
    const Run n = run_host(with({negative, "--out", dir}, kSmall));
    CHECK(n.exit_code == 1);
    CHECK(n.err.find("ssao.radius_pixels") != std::string::npos);
    const Run flag = run_host(with({kData + "/hinted.gltf", "--out", dir, "--radius-pixels", "20000"}, kSmall));
    CHECK(flag.exit_code == 2);
    CHECK(flag.err.find("--radius-pixels") != std::string::npos);
    const Run idx = run_host(with({kData + "/hinted.gltf", "--out", dir, "--frame-index", "-1"}, kSmall));
    CHECK(idx.exit_code == 2);
    CHECK(fs::is_empty(dir));
}

TEST_CASE("--fade-start/--fade-end: beyond the fade end ao.exr is 1 exactly, before the start unchanged") {
    // The nested scene seen in perspective from the side spans view depths of about 4 to 15.
    const std::vector<std::string> view = {kData + "/nested.gltf", "--width", "64", "--height", "64", "--eye", "7,4,3",
                                           "--target", "3,0.5,-1", "--fov", "50", "--near", "1", "--far", "40",
                                           "--preset", "ultra", "--blur", "none", "--output-format", "r16f", "--no-sheet"};
    // (ultra: full resolution, so every pixel is its own sample; the half-resolution upsample mixes depths.)
    const std::string plain_dir = fresh_dir("fade_plain"), fade_dir = fresh_dir("fade_on");
    const Run p = run_host(with(view, {"--out", plain_dir}));
    const Run f = run_host(with(view, {"--out", fade_dir, "--fade-start", "6", "--fade-end", "8"}));
    INFO("stdout: " << f.out << "\nstderr: " << f.err);
    REQUIRE(p.exit_code == 0);
    REQUIRE(f.exit_code == 0);
    const std::vector<float> plain = load_exr(plain_dir + "/ao.exr"), faded = load_exr(fade_dir + "/ao.exr");
    const std::vector<float> depth = load_exr(fade_dir + "/view_depth.exr");
    REQUIRE(plain.size() == depth.size());
    size_t before = 0, beyond = 0, before_same = 0, beyond_one = 0;
    for (size_t i = 0; i < depth.size(); ++i) {
        if (depth[i] < 6.0f * 0.999f) {
            ++before;
            before_same += faded[i] == plain[i];
        } else if (depth[i] > 8.0f * 1.001f) {  // sky (+inf) included
            ++beyond;
            beyond_one += faded[i] == 1.0f;
        }
    }
    MESSAGE(before << " px before the fade, " << beyond << " beyond");
    CHECK(before > 100);
    CHECK(beyond > 100);
    CHECK(before_same == before);
    CHECK(beyond_one == beyond);
}

TEST_CASE("--frame-index: a fixed index is bit-stable, 0 is the default output, --accumulate 16 converges") {
    const std::vector<std::string> base = {kData + "/nested.gltf", "--width", "64", "--height", "64",
                                           "--eye", "7,4,3", "--target", "3,0.5,-1", "--fov", "50", "--near", "1",
                                           "--only", "ao", "--blur", "none", "--samples", "8",
                                           "--output-format", "r16f", "--rotation", "hash"};
    auto ao = [&](const std::string& name, const std::vector<std::string>& extra) {
        const std::string dir = fresh_dir(name);
        const Run r = run_host(with(with(base, {"--out", dir}), extra));
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        REQUIRE(r.exit_code == 0);
        return load_exr(dir + "/ao.exr");
    };
    const std::vector<float> def = ao("fi_default", {});
    CHECK(ao("fi_zero", {"--frame-index", "0"}) == def);
    const std::vector<float> a = ao("fi_a", {"--frame-index", "5"});
    CHECK(ao("fi_b", {"--frame-index", "5"}) == a);
    CHECK(a != def);
    // What a TAA host converges to, and what 16 frames of it give.
    const std::vector<float> converged = ao("fi_converged", {"--frame-index", "1000", "--accumulate", "256"});
    const std::vector<float> mean16 = ao("fi_16", {"--frame-index", "1", "--accumulate", "16"});
    const double single = rmse(a, converged), averaged = rmse(mean16, converged);
    MESSAGE("RMSE to the 256-frame mean: one frame " << single << ", mean of 16 frames " << averaged << ", factor "
                                                       << single / averaged);
    CHECK(single / averaged >= 2.5);
}
