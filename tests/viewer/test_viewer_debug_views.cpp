// ssao-viewer's debug views: X cycles settings.debug_view through
// debug_view_text's table (none -> normals -> reconstructed normals -> raw AO
// -> blur weights -> none), a preset key keeps the choice, the overlay names
// the view; in a window (xvfb-run) each view's screenshot is ssao-host's
// --debug-view picture of the same view.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>

#include "cli.h"
#include "controls.h"
#include "debug_view_text.h"
#include "overlay.h"
#include "plugin_loader.h"
#include "run_program.h"
#include "scene.h"

#include <GLFW/glfw3.h>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

const std::string kSpot = SSAO_SOURCE_DIR "/assets/models/spot-on-ground.glb";
const std::string kViewer = SSAO_VIEWER_EXE;
const std::string kHost = SSAO_HOST_EXE;
const std::string kXvfbRun = SSAO_XVFB_RUN;
const std::string kWork = SSAO_TEST_WORK_DIR;

bool contains(const std::vector<std::string>& lines, const std::string& text) {
    for (const auto& l : lines)
        if (l.find(text) != std::string::npos) return true;
    return false;
}

void tap(viewer::Controls& c, int key) {
    c.key(key, GLFW_PRESS);
    c.key(key, GLFW_RELEASE);
}

using testrun::Run;
using testrun::read_file;

std::string fresh_dir(const std::string& name) { return testrun::fresh_dir(kWork, name); }
std::string quote(const std::string& s) { return testrun::shell_quote(s); }

// `program` under `prefix` (xvfb-run for the viewer), logs beside its output in `dir`.
Run run(const std::string& prefix, const std::string& program, const std::vector<std::string>& args,
        const std::string& dir) {
    return testrun::run(program, args, dir, 120, prefix);
}

struct Png {
    int w = 0, h = 0, channels = 0;
    std::vector<unsigned char> px;
    int at(int x, int y, int c) const {
        return px[(static_cast<size_t>(y) * static_cast<size_t>(w) + static_cast<size_t>(x)) * static_cast<size_t>(channels) +
                  static_cast<size_t>(c)];
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

// Pixels of the RGB screenshot `a` that differ from `b` (grey: its one channel for each).
int differing(const Png& a, const Png& b) {
    REQUIRE(a.w == b.w);
    REQUIRE(a.h == b.h);
    int n = 0;
    for (int y = 0; y < a.h; ++y)
        for (int x = 0; x < a.w; ++x)
            for (int c = 0; c < a.channels; ++c)
                if (a.at(x, y, c) != b.at(x, y, b.channels == 1 ? 0 : c)) {
                    ++n;
                    break;
                }
    return n;
}

std::string shot(const std::string& dir, int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "/frame-%05d.png", frame);
    return dir + name;
}

constexpr int W = 160, H = 120;

// The viewer, overlay off, pressing X between screenshots: frame 1 is the
// lit picture, then frames 3, 5, 7, 9 the views in the table's order after
// none, and frame 11 none again.
std::string viewer_shots(const std::string& name) {
    REQUIRE_MESSAGE(!kXvfbRun.empty(), "xvfb-run is not installed: apt-get install xvfb xauth (scripts/install-deps.sh)");
    const std::string dir = fresh_dir(name);
    const std::string script = dir + "/script.txt";
    std::ofstream(script) << "0 O\n1 F12\n2 X\n3 F12\n4 X\n5 F12\n6 X\n7 F12\n8 X\n9 F12\n10 X\n11 F12\n";
    const Run r = run(quote(kXvfbRun) + " -a -s '-screen 0 320x240x24'", kViewer,
                      {"--width", std::to_string(W), "--height", std::to_string(H), "--script", script, "--frames", "12",
                       "--screenshot-dir", dir},
                      dir);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    REQUIRE(r.exit_code == 0);
    return dir;
}

int frame_of(ssao_debug_view v) {
    for (int i = 1; i < debug_view_text::kViewCount; ++i)
        if (debug_view_text::kViews[i].view == v) return 1 + 2 * i;
    return 1;
}

// ssao-host's picture of the bundled scene at W x H with --debug-view `name`.
std::string host_view(const char* name) {
    const std::string dir = fresh_dir(std::string("host_") + name);
    const Run r = run("", kHost,
                      {"--width", std::to_string(W), "--height", std::to_string(H), "--out", dir, "--debug-view", name},
                      dir);
    INFO("ssao-host: " << r.err);
    REQUIRE(r.exit_code == 0);
    return dir;
}

}  // namespace

TEST_CASE("X cycles the debug views in the table's order, a preset keeps it, the overlay names it") {
    plugin::Library library;
    scene::Scene scene;
    std::string error;
    REQUIRE_MESSAGE(library.open(plugin::Library::default_path(), error), error);
    REQUIRE_MESSAGE(scene::load(kSpot, scene, error), error);
    viewer::Controls c(library.api(), cli::Options{}, scene, 4.0f / 3.0f);
    ssao_timings t{};
    t.size = sizeof t;
    CHECK(c.state().settings.debug_view == SSAO_DEBUG_VIEW_NONE);
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), "view lit"));
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), "X debug view"));
    for (int i = 1; i <= debug_view_text::kViewCount; ++i) {
        const debug_view_text::Entry& e = debug_view_text::kViews[i % debug_view_text::kViewCount];
        CAPTURE(e.name);
        tap(c, GLFW_KEY_X);
        CHECK(c.state().settings.debug_view == e.view);
        const auto lines = viewer::overlay_lines(c.state(), t, 320, 240);
        if (e.view == SSAO_DEBUG_VIEW_NONE)
            CHECK(contains(lines, "view lit"));
        else
            CHECK(contains(lines, std::string("view debug ") + e.name));
        // The plugin accepts every setting X gives.
        ssao_settings r{};
        r.size = sizeof r;
        CHECK(library.api().resolve_settings(&c.state().settings, &r) == SSAO_OK);
        CHECK(r.debug_view == e.view);
    }
    // A preset key keeps the view; mode E (no SSAO) shows no debug view.
    for (int i = 0; i < 4; ++i) tap(c, GLFW_KEY_X);
    REQUIRE(c.state().settings.debug_view == SSAO_DEBUG_VIEW_BLUR_WEIGHTS);
    tap(c, GLFW_KEY_4);
    CHECK(c.state().settings.debug_view == SSAO_DEBUG_VIEW_BLUR_WEIGHTS);
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), "view debug blur-weights"));
    tap(c, GLFW_KEY_E);
    CHECK_FALSE(viewer::debug_view_shown(c.state()));
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), "view lit"));
}

TEST_CASE("X in a window: raw-ao and blur-weights screenshots are ssao-host's --debug-view pictures") {
    const std::string dir = viewer_shots("window");
    const Png lit = load_png(shot(dir, 1));
    for (const char* name : {"raw-ao", "blur-weights"}) {
        CAPTURE(name);
        const ssao_debug_view v = *debug_view_text::parse(name);
        const Png got = load_png(shot(dir, frame_of(v)));
        REQUIRE((got.w == W && got.h == H && got.channels == 3));
        const Png want = load_png(host_view(name) + "/debug_view.png");
        CHECK(want.channels == 1);
        CHECK(differing(got, want) == 0);
        CHECK(differing(got, lit) > 0);  // the screenshot changed
    }
    // X after the last view: the lit picture again.
    CHECK(differing(load_png(shot(dir, 11)), lit) == 0);
}

TEST_CASE("X in a window: the normals views show ssao-host's RGB normal pictures") {
    const std::string dir = viewer_shots("window_normals");
    for (const char* name : {"normals", "reconstructed-normals"}) {
        CAPTURE(name);
        const ssao_debug_view v = *debug_view_text::parse(name);
        const Png got = load_png(shot(dir, frame_of(v)));
        const Png want = load_png(host_view(name) + "/debug_view.png");
        REQUIRE(want.channels == 3);
        CHECK(differing(got, want) == 0);
        // A picture of view-space normals: surfaces face the camera (blue >= 0.5)
        // and the red and green channels vary over the model. Sky has no
        // normal and reads (0.5, 0.5, 0.5) (ssao.h): 127 or 128 in 8 bits.
        int facing = 0, surface = 0, red_lo = 255, red_hi = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                bool grey = true;
                for (int c = 0; c < 3; ++c) grey = grey && (got.at(x, y, c) == 127 || got.at(x, y, c) == 128);
                if (grey) continue;
                ++surface;
                facing += got.at(x, y, 2) >= 127;
                red_lo = std::min(red_lo, got.at(x, y, 0));
                red_hi = std::max(red_hi, got.at(x, y, 0));
            }
        CHECK(surface > W * H / 2);
        CHECK(facing > surface * 9 / 10);
        CHECK(red_hi - red_lo > 100);
    }
}
