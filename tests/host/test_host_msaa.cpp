// ssao-host's issue-12 flags end to end: --msaa N / --sample-index I (the
// plugin reads a multisampled G-buffer) and --output multiply (the plugin
// multiplies AO into the host's lit image).
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <tinyexr.h>
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include "run_program.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
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
const std::string kWork = SSAO_TEST_WORK_DIR;

using testrun::Run;

std::string fresh_dir(const std::string& name) { return testrun::fresh_dir(kWork, name); }

Run run_host(const std::vector<std::string>& args) { return testrun::run(kHost, args, kWork + "/logs"); }

std::vector<float> load_exr(const std::string& path, int& w, int& h) {
    float* rgba = nullptr;
    const char* err = nullptr;
    std::vector<float> v;
    if (LoadEXR(&rgba, &w, &h, path.c_str(), &err) != TINYEXR_SUCCESS) {
        if (err) FreeEXRErrorMessage(err);
        FAIL("cannot read " << path);
    }
    v.resize(size_t(w) * h);
    for (size_t i = 0; i < v.size(); ++i) v[i] = rgba[i * 4];
    std::free(rgba);
    return v;
}

std::vector<unsigned char> load_png(const std::string& path, int& w, int& h) {
    int n = 0;
    unsigned char* px = stbi_load(path.c_str(), &w, &h, &n, 3);
    REQUIRE(px != nullptr);
    std::vector<unsigned char> v(px, px + size_t(w) * h * 3);
    stbi_image_free(px);
    return v;
}

double mean_abs_diff(const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0;
    for (size_t i = 0; i < a.size(); ++i) sum += std::abs(double(a[i]) - b[i]);
    return sum / double(a.size());
}

}  // namespace

TEST_CASE("--msaa 4 gives about the single-sample AO and --sample-index picks a sample") {
    const std::string one = fresh_dir("msaa_1"), four = fresh_dir("msaa_4"), four3 = fresh_dir("msaa_4_3");
    const std::vector<std::string> common = {"--width", "96", "--height", "72", "--only", "ao"};
    auto with = [&](std::vector<std::string> extra, const std::string& dir) {
        std::vector<std::string> a = common;
        a.insert(a.end(), {"--out", dir});
        a.insert(a.end(), extra.begin(), extra.end());
        return run_host(a);
    };
    REQUIRE(with({}, one).exit_code == 0);
    const Run r4 = with({"--msaa", "4"}, four);
    CAPTURE(r4.err);
    REQUIRE(r4.exit_code == 0);
    const Run r43 = with({"--msaa", "4", "--sample-index", "3"}, four3);
    CAPTURE(r43.err);
    REQUIRE(r43.exit_code == 0);
    int w = 0, h = 0;
    const auto a = load_exr(one + "/ao.exr", w, h);
    const auto b = load_exr(four + "/ao.exr", w, h);
    const auto c = load_exr(four3 + "/ao.exr", w, h);
    // Sample 0 and sample 3 lie off the pixel centre (docs/api.md, "MSAA inputs"):
    // close to the single-sample AO on average, and not all equal to each other.
    CHECK(mean_abs_diff(a, b) < 0.02);
    CHECK(mean_abs_diff(a, c) < 0.02);
    CHECK(b != c);
}

TEST_CASE("--sample-index without --msaa is a command-line error") {
    const Run r = run_host({"--out", fresh_dir("msaa_bad"), "--sample-index", "2"});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--msaa") != std::string::npos);
}

TEST_CASE("--output multiply: lit_ao.png is lit_no_ao.png times the AO") {
    const std::string dir = fresh_dir("multiply");
    const Run r = run_host({"--out", dir, "--width", "96", "--height", "72", "--output", "multiply",
                            "--output-format", "r8", "--no-sheet"});
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    int w = 0, h = 0;
    const auto lit = load_png(dir + "/lit_ao.png", w, h);
    const auto base = load_png(dir + "/lit_no_ao.png", w, h);
    const auto ao = load_exr(dir + "/ao.exr", w, h);  // top row first, as the PNGs
    int worst = 0, darker = 0;
    for (size_t i = 0; i < ao.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const int want = static_cast<int>(std::lround(base[i * 3 + ch] * double(ao[i])));
            worst = std::max(worst, std::abs(int(lit[i * 3 + ch]) - want));
            darker += lit[i * 3 + ch] < base[i * 3 + ch];
        }
    // The blender multiplies the RGBA8 image by AO rounded to 8 bits, as the R8 output holds it.
    CHECK(worst <= 1);
    CHECK(darker > 0);
}
