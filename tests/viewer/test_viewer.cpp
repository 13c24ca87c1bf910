// ssao-viewer as a user runs it: in a virtual X server (xvfb-run; Mesa's
// llvmpipe through GLX), driven by --script, its F12 screenshots compared with
// the pictures ssao-host writes for the same scene, camera and size (the oracle:
// same G-buffer, plugin and lighting) and with ssao-reference's ray-traced AO.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const std::string kViewer = SSAO_VIEWER_EXE;
const std::string kHost = SSAO_HOST_EXE;
const std::string kReference = SSAO_REFERENCE_EXE;   // empty when not built
const std::string kXvfbRun = SSAO_XVFB_RUN;          // empty when not installed
const std::string kWork = SSAO_TEST_WORK_DIR;
// The bundled scene's view, as ssao-host and ssao-viewer choose it.
const std::vector<std::string> kBundledView = {"--eye", "2.3,1.6,-2.6", "--target", "0,0.65,0"};

std::string read_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string fresh_dir(const std::string& name) {
    const fs::path p = fs::path(kWork) / name;
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

struct Run {
    int exit_code = -1;   // -1: killed by a signal or the timeout
    std::string out, err;
    std::vector<std::string> err_lines() const {
        std::vector<std::string> lines;
        std::istringstream in(err);
        for (std::string l; std::getline(in, l);) lines.push_back(l);
        return lines;
    }
};

// Runs `program args` (after `prefix`, e.g. env settings or xvfb-run) with a
// 120 s limit, capturing both streams.
Run run(const std::string& prefix, const std::string& program, const std::vector<std::string>& args,
        const std::string& dir) {
    std::string cmd = prefix + " timeout -s KILL 120 " + quote(program);
    for (const auto& a : args) cmd += " " + quote(a);
    const std::string out = dir + "/stdout.txt", err = dir + "/stderr.txt";
    cmd += " >" + quote(out) + " 2>" + quote(err);
    const int status = std::system(cmd.c_str());
    Run r;
    if (WIFEXITED(status) && WEXITSTATUS(status) <= 128) r.exit_code = WEXITSTATUS(status);
    r.out = read_file(out);
    r.err = read_file(err);
    return r;
}

// The viewer in a fresh virtual X server (320 x 240 unless asked for more).
Run run_viewer(const std::vector<std::string>& args, const std::string& dir, const std::string& screen = "320x240") {
    REQUIRE_MESSAGE(!kXvfbRun.empty(), "xvfb-run is not installed: apt-get install xvfb xauth (scripts/install-deps.sh)");
    return run(quote(kXvfbRun) + " -a -s '-screen 0 " + screen + "x24'", kViewer, args, dir);
}

std::string write_script(const std::string& dir, const std::string& text) {
    const std::string path = dir + "/script.txt";
    std::ofstream(path) << text;
    return path;
}

struct Png {
    int w = 0, h = 0, channels = 0;
    std::vector<unsigned char> px;
    int at(int x, int y, int c = 0) const {
        return px[(static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)) * static_cast<size_t>(channels) +
                  static_cast<size_t>(c)];
    }
    // Sum of the colour channels (grey counts once per channel of an RGB image).
    int sum(int x, int y) const {
        int s = 0;
        for (int c = 0; c < channels; ++c) s += at(x, y, c);
        return s;
    }
};

Png load_png(const std::string& path) {
    Png p;
    unsigned char* data = stbi_load(path.c_str(), &p.w, &p.h, &p.channels, 0);
    REQUIRE_MESSAGE(data != nullptr, "cannot read " << path);
    p.px.assign(data, data + static_cast<size_t>(p.w) * static_cast<size_t>(p.h) * static_cast<size_t>(p.channels));
    stbi_image_free(data);
    return p;
}

std::string shot(const std::string& dir, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame-%05d.png", frame);
    return dir + name;
}

// Pixels of `a` (RGB) whose channels differ from `b`'s channel `from`..: b may
// be grey (each channel compared with its one channel) or RGB, or a panel of a
// wider sheet starting at column `x0`. Pixels inside `skip` (x, y < skip) are
// left out (the host's panel labels).
int differing(const Png& a, const Png& b, int x0 = 0, int skip = 0) {
    REQUIRE(a.h == b.h);
    REQUIRE(x0 + a.w <= b.w);
    int n = 0;
    for (int y = 0; y < a.h; ++y)
        for (int x = 0; x < a.w; ++x) {
            if (x < skip && y < skip) continue;
            for (int c = 0; c < a.channels; ++c)
                if (a.at(x, y, c) != b.at(x0 + x, y, b.channels == 1 ? 0 : c)) {
                    ++n;
                    break;
                }
        }
    return n;
}

// ssao-host's pictures of the bundled scene at w x h.
std::string host_pictures(const std::string& name, int w, int h, bool only_ao = false,
                          const std::vector<std::string>& extra = {}) {
    const std::string dir = fresh_dir(name);
    std::vector<std::string> args = {"--width", std::to_string(w), "--height", std::to_string(h), "--out", dir};
    args.insert(args.end(), extra.begin(), extra.end());
    if (only_ao) args.insert(args.end(), {"--only", "ao"});
    const Run r = run("", kHost, args, dir);
    INFO("ssao-host: " << r.err);
    REQUIRE(r.exit_code == 0);
    return dir;
}

}  // namespace

TEST_CASE("without a display it exits with one clear line") {
    const std::string dir = fresh_dir("no_display");
    for (const std::string env : {"env -u DISPLAY -u WAYLAND_DISPLAY", "env -u WAYLAND_DISPLAY DISPLAY=:987"}) {
        CAPTURE(env);
        const Run r = run(env, kViewer, {"--frames", "3", "--screenshot-dir", dir}, dir);
        CHECK(r.exit_code == 1);
        const std::vector<std::string> lines = r.err_lines();
        REQUIRE(lines.size() == 1);
        CHECK(lines[0].rfind("ssao-viewer: error: cannot open a display (", 0) == 0);
        CHECK(lines[0].find("xvfb-run") != std::string::npos);
    }
    // A bad script is refused before any window, naming the file and the line.
    const std::string script = write_script(dir, "1 E\n2 resize 10\n");
    const Run r = run("env -u DISPLAY", kViewer, {"--script", script}, dir);
    CHECK(r.exit_code == 1);
    REQUIRE(r.err_lines().size() == 1);
    CHECK(r.err_lines()[0] == "ssao-viewer: error: script " + script + ":2: expected 'FRAME resize WIDTH HEIGHT'");
    const Run bad_flag = run("", kViewer, {"--width", "0"}, dir);
    CHECK(bad_flag.exit_code == 2);
    CHECK(bad_flag.err_lines().size() == 1);
}

TEST_CASE("each mode key shows ssao-host's picture of that mode, U darkens contacts and E nothing") {
    const int W = 160, H = 120;
    const std::string host = host_pictures("modes_host", W, H);
    const std::string dir = fresh_dir("modes");
    const std::string script = write_script(dir,
                                            "0 F12\n"    // with the overlay
                                            "1 O\n"
                                            "1 F12\n"    // the first frame's settings: ssao-host's defaults
                                            "2 E\n 3 F12\n 4 R\n 5 F12\n 6 T\n 7 F12\n 8 Y\n 9 F12\n 10 U\n 11 F12\n"
                                            "12 V\n 13 F12\n"   // AO only, mode U
                                            "14 E\n 15 F12\n");  // AO only, mode E
    const Run r = run_viewer({"--width", std::to_string(W), "--height", std::to_string(H), "--script", script,
                              "--frames", "16", "--screenshot-dir", dir},
                             dir);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.out.find("screenshot: " + shot(dir, 15)) != std::string::npos);

    const Png lit_ao = load_png(host + "/lit_ao.png"), lit_no_ao = load_png(host + "/lit_no_ao.png");
    const Png sheet = load_png(host + "/modes.png");
    const Png first = load_png(shot(dir, 1));
    REQUIRE((first.w == W && first.h == H && first.channels == 3));
    CHECK(differing(first, lit_ao) == 0);
    // E R T Y U against the host's mode sheet (panels left to right, each
    // labelled in its top-left corner, which is left out).
    const int frames[5] = {3, 5, 7, 9, 11};
    for (int m = 0; m < 5; ++m) {
        CAPTURE("ERTYU"[m]);
        CHECK(differing(load_png(shot(dir, frames[m])), sheet, m * W, 12) == 0);
    }
    // U is the defaults with the chapter's hemisphere, accelerating
    // distribution and 4x4 noise: ssao-host with the same flags.
    const std::string host_u = host_pictures("modes_host_u", W, H, false,
                                             {"--kernel", "hemisphere", "--distribution", "accelerating", "--rotation", "noise"});
    const Png e = load_png(shot(dir, 3)), u = load_png(shot(dir, 11));
    CHECK(differing(e, lit_no_ao) == 0);
    CHECK(differing(u, load_png(host_u + "/lit_ao.png")) == 0);
    // AO only: U is the host's AO image, E is white everywhere.
    const Png u_ao = load_png(shot(dir, 13)), e_ao = load_png(shot(dir, 15));
    CHECK(differing(u_ao, load_png(host_u + "/ao.png")) == 0);
    int not_white = 0;
    for (unsigned char v : e_ao.px) not_white += v != 255;
    CHECK(not_white == 0);

    // The AO only darkens (it scales the ambient term), and it darkens where
    // the ray-traced truth says surfaces meet, not in the open.
    int brighter = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) brighter += u.sum(x, y) > e.sum(x, y);
    CHECK(brighter == 0);
    if (!kReference.empty()) {
        std::vector<std::string> args = {"--width", std::to_string(W), "--height", std::to_string(H), "--samples", "256",
                                         "--quiet", "--out", dir};
        args.insert(args.end(), kBundledView.begin(), kBundledView.end());
        const Run ref = run("", kReference, args, dir);
        REQUIRE_MESSAGE(ref.exit_code == 0, ref.err);
        const Png truth = load_png(dir + "/reference_ao.png");
        double contact = 0, open = 0;
        int contacts = 0, opens = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const int t = truth.at(x, y);
                const double darker = (e.sum(x, y) - u.sum(x, y)) / 3.0;
                if (e.sum(x, y) == 0) continue;   // sky
                if (t < 0.7 * 255) contact += darker, ++contacts;
                else if (t >= 0.98 * 255) open += darker, ++opens;
            }
        REQUIRE(contacts > 100);
        REQUIRE(opens > 1000);
        MESSAGE("U darker than E by " << contact / contacts << " levels at " << contacts << " contact pixels, "
                                      << open / opens << " at " << opens << " open ones");
        CHECK(contact / contacts > 3.0);
        CHECK(contact / contacts > 10.0 * (open / opens));
    }

    // The overlay changes the picture (it is checked for its extent at 480 px in its own test).
    CHECK(differing(load_png(shot(dir, 0)), first) > 1000);
}

TEST_CASE("at 480 px the overlay, GPU line included, lies inside the window: a band at the top left") {
    const int W = 480, H = 360;
    const std::string dir = fresh_dir("overlay_480");
    // The GPU line needs a finished timed frame: shoot on frame 12 with the overlay, 14 without. The AO
    // view (V) is light everywhere, sky included, so the overlay's dark band changes every pixel it covers.
    const Run r = run_viewer({"--width", std::to_string(W), "--height", std::to_string(H), "--script",
                              write_script(dir, "0 H\n0 V\n12 F12\n13 O\n14 F12\n"), "--frames", "15", "--screenshot-dir", dir},
                             dir, "640x480");
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    const Png on = load_png(shot(dir, 12)), off = load_png(shot(dir, 14));
    REQUIRE((on.w == W && on.h == H));
    int changed = 0, right = 0, bottom = 0, last_row = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x)
            for (int c = 0; c < 3; ++c)
                if (on.at(x, y, c) != off.at(x, y, c)) {
                    ++changed;
                    right = std::max(right, x);
                    last_row = std::max(last_row, y);
                    if (y >= H / 2) ++bottom;
                    break;
                }
    MESSAGE("the overlay's band: " << right + 1 << " x " << last_row + 1 << " px");
    CHECK(changed > 5000);
    // Its band ends before the right edge: no line runs off the window (before, the GPU line and the key help did,
    // and the band reached the last column).
    CHECK(right < W - 1);
    CHECK(bottom == 0);
}

TEST_CASE("after a resize the AO matches a fresh start at that size") {
    const std::string dir = fresh_dir("resize");
    const std::string script = write_script(dir,
                                            "0 O\n0 V\n"
                                            "2 resize 192 96\n5 F12\n"
                                            "6 resize 128 112\n9 F12\n"
                                            "10 resize 160 120\n13 F12\n");
    const Run r = run_viewer({"--width", "160", "--height", "120", "--script", script, "--frames", "14",
                              "--screenshot-dir", dir},
                             dir);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    const struct {
        int frame, w, h;
    } after[] = {{5, 192, 96}, {9, 128, 112}, {13, 160, 120}};
    for (const auto& a : after) {
        CAPTURE(a.w);
        CAPTURE(a.h);
        const Png got = load_png(shot(dir, a.frame));
        REQUIRE((got.w == a.w && got.h == a.h));
        const Png fresh = load_png(host_pictures("resize_host", a.w, a.h, true) + "/ao.png");
        CHECK(differing(got, fresh) == 0);
    }
    // And a fresh viewer at the first new size.
    const std::string fresh_dir_ = fresh_dir("resize_fresh");
    const Run f = run_viewer({"--width", "192", "--height", "96", "--script",
                              write_script(fresh_dir_, "0 O\n0 V\n1 F12\n"), "--frames", "2", "--screenshot-dir",
                              fresh_dir_},
                             fresh_dir_);
    REQUIRE(f.exit_code == 0);
    CHECK(differing(load_png(shot(dir, 5)), load_png(shot(fresh_dir_, 1))) == 0);
}

TEST_CASE("resizing reallocates without leaking") {
    const std::string dir = fresh_dir("leak");
    // 60 resizes between 160 x 120 and 256 x 192, the memory read after 10 and after 60.
    std::string text;
    for (int i = 0; i < 60; ++i) text += std::to_string(2 * i) + (i % 2 ? " resize 256 192\n" : " resize 160 120\n");
    text += "21 memory\n119 memory\n";
    const Run r = run_viewer({"--width", "160", "--height", "120", "--script", write_script(dir, text), "--frames", "121"},
                             dir);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    std::vector<long> kib;
    std::istringstream in(r.out);
    for (std::string line; std::getline(in, line);) {
        const size_t at = line.find("resident ");
        if (at != std::string::npos) kib.push_back(std::stol(line.substr(at + 9)));
    }
    REQUIRE(kib.size() == 2);
    MESSAGE("resident after 10 resizes " << kib[0] << " KiB, after 60 " << kib[1] << " KiB");
    // A G-buffer and lighting target left behind per resize would be ~1.5 MiB each: 75 MiB.
    CHECK(kib[1] - kib[0] < 8 * 1024);
}

TEST_CASE("C brings the start view back: the same picture as before flying and turning") {
    const std::string dir = fresh_dir("reset");
    const std::string script = write_script(dir,
                                            "0 O\n1 F12\n"          // the start view, no overlay
                                            "2 hold W 20\n"         // fly forward
                                            "22 hold L 10\n"        // and turn
                                            "33 F12\n"
                                            "34 C\n35 F12\n");
    const Run r = run_viewer({"--width", "160", "--height", "120", "--script", script, "--frames", "36",
                              "--screenshot-dir", dir},
                             dir);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    const Png start = load_png(shot(dir, 1)), moved = load_png(shot(dir, 33)), reset = load_png(shot(dir, 35));
    CHECK(differing(moved, start) > 160 * 120 / 10);
    CHECK(differing(reset, start) == 0);
    CHECK(r.out.find("frame 34: press C\n") != std::string::npos);
}

TEST_CASE("the shipped demo script runs every event and quits where it says") {
    const std::string dir = fresh_dir("demo");
    std::ifstream in(SSAO_DEMO_SCRIPT);
    REQUIRE_MESSAGE(in.good(), "cannot read " << SSAO_DEMO_SCRIPT);
    // The events the file holds, as the viewer logs them ("frame N: press K", a tap's release a frame later).
    std::vector<std::string> want;
    long quit_frame = -1;
    for (std::string line; std::getline(in, line);) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string x; words >> x;) w.push_back(x);
        if (w.empty()) continue;
        if (w[1] == "quit") {
            quit_frame = std::stol(w[0]);
        } else if (w[1] == "hold") {
            want.push_back("frame " + w[0] + ": press " + w[2]);
            want.push_back("frame " + std::to_string(std::stol(w[0]) + std::stol(w[3])) + ": release " + w[2]);
        } else {
            want.push_back("frame " + w[0] + ": press " + w[1]);
            want.push_back("frame " + std::to_string(std::stol(w[0]) + 1) + ": release " + w[1]);
        }
    }
    REQUIRE(quit_frame > 0);
    REQUIRE(want.size() >= 20);
    // Small and with a frame limit past its end, so only the script's quit ends it.
    const Run r = run_viewer({"--width", "96", "--height", "72", "--script", SSAO_DEMO_SCRIPT, "--frames",
                              std::to_string(quit_frame + 50)},
                             dir);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.empty());
    for (const auto& line : want) {
        INFO(line);
        CHECK(r.out.find(line + "\n") != std::string::npos);
    }
    CHECK(r.out.find("frame " + std::to_string(quit_frame) + ": quit\n") != std::string::npos);
    // Its keys are the documented ones: modes, presets, blur, estimator, resolution, debug views, a flight and C.
    for (const char* key : {"press U", "press 3", "press B", "press M", "press H", "press X", "press W", "press C"}) {
        INFO(key);
        CHECK(r.out.find(key) != std::string::npos);
    }
}

TEST_CASE("--help is complete and names the demo script it ships") {
    const std::string dir = fresh_dir("help");
    const Run r = run("", kViewer, {"--help"}, dir);
    REQUIRE(r.exit_code == 0);
    for (const char* text : {"  X  ", "debug view", "  C  ", "start view", "viewer/demo.txt"}) {
        INFO(text);
        CHECK(r.out.find(text) != std::string::npos);
    }
    const size_t at = r.out.find("A tour of the keys: ");
    REQUIRE(at != std::string::npos);
    const std::string path = r.out.substr(at + 20, r.out.find('\n', at) - at - 20);
    CHECK(fs::equivalent(path, SSAO_DEMO_SCRIPT));
}

TEST_CASE("a directory, a non-glTF file, a misspelled flag: one line each, before any window") {
    const std::string dir = fresh_dir("refusals");
    const std::string folder = dir + "/folder.glb", obj = dir + "/model.obj";
    fs::create_directories(folder);
    std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    struct Case {
        std::vector<std::string> args;
        int code;
        std::string line;
    };
    const Case cases[] = {
        // Before: "cannot read the file."
        {{folder}, 1, "ssao-viewer: error: cannot load the scene: " + folder + ": not a regular file but a directory."},
        // Before: tinygltf's raw JSON parse error.
        {{obj}, 1, "ssao-viewer: error: cannot load the scene: " + obj +
                       ": not a glTF scene; the tools read glTF 2.0 only (a .gltf JSON file or a .glb binary), "
                       "converted with e.g. Blender or obj2gltf."},
        {{"--widht", "64"}, 2, "ssao-viewer: error: unknown flag '--widht'; did you mean --width? (see --help)"},
        // Before: chapter was refused here but taken by ssao-host.
        {{"--preset", "best"}, 2, "ssao-viewer: error: --preset expects one of low|medium|high|ultra|chapter, got 'best'"},
    };
    for (const Case& c : cases) {
        const Run r = run("env -u DISPLAY", kViewer, c.args, dir);
        INFO(r.err);
        CHECK(r.exit_code == c.code);
        REQUIRE(r.err_lines().size() == 1);
        CHECK(r.err_lines()[0] == c.line);
    }
    // --preset chapter and --allow-outside-files are taken (the run then stops for want of a display).
    const Run r = run("env -u DISPLAY -u WAYLAND_DISPLAY", kViewer, {"--preset", "chapter", "--allow-outside-files"}, dir);
    CHECK(r.exit_code == 1);
    REQUIRE(r.err_lines().size() == 1);
    CHECK(r.err_lines()[0].rfind("ssao-viewer: error: cannot open a display (", 0) == 0);
    const Run help = run("", kViewer, {"--help"}, dir);
    CHECK(help.out.find("--allow-outside-files") != std::string::npos);
    CHECK(help.out.find("low|medium|high|ultra|chapter") != std::string::npos);
    CHECK(help.out.find("the bundled view of the cow") != std::string::npos);
}
