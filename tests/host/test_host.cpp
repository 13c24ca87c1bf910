// End-to-end tests of ssao-host: the program is run as a user would run it
// (a child process, small images, a timeout) and its files are inspected.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include <tinyexr.h>
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include "plugin_loader.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#ifndef SSAO_HOST_EXE
#error "SSAO_HOST_EXE must name the ssao-host executable"
#endif

namespace fs = std::filesystem;

namespace {

const std::string kHost = SSAO_HOST_EXE;
const std::string kSource = SSAO_SOURCE_DIR;
const std::string kData = SSAO_SOURCE_DIR "/tests/host/data";
const std::string kWork = SSAO_TEST_WORK_DIR;
const std::string kSpot = SSAO_SOURCE_DIR "/assets/models/spot-on-ground.glb";
const std::string kTeapot = SSAO_SOURCE_DIR "/assets/models/teapot-on-ground.glb";

std::string read_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// A fresh directory for one test.
std::string fresh_dir(const std::string& name) {
    const fs::path p = fs::path(kWork) / name;
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

struct Run {
    int exit_code = -1;       // -1: killed by a signal (a crash)
    bool timed_out = false;
    std::string out, err;
    // The lines of stderr that the program itself wrote (drivers may add their own).
    std::vector<std::string> own_error_lines() const {
        std::vector<std::string> lines;
        std::istringstream in(err);
        for (std::string line; std::getline(in, line);)
            if (line.rfind("ssao-host", 0) == 0) lines.push_back(line);
        return lines;
    }
};

// Runs ssao-host with `args` under a 60 s timeout, capturing stdout and stderr.
Run run_host(const std::vector<std::string>& args, const std::string& env = "") {
    static int counter = 0;
    const fs::path logs = fs::path(kWork) / "logs";
    fs::create_directories(logs);
    const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(counter++);
    const std::string out_path = (logs / ("out_" + tag)).string();
    const std::string err_path = (logs / ("err_" + tag)).string();
    std::string cmd = env + (env.empty() ? "" : " ") + "timeout -s KILL 60 " + shell_quote(kHost);
    for (const auto& a : args) cmd += " " + shell_quote(a);
    cmd += " >" + shell_quote(out_path) + " 2>" + shell_quote(err_path);
    const int status = std::system(cmd.c_str());
    Run r;
    if (WIFEXITED(status)) {
        r.exit_code = WEXITSTATUS(status);
        // `timeout -s KILL` reports a killed child as 128 + 9.
        if (r.exit_code == 137) {
            r.timed_out = true;
            r.exit_code = -1;
        } else if (r.exit_code > 128) {
            r.exit_code = -1;   // the shell reports a child's signal as 128 + n
        }
    }
    r.out = read_file(out_path);
    r.err = read_file(err_path);
    fs::remove(out_path);
    fs::remove(err_path);
    return r;
}

struct Image {
    int w = 0, h = 0;
    std::vector<float> v;   // first channel, top row first
    float at(int x, int y) const { return v[static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)]; }
};

Image load_exr(const std::string& path) {
    float* rgba = nullptr;
    const char* err = nullptr;
    Image img;
    const int ret = LoadEXR(&rgba, &img.w, &img.h, path.c_str(), &err);
    if (ret != TINYEXR_SUCCESS) {
        const std::string why = err ? err : "?";
        if (err) FreeEXRErrorMessage(err);
        FAIL("cannot read " << path << ": " << why);
    }
    img.v.resize(static_cast<size_t>(img.w) * static_cast<size_t>(img.h));
    for (size_t i = 0; i < img.v.size(); ++i) img.v[i] = rgba[i * 4];
    std::free(rgba);
    return img;
}

// Channel names of an EXR file's header.
std::vector<std::string> exr_channels(const std::string& path) {
    EXRVersion version;
    EXRHeader header;
    InitEXRHeader(&header);
    std::vector<std::string> names;
    const char* err = nullptr;
    if (ParseEXRVersionFromFile(&version, path.c_str()) == TINYEXR_SUCCESS &&
        ParseEXRHeaderFromFile(&header, &version, path.c_str(), &err) == TINYEXR_SUCCESS) {
        for (int i = 0; i < header.num_channels; ++i) names.push_back(header.channels[i].name);
        FreeEXRHeader(&header);
    }
    if (err) FreeEXRErrorMessage(err);
    return names;
}

struct Diff {
    double mean = 0, max = 0, p99 = 0;
};
Diff compare(const Image& a, const Image& b) {
    REQUIRE(a.w == b.w);
    REQUIRE(a.h == b.h);
    std::vector<double> d(a.v.size());
    Diff r;
    for (size_t i = 0; i < a.v.size(); ++i) {
        d[i] = std::fabs(double(a.v[i]) - double(b.v[i]));
        r.mean += d[i];
        r.max = std::max(r.max, d[i]);
    }
    r.mean /= double(d.size());
    std::sort(d.begin(), d.end());
    r.p99 = d[static_cast<size_t>(0.99 * double(d.size() - 1))];
    return r;
}

// Pixel distance (4-neighbour steps) from the nearest pixel where `seed` is true.
std::vector<int> distance_from(const std::vector<bool>& seed, int w, int h) {
    std::vector<int> dist(seed.size(), 1 << 30);
    std::deque<int> queue;
    for (size_t i = 0; i < seed.size(); ++i)
        if (seed[i]) {
            dist[i] = 0;
            queue.push_back(static_cast<int>(i));
        }
    while (!queue.empty()) {
        const int i = queue.front();
        queue.pop_front();
        const int x = i % w, y = i / w;
        const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
        for (int k = 0; k < 4; ++k) {
            if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
            const int j = ny[k] * w + nx[k];
            if (dist[static_cast<size_t>(j)] > dist[static_cast<size_t>(i)] + 1) {
                dist[static_cast<size_t>(j)] = dist[static_cast<size_t>(i)] + 1;
                queue.push_back(j);
            }
        }
    }
    return dist;
}

const std::vector<std::string> kAllFiles = {"ao.png",    "ao.exr",         "lit_ao.png", "lit_no_ao.png",
                                            "normals.png", "depth.png", "view_depth.exr", "modes.png"};

std::map<std::string, std::string> snapshot(const std::string& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::directory_iterator(dir)) files[e.path().filename().string()] = read_file(e.path().string());
    return files;
}

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

bool has_png_signature(const std::string& path) { return read_file(path).rfind("\x89PNG\r\n\x1a\n", 0) == 0; }

}  // namespace

TEST_CASE("the bundled scene renders every file and the report") {
    REQUIRE(fs::exists(kSpot));
    const std::string dir = fresh_dir("bundled");
    const Run r = run_host({"--out", dir, "--width", "128", "--height", "96"});
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    for (const auto& f : kAllFiles) {
        CHECK_MESSAGE(fs::exists(fs::path(dir) / f), f);
        if (f.size() > 4 && f.substr(f.size() - 4) == ".png") CHECK_MESSAGE(has_png_signature(dir + "/" + f), f);
    }
    // Nothing else (no temporary files left behind).
    CHECK(snapshot(dir).size() == kAllFiles.size());
    CHECK(r.out.find("128x96") != std::string::npos);
    CHECK(r.out.find("5,858 triangles") != std::string::npos);
    CHECK(r.out.find("GPU times") != std::string::npos);
    CHECK(r.out.find(fs::absolute(dir).lexically_normal().string()) != std::string::npos);
    // The report names what the DEFAULT preset runs, and each pass under its
    // own name: the upsample is not a blur, and no blur runs.
    CHECK(r.out.find("ssao: visibility, 8 directions x 4 steps, half resolution, no blur, thickness ") !=
          std::string::npos);
    CHECK(r.out.find("kernel hemisphere") == std::string::npos);
    CHECK(r.out.find("grid ") != std::string::npos);
    CHECK(r.out.find("visibility ") != std::string::npos);
    CHECK(r.out.find("upsample ") != std::string::npos);
    CHECK(r.out.find("blur x") == std::string::npos);

    const Image ao = load_exr(dir + "/ao.exr");
    CHECK(ao.w == 128);
    CHECK(ao.h == 96);
    CHECK(exr_channels(dir + "/ao.exr") == std::vector<std::string>{"Y"});
    for (float v : ao.v) REQUIRE((v >= 0.0f && v <= 1.0f));
    // view_depth: positive distances on geometry, +inf on the sky (top corners).
    const Image depth = load_exr(dir + "/view_depth.exr");
    CHECK(std::isinf(depth.at(0, 0)));
    CHECK(std::isinf(depth.at(127, 0)));
    const float centre = depth.at(64, 60);
    CHECK(std::isfinite(centre));
    CHECK(centre > 0.0f);

    // AO only darkens the ambient term: lit_ao <= lit_no_ao everywhere, and
    // somewhere strictly.
    const Png lit = load_png(dir + "/lit_ao.png"), unlit = load_png(dir + "/lit_no_ao.png");
    REQUIRE(lit.px.size() == unlit.px.size());
    CHECK((lit.w == 128 && lit.h == 96 && lit.channels == 3));
    long darker = 0, brighter = 0;
    for (size_t i = 0; i < lit.px.size(); ++i) {
        if (lit.px[i] + 1 < unlit.px[i]) ++darker;   // 1 level of rounding allowed
        if (lit.px[i] > unlit.px[i] + 1) ++brighter;
    }
    CHECK(darker > 50);
    CHECK(brighter == 0);
    // The mode sheet: five panels side by side; E (no SSAO) is lit_no_ao under its label.
    const Png sheet = load_png(dir + "/modes.png");
    CHECK(sheet.w == 5 * 128);
    CHECK(sheet.h == 96);
    long e_differs = 0;
    for (int y = 40; y < 96; ++y)
        for (int x = 0; x < 128; ++x)
            for (int c = 0; c < 3; ++c)
                e_differs += sheet.px[(static_cast<size_t>(y) * 640 + static_cast<size_t>(x)) * 3 + static_cast<size_t>(c)] !=
                             unlit.px[(static_cast<size_t>(y) * 128 + static_cast<size_t>(x)) * 3 + static_cast<size_t>(c)];
    CHECK(e_differs == 0);
}

TEST_CASE("the ground right beside the model is darker than open ground") {
    for (const std::string& model : {kSpot, kTeapot}) {
        if (!fs::exists(model)) continue;
        CAPTURE(model);
        const std::string dir = fresh_dir("beside_" + fs::path(model).stem().string());
        // Straight down from y = 10, orthographic: the ground (y = 0) is at view
        // depth 10 everywhere, anything nearer is the model.
        const int n = 128;
        const Run r = run_host({model, "--out", dir, "--width", std::to_string(n), "--height", std::to_string(n),
                                "--eye", "0,10,0", "--target", "0,0,0", "--ortho", "2.5", "--no-sheet",
                                // Straight down, the model's top lies further in front of the ground
                                // beside it than the visibility estimator's thickness, so that
                                // estimator (like the depth-only limit) reads the ground as open:
                                // one depth layer cannot tell a tall object from a floating one.
                                // The kernel's volume count is what this case checks.
                                "--method", "kernel"});
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        REQUIRE(r.exit_code == 0);
        const Image ao = load_exr(dir + "/ao.exr");
        const Image depth = load_exr(dir + "/view_depth.exr");
        std::vector<bool> model_px(depth.v.size()), ground_px(depth.v.size());
        for (size_t i = 0; i < depth.v.size(); ++i) {
            model_px[i] = depth.v[i] < 9.95f;
            ground_px[i] = std::fabs(depth.v[i] - 10.0f) < 1e-3f;
        }
        const std::vector<int> dist = distance_from(model_px, n, n);
        double beside = 0, far = 0;
        int n_beside = 0, n_far = 0;
        for (size_t i = 0; i < ao.v.size(); ++i) {
            if (!ground_px[i]) continue;
            if (dist[i] >= 1 && dist[i] <= 3) {
                beside += ao.v[i];
                ++n_beside;
            } else if (dist[i] >= 40) {
                far += ao.v[i];
                ++n_far;
            }
        }
        REQUIRE(n_beside > 20);
        REQUIRE(n_far > 200);
        beside /= n_beside;
        far /= n_far;
        MESSAGE("AO beside the model " << beside << ", far from it " << far);
        CHECK(far > 0.95);
        CHECK(beside < far - 0.05);
    }
}

TEST_CASE("a nested node hierarchy puts the geometry where its transforms say") {
    // tests/host/data/nested.gltf: parent T(1,0,0) R(90 deg about +Y) > child
    // T(1,0,2) > box T(0,1,0) S(1,2,1): the unit box ends up at x 2.5..3.5,
    // y 0..2, z -1.5..-0.5 on a ground at y = 0. The file's orthographic camera
    // looks straight down from y = 10 (screen right = +x, up = -z, 5 units
    // either side of the centre).
    const int n = 96;
    const std::string dir = fresh_dir("nested");
    const Run r = run_host({kData + "/nested.gltf", "--out", dir, "--width", std::to_string(n), "--height",
                            std::to_string(n), "--no-sheet", "--method", "kernel" /* top-down: see "beside the model" */});
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("the scene's") != std::string::npos);
    const Image depth = load_exr(dir + "/view_depth.exr");
    const Image ao = load_exr(dir + "/ao.exr");
    auto world_x = [&](int col) { return (col + 0.5) / n * 10.0 - 5.0; };
    auto world_z = [&](int row) { return (row + 0.5) / n * 10.0 - 5.0; };
    const double px = 10.0 / n;
    int inside = 0, outside = 0;
    std::vector<bool> box_px(depth.v.size());
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const double wx = world_x(x), wz = world_z(y);
            const bool in = wx > 2.5 + px && wx < 3.5 - px && wz > -1.5 + px && wz < -0.5 - px;
            const bool out = wx < 2.5 - px || wx > 3.5 + px || wz < -1.5 - px || wz > -0.5 + px;
            CAPTURE(x);
            CAPTURE(y);
            if (in) {
                CHECK(depth.at(x, y) == doctest::Approx(8.0).epsilon(1e-3));   // the box's top, y = 2
                ++inside;
            } else if (out) {
                CHECK(depth.at(x, y) == doctest::Approx(10.0).epsilon(1e-3));  // the ground
                ++outside;
            }
            box_px[static_cast<size_t>(y * n + x)] = depth.at(x, y) < 9.5f;
        }
    }
    CHECK(inside >= 49);   // about 9 x 9 pixels
    CHECK(outside > n * n - 200);
    // The box occludes the ground around it.
    const std::vector<int> dist = distance_from(box_px, n, n);
    double ring = 0, open = 0;
    int n_ring = 0, n_open = 0;
    for (size_t i = 0; i < ao.v.size(); ++i) {
        if (box_px[i]) continue;
        if (dist[i] >= 1 && dist[i] <= 2) {
            ring += ao.v[i];
            ++n_ring;
        } else if (dist[i] >= 30) {
            open += ao.v[i];
            ++n_open;
        }
    }
    ring /= std::max(n_ring, 1);
    open /= std::max(n_open, 1);
    MESSAGE("AO around the box " << ring << ", open ground " << open);
    CHECK(ring < open - 0.05);
}

TEST_CASE("a scene in millimetres gives the same AO as the same scene in metres") {
    // The radius follows the scene's size (0.05 x the bounding-box diagonal).
    const std::string m = fresh_dir("metres"), mm = fresh_dir("millimetres");
    const Run a = run_host({kData + "/nested.gltf", "--out", m, "--width", "96", "--height", "96", "--only", "ao",
                            "--output-format", "r16f"});
    const Run b = run_host({kData + "/millimetres.gltf", "--out", mm, "--width", "96", "--height", "96", "--only",
                            "ao", "--output-format", "r16f"});
    INFO("stderr: " << a.err << b.err);
    REQUIRE(a.exit_code == 0);
    REQUIRE(b.exit_code == 0);
    const Diff d = compare(load_exr(m + "/ao.exr"), load_exr(mm + "/ao.exr"));
    MESSAGE("metres vs millimetres: mean " << d.mean << ", p99 " << d.p99 << ", max " << d.max);
    CHECK(d.mean < 0.005);
    CHECK(d.p99 < 0.05);
}

TEST_CASE("world-space and view-space normal G-buffers give the same AO") {
    // r16f output: 8-bit output would hide small differences.
    const std::vector<std::string> common = {"--width", "128", "--height", "96", "--only", "ao", "--output-format", "r16f"};
    auto render = [&](const std::string& name, std::vector<std::string> extra) {
        const std::string dir = fresh_dir(name);
        std::vector<std::string> args = {"--out", dir};
        args.insert(args.end(), common.begin(), common.end());
        args.insert(args.end(), extra.begin(), extra.end());
        const Run r = run_host(args);
        INFO("stderr: " << r.err);
        REQUIRE(r.exit_code == 0);
        return load_exr(dir + "/ao.exr");
    };
    const Image view = render("normals_view", {"--normals", "view"});
    const Image world = render("normals_world", {"--normals", "world"});
    const Diff d = compare(view, world);
    MESSAGE("view vs world normals: mean " << d.mean << ", p99 " << d.p99 << ", max " << d.max);
    CHECK(d.mean < 0.002);
    CHECK(d.p99 < 0.02);
    // Unorm-packed rgba8 normals: quantised, so a looser tolerance.
    const Image world8 = render("normals_world8", {"--normals", "world", "--normal-format", "rgba8"});
    const Diff d8 = compare(view, world8);
    MESSAGE("view rgba16f vs world rgba8: mean " << d8.mean << ", p99 " << d8.p99);
    CHECK(d8.mean < 0.01);
}

TEST_CASE("--only ao writes only the AO files") {
    const std::string dir = fresh_dir("only_ao");
    const Run r = run_host({"--out", dir, "--width", "96", "--height", "96", "--only", "ao"});
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(fs::exists(dir + "/ao.png"));
    CHECK(fs::exists(dir + "/ao.exr"));
    for (const char* f : {"lit_ao.png", "lit_no_ao.png", "modes.png", "normals.png", "depth.png", "view_depth.exr"})
        CHECK_MESSAGE(!fs::exists(fs::path(dir) / f), f);
    CHECK(snapshot(dir).size() == 2);
    // The sheet on request: its panels need the lighting pass, but no lit image is written.
    const std::string dir2 = fresh_dir("only_ao_sheet");
    const Run r2 = run_host({"--out", dir2, "--width", "64", "--height", "48", "--only", "ao", "--sheet"});
    REQUIRE(r2.exit_code == 0);
    CHECK(fs::exists(dir2 + "/modes.png"));
    CHECK(!fs::exists(dir2 + "/lit_ao.png"));
}

TEST_CASE("bad input: one message, a non-zero exit, earlier output untouched") {
    const std::string dir = fresh_dir("bad_input");
    const Run first = run_host({"--out", dir, "--width", "48", "--height", "32"});
    REQUIRE(first.exit_code == 0);
    const auto before = snapshot(dir);
    REQUIRE(before.size() == kAllFiles.size());

    // A truncated .glb, made from the bundled one.
    const std::string truncated = fs::path(kWork) / "truncated.glb";
    {
        const std::string whole = read_file(kSpot);
        REQUIRE(whole.size() > 4000);
        std::ofstream(truncated, std::ios::binary) << whole.substr(0, 3000);
    }
    const std::string garbage = fs::path(kWork) / "garbage.glb";
    std::ofstream(garbage, std::ios::binary) << "this is not a glTF file at all";

    struct Case {
        std::vector<std::string> args;
        std::string expect;   // a fragment the message must contain
    };
    const std::vector<Case> cases = {
        {{kData + "/does-not-exist.gltf"}, "does-not-exist.gltf"},
        {{kData}, "directory"},
        {{kData + "/malformed.gltf"}, "malformed.gltf"},
        {{truncated}, "truncated.glb"},
        {{garbage}, "garbage.glb"},
        {{kData + "/out_of_range.gltf"}, "out_of_range.gltf"},
        {{kData + "/lines.gltf"}, "lines"},
        {{kData + "/empty.gltf"}, "nothing to draw"},
        {{"--width", "0"}, "--width"},
        {{"--height", "0"}, "--height"},
        {{"--width", "16385"}, "--width"},
        {{"--width", "100000000000000000000"}, "--width"},
        {{"--height", "abc"}, "--height"},
        {{"--width", "12.5"}, "--width"},
        {{"--width"}, "--width"},
        {{"--frobnicate"}, "--frobnicate"},
        {{"-x"}, "-x"},
        {{"--samples", "65"}, "--samples"},
        {{"--samples", "0"}, "--samples"},
        {{"--radius", "-1"}, "--radius"},
        {{"--radius", "nan"}, "--radius"},
        {{"--bias", "-0.1"}, "--bias"},
        {{"--power", "0"}, "--power"},
        {{"--strength", "9"}, "--strength"},
        {{"--kernel", "cube"}, "--kernel"},
        {{"--distribution", "gaussian"}, "--distribution"},
        {{"--rotation", "spin"}, "--rotation"},
        {{"--blur", "median"}, "--blur"},
        {{"--blur-radius", "17"}, "--blur-radius"},
        {{"--blur-sigma", "0"}, "--blur-sigma"},
        {{"--blur-tolerance", "2"}, "--blur-tolerance"},
        {{"--output-format", "rgba8"}, "--output-format"},
        {{"--method", "horizon"}, "--method"},
        {{"--thickness", "0"}, "--thickness"},
        {{"--thickness", "-0.5"}, "--thickness"},
        {{"--thickness", "nan"}, "--thickness"},
        {{"--steps", "0"}, "--steps"},
        {{"--steps", "33"}, "--steps"},
        {{"--steps", "2.5"}, "--steps"},
        {{"--preset", "extreme"}, "--preset"},
        {{"--seed", "-3"}, "--seed"},
        {{"--depth", "d8"}, "--depth"},
        {{"--normals", "tangent"}, "--normals"},
        {{"--normal-format", "rgb10"}, "--normal-format"},
        {{"--eye", "1,2"}, "--eye"},
        {{"--target", "1,2,x"}, "--target"},
        {{"--fov", "180"}, "--fov"},
        {{"--near", "0"}, "--near"},
        {{"--far", "-5"}, "--far"},
        {{"--near", "10", "--far", "5"}, "--far"},
        {{"--ortho", "2", "--far", "inf"}, "--far"},
        {{"--only", "lit"}, "--only"},
        {{"--frames", "0"}, "--frames"},
        {{"--gl33=yes"}, "--gl33"},
        {{kSpot, kSpot}, "more than one scene"},
        {{"--plugin", fs::path(kWork) / "no-such-plugin.so"}, "no-such-plugin.so"},
        // Refused by the plugin at execute, after create_context: its log line must land in live memory.
        {{"--ortho", "1e-30"}, "projection"},
        {{"--near", "1e30", "--far", "inf"}, "projection"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args = c.args;
        args.insert(args.end(), {"--out", dir, "--width", "48", "--height", "32"});
        // Flags given twice: the case's own value comes last for --width/--height cases.
        if (std::find(c.args.begin(), c.args.end(), "--width") != c.args.end() ||
            std::find(c.args.begin(), c.args.end(), "--height") != c.args.end())
            args = [&] {
                std::vector<std::string> a = {"--out", dir};
                a.insert(a.end(), c.args.begin(), c.args.end());
                return a;
            }();
        const Run r = run_host(args);
        std::string joined;
        for (const auto& a : c.args) joined += a + " ";
        CAPTURE(joined);
        CAPTURE(r.err);
        CHECK(!r.timed_out);
        CHECK(r.exit_code > 0);   // not 0, and not a crash (-1)
        const auto lines = r.own_error_lines();
        CHECK(lines.size() == 1);
        if (!lines.empty()) CHECK(lines[0].find(c.expect) != std::string::npos);
        CHECK(snapshot(dir) == before);
    }
}

TEST_CASE("--help lists every flag with the plugin's own defaults") {
    const Run r = run_host({"--help"});
    REQUIRE(r.exit_code == 0);
    for (const char* flag :
         {"--eye", "--target", "--fov", "--near", "--far", "--ortho", "--reverse-z", "--depth", "--width", "--height",
          "--normals", "--normal-format", "--samples", "--radius", "--bias", "--depth-step-bias", "--power",
          "--strength", "--kernel", "--distribution", "--rotation", "--seed", "--blur", "--blur-radius",
          "--blur-sigma", "--blur-tolerance", "--output-format", "--preset", "--frames", "--only", "--sheet",
          "--gl33", "--out", "--method", "--thickness", "--steps", "--max-step-texels", "--resolution"})
        CHECK_MESSAGE(r.out.find(flag) != std::string::npos, flag);
    // The defaults shown are the plugin's resolved zeroed settings.
    plugin::Library lib;
    std::string error;
    REQUIRE_MESSAGE(lib.open(plugin::Library::default_path(), error), error);
    ssao_settings zero{}, d{};
    zero.size = d.size = sizeof(ssao_settings);
    REQUIRE(lib.api().resolve_settings(&zero, &d) == SSAO_OK);
    auto line_of = [&](const std::string& flag) {
        const size_t at = r.out.find("  " + flag + " ");
        REQUIRE(at != std::string::npos);
        return r.out.substr(at, r.out.find('\n', at) - at);
    };
    CHECK(line_of("--samples").find("(default " + std::to_string(d.sample_count) + ")") != std::string::npos);
    CHECK(line_of("--blur-radius").find("(default " + std::to_string(d.blur_radius) + ")") != std::string::npos);
    std::ostringstream power;
    power << "(default " << d.power << ")";
    CHECK(line_of("--power").find(power.str()) != std::string::npos);
    // The estimator's flags: ranges from the header's limits, defaults from the plugin.
    CHECK(line_of("--steps").find("1.." + std::to_string(SSAO_MAX_STEPS) + " (default " + std::to_string(d.step_count) + ")") !=
          std::string::npos);
    // The step length's default, 0, reads "off" (its text wraps onto a third line).
    REQUIRE(d.max_step_texels == 0.0f);
    const size_t step_length = r.out.find("  --max-step-texels X ");
    REQUIRE(step_length != std::string::npos);
    CHECK(r.out.find("fixed (default off)", step_length) < r.out.find("  --output-format", step_length));
    CHECK(r.out.find("(default " + std::string(d.method == SSAO_METHOD_VISIBILITY ? "visibility" : "kernel") + ")") !=
          std::string::npos);
    std::ostringstream thickness;
    thickness << "(default radius x (0.5 + 1.5 / steps): " << d.thickness / d.radius << " x radius)";
    CHECK(r.out.find(thickness.str()) != std::string::npos);
    std::ostringstream bias;  // the fraction and the value agree with the plugin's (the fraction once read 10x)
    bias << "(default " << d.bias / d.radius << " x radius, i.e. " << d.bias << " at radius " << d.radius << ")";
    CHECK(line_of("--bias").find(bias.str()) != std::string::npos);
    const char* grid = d.resolution == SSAO_RESOLUTION_FULL ? "full" : d.resolution == SSAO_RESOLUTION_HALF ? "half" : "quarter";
    CHECK(r.out.find("(default " + std::string(grid) + ")", r.out.find("  --resolution ")) < r.out.find("  --fade-start"));
}

TEST_CASE("--resolution reaches the plugin: the default's grid gives the default's image, another grid another") {
    auto render = [&](const std::string& name, const std::vector<std::string>& extra) {
        const std::string dir = fresh_dir(name);
        std::vector<std::string> args = {"--width", "64", "--height", "48", "--only", "ao", "--out", dir};
        args.insert(args.end(), extra.begin(), extra.end());
        const Run r = run_host(args);
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        REQUIRE(r.exit_code == 0);
        return std::make_pair(load_exr(dir + "/ao.exr"), r.out);
    };
    const auto plain = render("resolution_default", {});
    const auto half = render("resolution_half", {"--resolution", "half"});
    const auto full = render("resolution_full", {"--resolution", "full"});
    const auto quarter = render("resolution_quarter", {"--resolution", "quarter"});
    CHECK(plain.second.find(", half resolution, ") != std::string::npos);  // DEFAULT runs at half
    CHECK(compare(plain.first, half.first).max == 0.0);
    CHECK(full.second.find(", full resolution, ") != std::string::npos);
    CHECK(quarter.second.find(", quarter resolution, ") != std::string::npos);
    CHECK(compare(full.first, half.first).max > 0.0);
    CHECK(compare(quarter.first, half.first).max > 0.0);
    const Run bad = run_host({"--resolution", "eighth"});
    CHECK(bad.exit_code == 2);
    const auto lines = bad.own_error_lines();
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].find("--resolution expects one of full|half|quarter") != std::string::npos);
}

TEST_CASE("usage errors of the estimator flags exit with status 2 and one line naming the flag") {
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"--method", "horizon"}, {"--method"}, {"--thickness", "0"}, {"--thickness", "inf"}, {"--thickness", "x"},
             {"--steps", "0"}, {"--steps", "33"}, {"--steps", "-1"}, {"--max-step-texels", "-1"},
             {"--max-step-texels", "2e6"}, {"--max-step-texels", "nan"}, {"--max-step-texels"}}) {
        CAPTURE(args[0]);
        CAPTURE(args.size() > 1 ? args[1] : std::string("(no value)"));
        const Run r = run_host(args);
        CAPTURE(r.err);
        CHECK(r.exit_code == 2);
        const auto lines = r.own_error_lines();
        REQUIRE(lines.size() == 1);
        CHECK(lines[0].find(args[0]) != std::string::npos);
    }
}

TEST_CASE("a --near or --far that the fitted other plane contradicts is an error naming it, not replaced") {
    // The framed camera's planes hug the scene: a far plane inside it, or a
    // near plane beyond it, given alone, used to be moved silently.
    const std::pair<std::vector<std::string>, std::string> cases[] = {
        {{"--far", "0.001"}, "--far 0.001 is not beyond the near plane fitted to the scene"},
        {{"--near", "1000"}, "--near 1000 is not in front of the far plane fitted to the scene"},
    };
    for (const auto& entry : cases) {
        const std::vector<std::string>& flags_ = entry.first;
        const std::string expect = entry.second;
        CAPTURE(expect);
        std::vector<std::string> args = {"--width", "16", "--height", "12", "--only", "ao", "--out",
                                         fresh_dir("clip_planes")};
        args.insert(args.end(), flags_.begin(), flags_.end());
        const Run r = run_host(args);
        CAPTURE(r.err);
        CHECK(r.exit_code == 1);
        const auto lines = r.own_error_lines();
        REQUIRE(lines.size() == 1);
        CHECK(lines[0].find(expect) != std::string::npos);
    }
}

TEST_CASE("--method, --thickness, --steps and --max-step-texels reach the plugin") {
    // Spot, 64x48, radius 0.3, no blur, hash rotation: per pixel the
    // visibility estimator can only block more as the thickness grows.
    const std::vector<std::string> common = {"--width", "64", "--height", "48", "--only", "ao", "--radius", "0.3",
                                             "--blur", "none", "--rotation", "hash", "--output-format", "r16f"};
    auto render = [&](const std::string& name, const std::vector<std::string>& extra) {
        const std::string dir = fresh_dir(name);
        std::vector<std::string> args = common;
        args.insert(args.end(), {"--out", dir});
        args.insert(args.end(), extra.begin(), extra.end());
        const Run r = run_host(args);
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        REQUIRE(r.exit_code == 0);
        return std::make_pair(load_exr(dir + "/ao.exr"), r.out);
    };
    plugin::Library lib;
    std::string error;
    REQUIRE_MESSAGE(lib.open(plugin::Library::default_path(), error), error);
    ssao_settings want{}, d{};
    want.size = d.size = sizeof(ssao_settings);
    want.method = SSAO_METHOD_VISIBILITY;
    want.radius = 0.3f;
    REQUIRE(lib.api().resolve_settings(&want, &d) == SSAO_OK);

    const auto kernel = render("method_kernel", {"--method", "kernel"});
    const auto vis = render("method_visibility", {"--method", "visibility"});
    CHECK(kernel.second.find("ssao: kernel, ") != std::string::npos);
    std::ostringstream summary;
    summary << "ssao: visibility, " << d.sample_count << " directions x " << d.step_count << " steps, "
            << "half resolution, no blur, thickness " << d.thickness << ",";
    CHECK(vis.second.find(summary.str()) != std::string::npos);
    const Diff km = compare(kernel.first, vis.first);
    MESSAGE("kernel vs visibility: mean |diff| " << km.mean << ", max " << km.max);
    CHECK(km.mean > 0.003);
    CHECK(km.max > 0.05);

    // The plugin's own defaults given explicitly: the same image, bit for bit.
    std::ostringstream t;
    t << d.thickness;
    const auto explicit_defaults =
        render("method_explicit", {"--method", "visibility", "--steps", std::to_string(d.step_count), "--thickness", t.str()});
    CHECK(compare(vis.first, explicit_defaults.first).max == 0.0);

    // Steps: a different march, a different image.
    const auto one_step = render("method_one_step", {"--method", "visibility", "--steps", "1"});
    CHECK(one_step.second.find(" x 1 steps,") != std::string::npos);
    CHECK(compare(vis.first, one_step.first).mean > 1e-3);

    // Step length: at 160x120 a radius of 0.6 spans several grid texels, so
    // steps at most one texel apart march more of them than the fixed count
    // and find occluders the coarser steps pass over: a different image,
    // darker on the whole. (The flag given last wins.)
    const std::vector<std::string> larger = {"--method", "visibility", "--width", "160", "--height", "120", "--radius", "0.6"};
    auto with = [](std::vector<std::string> v, const std::vector<std::string>& more) {
        v.insert(v.end(), more.begin(), more.end());
        return v;
    };
    const auto fixed_steps = render("method_fixed_steps", larger);
    const auto short_steps = render("method_short_steps", with(larger, {"--max-step-texels", "1"}));
    CHECK(short_steps.second.find(", steps <= 1 texels apart") != std::string::npos);
    CHECK(fixed_steps.second.find("texels apart") == std::string::npos);  // off by default
    double sum_fixed = 0, sum_short = 0;
    for (size_t i = 0; i < fixed_steps.first.v.size(); ++i) {
        sum_fixed += fixed_steps.first.v[i];
        sum_short += short_steps.first.v[i];
    }
    MESSAGE("mean AO: fixed steps " << sum_fixed / fixed_steps.first.v.size() << ", steps <= 1 texel apart "
                                    << sum_short / fixed_steps.first.v.size());
    CHECK(compare(fixed_steps.first, short_steps.first).mean > 1e-3);
    CHECK(sum_short < sum_fixed);
    // 0 is off: the fixed count's image, bit for bit.
    const auto off = render("method_steps_off", with(larger, {"--max-step-texels", "0"}));
    CHECK(compare(fixed_steps.first, off.first).max == 0.0);

    // Thickness: a height field (huge thickness) blocks everything the
    // default blocks and more; never lighter at any pixel.
    const auto height_field = render("method_height_field", {"--method", "visibility", "--thickness", "1e30"});
    double lighter = 0, mean_default = 0, mean_height = 0;
    for (size_t i = 0; i < vis.first.v.size(); ++i) {
        lighter = std::max(lighter, double(height_field.first.v[i]) - vis.first.v[i]);
        mean_default += vis.first.v[i];
        mean_height += height_field.first.v[i];
    }
    MESSAGE("mean AO: thickness " << d.thickness << " " << mean_default / vis.first.v.size() << ", 1e30 "
                                  << mean_height / vis.first.v.size());
    CHECK(lighter <= 1e-3);
    CHECK(mean_height < mean_default - 1e-3 * vis.first.v.size());
}

TEST_CASE("scene hints set the AO settings and flags override them") {
    const std::string dir = fresh_dir("hints");
    const Run r = run_host({kData + "/hinted.gltf", "--out", dir, "--width", "48", "--height", "48", "--only", "ao"});
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("8 directions x 4 steps, half resolution, 4x4 box blur") != std::string::npos);
    CHECK(r.out.find("radius 0.75 (scene hint)") != std::string::npos);
    const Run r2 = run_host({kData + "/hinted.gltf", "--out", dir, "--width", "48", "--height", "48", "--only", "ao",
                             "--samples", "4", "--radius", "0.3", "--blur", "none"});
    REQUIRE(r2.exit_code == 0);
    CHECK(r2.out.find("4 directions x 4 steps, half resolution, no blur") != std::string::npos);
    CHECK(r2.out.find("radius 0.3 (--radius)") != std::string::npos);
    // Without hints the radius follows the scene's size.
    const Run r3 = run_host({kData + "/nested.gltf", "--out", dir, "--width", "48", "--height", "48", "--only", "ao"});
    REQUIRE(r3.exit_code == 0);
    CHECK(r3.out.find("0.05 x scene diagonal") != std::string::npos);
}

TEST_CASE("a scene hint that is no setting is refused naming it, not wrapped, truncated or ignored") {
    const std::string dir = fresh_dir("bad_hints");
    const std::string hinted = read_file(kData + "/hinted.gltf");
    struct Case {
        std::string from, to, expect;
    };
    const std::vector<Case> cases = {
        {"\"radius\": 0.75", "\"radius\": 1e300", "ssao.radius = 1e+300"},  // beyond float: not inf
        {"\"radius\": 0.75", "\"radius\": 1e-50", "ssao.radius = 1e-50"},   // below float: not 0, the default
        {"\"samples\": 8", "\"samples\": 8.9", "ssao.samples = 8.9"},       // not a whole number: not 8
        {"\"samples\": 8", "\"samples\": 1e300", "ssao.samples = 1e+300"},  // not ignored
        {"\"samples\": 8", "\"samples\": 8, \"bias\": -1e300", "ssao.bias = -1e+300"},
        {"\"samples\": 8", "\"samples\": 8, \"fade_end\": 1e300", "ssao.fade_end = 1e+300"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.to);
        std::string text = hinted;
        const size_t at = text.find(c.from);
        REQUIRE(at != std::string::npos);
        text.replace(at, c.from.size(), c.to);
        const std::string scene = (fs::path(kWork) / "bad_hint.gltf").string();
        std::ofstream(scene, std::ios::binary) << text;
        const Run r = run_host({scene, "--out", dir, "--width", "32", "--height", "32", "--only", "ao"});
        CAPTURE(r.err);
        CHECK(r.exit_code == 1);
        const auto lines = r.own_error_lines();
        CHECK(lines.size() == 1);
        if (!lines.empty()) CHECK(lines[0].find(c.expect) != std::string::npos);
    }
    // A bias below float's range is the smallest bias, not 0 (the plugin's default).
    std::string tiny_bias = hinted;
    tiny_bias.replace(tiny_bias.find("\"samples\": 8"), 12, "\"samples\": 8, \"bias\": 1e-50");
    const std::string scene = (fs::path(kWork) / "tiny_bias.gltf").string();
    std::ofstream(scene, std::ios::binary) << tiny_bias;
    const Run r = run_host({scene, "--out", dir, "--width", "32", "--height", "32", "--only", "ao"});
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("bias 1.175e-38") != std::string::npos);
}

TEST_CASE("reverse-Z, an infinite far plane and 16-bit depth give the same AO") {
    // A perspective view of the nested scene from the side.
    const std::vector<std::string> common = {kData + "/nested.gltf", "--width", "96", "--height", "96",
                                             "--eye", "7,4,3", "--target", "3,0.5,-1", "--fov", "50",
                                             "--near", "1", "--only", "ao", "--output-format", "r16f"};
    auto render = [&](const std::string& name, std::vector<std::string> extra) {
        const std::string dir = fresh_dir(name);
        std::vector<std::string> args = common;
        args.insert(args.end(), {"--out", dir});
        args.insert(args.end(), extra.begin(), extra.end());
        const Run r = run_host(args);
        INFO("stdout: " << r.out << "\nstderr: " << r.err);
        REQUIRE(r.exit_code == 0);
        return std::make_pair(load_exr(dir + "/ao.exr"), r.out);
    };
    const auto standard = render("depth_standard", {"--far", "40"});
    const auto reversed = render("depth_reversed", {"--far", "inf", "--reverse-z"});
    CHECK(reversed.second.find("reverse-Z") != std::string::npos);
    CHECK(reversed.second.find("infinite far") != std::string::npos);
    const Diff d = compare(standard.first, reversed.first);
    MESSAGE("standard vs reverse-Z infinite: mean " << d.mean << ", p99 " << d.p99);
    CHECK(d.mean < 0.01);
    const auto d16 = render("depth_d16", {"--far", "40", "--depth", "d16"});
    CHECK(d16.second.find("16-bit depth") != std::string::npos);
    const Diff e = compare(standard.first, d16.first);
    MESSAGE("d32f vs d16: mean " << e.mean << ", p99 " << e.p99);
    CHECK(e.mean < 0.02);
}

TEST_CASE("a genuine GL 3.3 core context works (--gl33)") {
    const std::string dir = fresh_dir("gl33");
    // Mesa's EGL hands out 4.5 for a 3.3 request; the override makes it 3.3.
    const Run r = run_host({"--gl33", "--out", dir, "--width", "64", "--height", "48", "--no-sheet"},
                           "MESA_GL_VERSION_OVERRIDE=3.3");
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("GL 3.3 core") != std::string::npos);
    CHECK(fs::exists(dir + "/lit_ao.png"));
    // The AO is the 4.5 context's, bit for bit.
    const std::string dir45 = fresh_dir("gl45");
    REQUIRE(run_host({"--out", dir45, "--width", "64", "--height", "48", "--no-sheet", "--only", "ao"}).exit_code == 0);
    const Image ao33 = load_exr(dir + "/ao.exr"), ao45 = load_exr(dir45 + "/ao.exr");
    REQUIRE(!ao45.v.empty());
    CHECK(*std::min_element(ao45.v.begin(), ao45.v.end()) < 0.8f);  // the cow's contact shadow: not a blank AO
    CHECK(ao33.v == ao45.v);
}
