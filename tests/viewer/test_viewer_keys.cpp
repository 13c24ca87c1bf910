// ssao-viewer without a window: the script parser, the command line, what each
// key does to the settings and the camera, and the overlay's text. The plugin
// is loaded (dlopen) for its presets and defaults; no GL context is made.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "cli.h"
#include "controls.h"
#include "modes.h"
#include "options.h"
#include "overlay.h"
#include "plugin_loader.h"
#include "run_setup.h"
#include "scene.h"
#include "script.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace {

const std::string kSpot = SSAO_SOURCE_DIR "/assets/models/spot-on-ground.glb";

struct Fixture {
    plugin::Library library;
    scene::Scene scene;
    Fixture() {
        std::string error;
        REQUIRE_MESSAGE(library.open(plugin::Library::default_path(), error), error);
        REQUIRE_MESSAGE(scene::load(kSpot, scene, error), error);
    }
    const ssao_api& api() const { return library.api(); }
    viewer::Controls controls(std::optional<ssao_preset> preset = std::nullopt) {
        cli::Options base;
        base.preset = preset;
        return viewer::Controls(api(), base, scene, 4.0f / 3.0f);
    }
    ssao_settings preset(ssao_preset p) {
        ssao_settings s{};
        s.size = sizeof s;
        REQUIRE(api().preset_settings(p, &s) == SSAO_OK);
        return s;
    }
};

void tap(viewer::Controls& c, int key) {
    c.key(key, GLFW_PRESS);
    c.key(key, GLFW_RELEASE);
}

// Holds `key` for `frames` frames of 1/30 s, as a script's "hold" does.
void hold(viewer::Controls& c, int key, int frames) {
    c.key(key, GLFW_PRESS);
    for (int i = 0; i < frames; ++i) c.advance(1.0f / 30.0f);
    c.key(key, GLFW_RELEASE);
}

glm::vec3 forward(const camera::Camera& c) { return glm::normalize(c.target - c.eye); }

// The overlay's lines with the window-fitting undone: a continuation (two
// spaces first) joined back to the line it was broken from.
std::vector<std::string> unwrapped(const std::vector<std::string>& lines) {
    std::vector<std::string> out;
    for (const auto& l : lines) {
        if (!out.empty() && l.rfind("  ", 0) == 0)
            out.back() += l;
        else
            out.push_back(l);
    }
    return out;
}

bool contains(const std::vector<std::string>& lines, const std::string& text) {
    for (const auto& l : unwrapped(lines))
        if (l.find(text) != std::string::npos) return true;
    return false;
}

// A 1.1 timing of every pass the plugin can run, each with a long number.
ssao_timings all_pass_timings() {
    ssao_timings t{};
    t.size = sizeof t;
    t.available = 1;
    t.frame = 123456;
    const uint32_t kinds[] = {SSAO_PASS_CLEAR, SSAO_PASS_GRID, SSAO_PASS_OCCLUSION, SSAO_PASS_BLUR_X, SSAO_PASS_BLUR_Y,
                              SSAO_PASS_UPSAMPLE};
    t.pass_count = 6;
    for (uint32_t i = 0; i < t.pass_count; ++i) {
        t.pass_kind[i] = kinds[i];
        t.pass_ms[i] = 123.456 + i;
    }
    t.total_ms = 999.999;
    return t;
}

}  // namespace

TEST_CASE("scripts: taps, holds, resizes and their errors") {
    std::vector<viewer::ScriptEvent> e;
    std::string error;
    REQUIRE(viewer::parse_script("# comment\n\n5 e   # tap\n2 resize 200 150\n3 hold w 4\n9 F12\n9 memory\n12 quit\n", e, error));
    using K = viewer::ScriptEvent::Kind;
    // Sorted by frame; a tap releases on the next frame, a hold after its length.
    REQUIRE(e.size() == 9);
    CHECK((e[0].frame == 2 && e[0].kind == K::Resize && e[0].width == 200 && e[0].height == 150));
    CHECK((e[1].frame == 3 && e[1].kind == K::Press && e[1].key == GLFW_KEY_W));
    CHECK((e[2].frame == 5 && e[2].kind == K::Press && e[2].key == GLFW_KEY_E));
    CHECK((e[3].frame == 6 && e[3].kind == K::Release && e[3].key == GLFW_KEY_E));
    CHECK((e[4].frame == 7 && e[4].kind == K::Release && e[4].key == GLFW_KEY_W));
    CHECK((e[5].frame == 9 && e[5].kind == K::Press && e[5].key == GLFW_KEY_F12));
    CHECK((e[6].frame == 9 && e[6].kind == K::Memory));
    CHECK((e[7].frame == 10 && e[7].kind == K::Release && e[7].key == GLFW_KEY_F12));
    CHECK((e[8].frame == 12 && e[8].kind == K::Quit));

    const std::vector<std::pair<std::string, std::string>> bad = {
        {"x E", "1: 'x' is not a frame number"},
        {"-1 E", "1: '-1' is not a frame number"},
        {"\n3 NOPE", "2: unknown key 'NOPE'"},
        {"3 F13", "1: unknown key 'F13'"},
        {"3 resize 0 10", "1: resize needs a width and a height"},
        {"3 resize 10", "1: expected 'FRAME resize WIDTH HEIGHT'"},
        {"3 hold W", "1: expected 'FRAME hold KEY FRAMES'"},
        {"3 hold W 0", "1: hold needs a number of frames"},
        {"3", "1: expected 'FRAME KEY'"},
        {"3 E E", "1: expected 'FRAME KEY'"},
    };
    for (const auto& [text, message] : bad) {
        CAPTURE(text);
        error.clear();
        e.assign(3, viewer::ScriptEvent{});
        CHECK_FALSE(viewer::parse_script(text, e, error));
        CHECK(error.rfind(message, 0) == 0);
        CHECK(e.size() == 3);   // untouched on failure
    }
    CHECK(viewer::key_from_name("space") == GLFW_KEY_SPACE);
    CHECK(viewer::key_from_name("f1") == GLFW_KEY_F1);
    for (int k : {GLFW_KEY_A, GLFW_KEY_Z, GLFW_KEY_0, GLFW_KEY_9, GLFW_KEY_F12, GLFW_KEY_ESCAPE})
        CHECK(viewer::key_from_name(viewer::key_name(k)) == k);
}

TEST_CASE("the command line") {
    viewer::Options o;
    std::string error;
    const char* ok[] = {"ssao-viewer", "scene.glb", "--width=320", "--height", "240", "--preset", "high",
                        "--script", "s.txt", "--frames", "12", "--screenshot-dir", "shots"};
    REQUIRE(viewer::parse(13, ok, o, error) == viewer::Parse::Run);
    CHECK(o.scene_path == "scene.glb");
    CHECK((o.width == 320 && o.height == 240 && o.frames == 12));
    CHECK((o.preset && *o.preset == SSAO_PRESET_HIGH));
    CHECK((o.script_path == "s.txt" && o.screenshot_dir == "shots"));
    const std::vector<std::vector<const char*>> bad = {
        {"ssao-viewer", "--width", "0"},       {"ssao-viewer", "--frames", "-3"},
        {"ssao-viewer", "--preset", "insane"}, {"ssao-viewer", "--bogus"},
        {"ssao-viewer", "--script"},
    };
    for (const auto& argv : bad) {
        viewer::Options b;
        error.clear();
        CAPTURE(argv.back());
        CHECK(viewer::parse(static_cast<int>(argv.size()), argv.data(), b, error) == viewer::Parse::Error);
        CHECK_FALSE(error.empty());
    }
}

TEST_CASE("the first frame's settings and camera are ssao-host's") {
    Fixture f;
    viewer::Controls c = f.controls();
    cli::Options host;
    std::string note;
    const ssao_settings expected = run_setup::build_settings(f.api(), host, f.scene, note);
    CHECK(std::memcmp(&c.state().settings, &expected, sizeof expected) == 0);
    CHECK(c.state().ssao);
    camera::Source from_scene = camera::Source::Framed;
    const camera::Camera cam = run_setup::build_camera(host, f.scene, 4.0f / 3.0f, from_scene);
    CHECK(c.camera().eye == cam.eye);
    CHECK(c.camera().target == cam.target);
    CHECK(c.camera().eye == camera::kBundledEye);
}

TEST_CASE("E R T Y U set the mode sheet's fields and keep the rest") {
    Fixture f;
    viewer::Controls c = f.controls(SSAO_PRESET_HIGH);
    const ssao_settings before = c.state().settings;
    for (const modes::Mode& m : modes::kModes) {
        CAPTURE(m.letter);
        tap(c, GLFW_KEY_A + (m.letter - 'A'));
        const ssao_settings& s = c.state().settings;
        CHECK(c.state().mode == m.letter);
        CHECK(c.state().ssao == m.ssao);
        if (m.ssao) {
            CHECK(s.rotation == m.rotation);
            CHECK(s.distribution == m.distribution);
            CHECK(s.kernel_shape == m.kernel);
        }
        CHECK(s.sample_count == before.sample_count);
        CHECK(s.blur == before.blur);
        CHECK(s.radius == before.radius);
    }
    // The table is the reference demo's: E has no SSAO, U is the hemisphere.
    CHECK_FALSE(modes::find('E')->ssao);
    CHECK(modes::find('U')->kernel == SSAO_KERNEL_HEMISPHERE);
    CHECK(modes::find('R')->rotation == SSAO_ROTATION_NONE);
    CHECK(modes::find('X') == nullptr);
}

TEST_CASE("1..4 pick the plugin's presets with the scene's radius, 0 the defaults") {
    Fixture f;
    viewer::Controls c = f.controls();
    const float radius = c.state().settings.radius;
    const ssao_settings defaults = c.state().settings;
    const ssao_preset presets[4] = {SSAO_PRESET_LOW, SSAO_PRESET_MEDIUM, SSAO_PRESET_HIGH, SSAO_PRESET_ULTRA};
    for (int i = 0; i < 4; ++i) {
        CAPTURE(i + 1);
        tap(c, GLFW_KEY_E);   // a mode first: the preset key replaces it
        tap(c, GLFW_KEY_1 + i);
        const ssao_settings p = f.preset(presets[i]);
        const ssao_settings& s = c.state().settings;
        CHECK(s.sample_count == p.sample_count);
        CHECK(s.distribution == p.distribution);
        CHECK(s.blur == p.blur);
        CHECK(s.radius == radius);   // scene-scaled, not the preset's
        CHECK((c.state().preset && *c.state().preset == presets[i]));
        CHECK(c.state().ssao);
        CHECK(c.state().mode == 0);
    }
    tap(c, GLFW_KEY_KP_3);   // the keypad's digits work alike
    CHECK((c.state().preset && *c.state().preset == SSAO_PRESET_HIGH));
    tap(c, GLFW_KEY_0);
    CHECK(std::memcmp(&c.state().settings, &defaults, sizeof defaults) == 0);
    CHECK_FALSE(c.state().preset);
}

TEST_CASE("B steps through every blur and back, V, O, F12 and Esc") {
    Fixture f;
    viewer::Controls c = f.controls();
    std::vector<ssao_blur> seen = {c.state().settings.blur};
    for (int i = 0; i < 4; ++i) {
        tap(c, GLFW_KEY_B);
        seen.push_back(c.state().settings.blur);
    }
    // The cycle depth-aware -> 4x4 box -> gaussian -> none -> depth-aware, from wherever the defaults start it.
    const std::vector<ssao_blur> cycle = {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_NONE};
    const auto start = std::find(cycle.begin(), cycle.end(), seen[0]);
    REQUIRE(start != cycle.end());
    for (size_t i = 0; i < seen.size(); ++i)
        CHECK(seen[i] == cycle[(size_t(start - cycle.begin()) + i) % cycle.size()]);
    // Every blur B gives is one the plugin accepts.
    for (ssao_blur b : seen) {
        ssao_settings s = c.state().settings, r{};
        s.blur = b;
        r.size = sizeof r;
        CHECK(f.api().resolve_settings(&s, &r) == SSAO_OK);
    }
    CHECK(c.state().view == viewer::View::Lit);
    tap(c, GLFW_KEY_V);
    CHECK(c.state().view == viewer::View::AoOnly);
    tap(c, GLFW_KEY_V);
    CHECK(c.state().view == viewer::View::Lit);
    tap(c, GLFW_KEY_O);
    CHECK_FALSE(c.state().overlay);
    CHECK_FALSE(c.take_screenshot());
    tap(c, GLFW_KEY_F12);
    CHECK(c.take_screenshot());
    CHECK_FALSE(c.take_screenshot());   // once per press
    CHECK_FALSE(c.quit());
    tap(c, GLFW_KEY_ESCAPE);
    CHECK(c.quit());
}

TEST_CASE("WASD QZ move the eye, IJKL turn the view") {
    Fixture f;
    viewer::Controls c = f.controls();
    const camera::Camera start = c.camera();
    const float speed = 0.15f * glm::length(f.scene.bounds_max - f.scene.bounds_min);   // per second
    const glm::vec3 fwd = forward(start);
    const glm::vec3 right = glm::normalize(glm::cross(fwd, glm::vec3(0, 1, 0)));

    // Nothing held: nothing moves.
    c.advance(1.0f);
    CHECK(c.camera().eye == start.eye);

    hold(c, GLFW_KEY_W, 15);   // half a second forward
    CHECK(glm::length(c.camera().eye - (start.eye + fwd * speed * 0.5f)) < 1e-4f);
    CHECK(glm::length(forward(c.camera()) - fwd) < 1e-5f);
    hold(c, GLFW_KEY_S, 15);
    CHECK(glm::length(c.camera().eye - start.eye) < 1e-4f);
    hold(c, GLFW_KEY_D, 30);
    CHECK(glm::length(c.camera().eye - (start.eye + right * speed)) < 1e-4f);
    hold(c, GLFW_KEY_A, 30);
    hold(c, GLFW_KEY_Q, 30);
    CHECK(glm::length(c.camera().eye - (start.eye + glm::vec3(0, speed, 0))) < 1e-4f);
    hold(c, GLFW_KEY_Z, 30);
    CHECK(glm::length(c.camera().eye - start.eye) < 1e-4f);

    // L for 1.5 s at 60 degrees a second: a quarter turn to the right, about +y.
    hold(c, GLFW_KEY_L, 45);
    const glm::vec3 f1 = forward(c.camera());
    CHECK(glm::length(c.camera().eye - start.eye) < 1e-4f);
    CHECK(std::fabs(f1.y - fwd.y) < 1e-4f);   // the pitch is kept
    CHECK(glm::dot(glm::normalize(glm::vec3(f1.x, 0, f1.z)), right) == doctest::Approx(1.0f).epsilon(1e-4));
    hold(c, GLFW_KEY_J, 45);
    CHECK(glm::length(forward(c.camera()) - fwd) < 1e-4f);
    // I looks up, K down, never past vertical.
    hold(c, GLFW_KEY_I, 15);
    CHECK(forward(c.camera()).y > fwd.y + 0.1f);
    hold(c, GLFW_KEY_K, 300);
    CHECK(forward(c.camera()).y > -1.0f + 1e-4f);
    CHECK(forward(c.camera()).y < -0.999f);
    // Moving refits near and far to the scene (camera::apply), as ssao-host does for --eye.
    CHECK(c.camera().znear > 0.0f);
    CHECK(c.camera().zfar > c.camera().znear);
}

TEST_CASE("the overlay states the settings, the GPU milliseconds and what a key could not do") {
    Fixture f;
    viewer::Controls c = f.controls();
    ssao_timings t{};
    t.size = sizeof t;
    std::vector<std::string> lines = viewer::overlay_lines(c.state(), t, 320, 240);
    CHECK(contains(lines, "320x240"));
    // The viewer starts from the plugin's defaults (a zeroed struct: the DEFAULT preset).
    const ssao_settings& start = c.state().settings;
    CHECK(contains(lines, "samples " + std::to_string(start.sample_count)));
    CHECK(contains(lines, std::string("blur ") + cli::name(start.blur)));
    CHECK(contains(lines, "GPU ms: waiting"));
    t.available = 1;
    t.frame = 7;
    t.ao_ms = 1.25;
    t.blur_ms = 0.5;
    t.total_ms = 1.75;
    tap(c, GLFW_KEY_U);
    const ssao_blur before = c.state().settings.blur;
    tap(c, GLFW_KEY_B);
    lines = viewer::overlay_lines(c.state(), t, 320, 240);
    CHECK(contains(lines, "mode U hemisphere"));
    CHECK(c.state().settings.blur != before);
    CHECK(contains(lines, std::string("blur ") + cli::name(c.state().settings.blur)));
    // The estimator's time under its debug group's (brief) name.
    const std::string estimator = c.state().settings.method == SSAO_METHOD_VISIBILITY ? "vis" : "kernel";
    CHECK(contains(lines, estimator + " 1.250  blur 0.500  total 1.750"));
#ifdef SSAO_MAX_PASSES   // interface 1.1 timings: every pass on its own
    t.pass_count = 3;
    t.pass_kind[0] = SSAO_PASS_OCCLUSION;
    t.pass_kind[1] = SSAO_PASS_BLUR_X;
    t.pass_kind[2] = SSAO_PASS_BLUR_Y;
    t.pass_ms[0] = 1.25;
    t.pass_ms[1] = 0.25;
    t.pass_ms[2] = 0.25;
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240),
                   "GPU ms (frame 7): " + estimator + " 1.250  blur x 0.250  blur y 0.250  total 1.750"));   // on fitted lines
    t.pass_count = 0;
#endif
    tap(c, GLFW_KEY_3);
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), "preset HIGH"));
    tap(c, GLFW_KEY_E);
    lines = viewer::overlay_lines(c.state(), t, 320, 240);
    CHECK(contains(lines, "SSAO off"));
    CHECK_FALSE(contains(lines, "GPU ms"));
}

TEST_CASE("H steps the resolution full -> half -> quarter -> full, the overlay shows it, the plugin accepts it") {
    Fixture f;
    viewer::Controls c = f.controls();
    ssao_timings t{};
    t.size = sizeof t;
    // The cycle full -> half -> quarter -> full, from wherever the defaults start.
    const ssao_resolution cycle[] = {SSAO_RESOLUTION_FULL, SSAO_RESOLUTION_HALF, SSAO_RESOLUTION_QUARTER};
    const char* names[] = {"resolution full", "resolution half", "resolution quarter"};
    int at = 0;
    while (at < 3 && cycle[at] != c.state().settings.resolution) ++at;
    REQUIRE(at < 3);
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), names[at]));
    for (int i = 0; i < 3; ++i) {
        CAPTURE(i);
        tap(c, GLFW_KEY_H);
        at = (at + 1) % 3;
        CHECK(c.state().settings.resolution == cycle[at]);
        CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), names[at]));
        ssao_settings r{};
        r.size = sizeof r;
        CHECK(f.api().resolve_settings(&c.state().settings, &r) == SSAO_OK);
        CHECK(r.resolution == cycle[at]);
    }
#ifdef SSAO_MAX_PASSES
    t.available = 1;
    t.frame = 3;
    t.pass_count = 3;
    t.pass_kind[0] = SSAO_PASS_GRID;
    t.pass_kind[1] = SSAO_PASS_OCCLUSION;
    t.pass_kind[2] = SSAO_PASS_UPSAMPLE;
    t.pass_ms[0] = 0.125;
    t.pass_ms[1] = 1.0;
    t.pass_ms[2] = 0.5;
    t.total_ms = 1.625;
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240),
                   std::string("GPU ms (frame 3): grid 0.125  ") +
                       (c.state().settings.method == SSAO_METHOD_VISIBILITY ? "vis" : "kernel") + " 1.000  up 0.500  total 1.625"));
#endif
}

TEST_CASE("M switches the estimator when the plugin has one") {
    Fixture f;
    viewer::Controls c = f.controls();
    ssao_timings t{};
    t.size = sizeof t;
#ifdef SSAO_SETTINGS_SIZE_1_0   // interface 1.1 has ssao_settings.method
    const ssao_method first = c.state().settings.method;
    const ssao_method other = first == SSAO_METHOD_VISIBILITY ? SSAO_METHOD_KERNEL : SSAO_METHOD_VISIBILITY;
    auto shown = [](ssao_method m) { return m == SSAO_METHOD_VISIBILITY ? "estimator visibility" : "estimator kernel"; };
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), shown(first)));
    tap(c, GLFW_KEY_M);
    CHECK(c.state().settings.method == other);
    ssao_settings r{};
    r.size = sizeof r;
    CHECK(f.api().resolve_settings(&c.state().settings, &r) == SSAO_OK);
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), shown(other)));
    tap(c, GLFW_KEY_M);
    CHECK(c.state().settings.method == first);
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), shown(first)));
#else
    tap(c, GLFW_KEY_M);
#endif
#ifdef SSAO_SETTINGS_SIZE_1_0
    tap(c, GLFW_KEY_M);
    tap(c, GLFW_KEY_2);   // a preset key brings the preset's estimator back
    CHECK(c.state().settings.method == f.preset(SSAO_PRESET_MEDIUM).method);
#else
    // HOOK(method): a 1.0 header has no estimator; the key says so.
    CHECK(contains(viewer::overlay_lines(c.state(), t, 320, 240), "no estimator choice"));
#endif
}

TEST_CASE("C puts the camera back to the start view, from a script as from the keyboard") {
    Fixture f;
    viewer::Controls c = f.controls();
    const camera::Camera start = c.camera();
    // The README's complaint: W held for 3 s flies into the model; C brings the start view back.
    std::vector<viewer::ScriptEvent> events;
    std::string error;
    REQUIRE_MESSAGE(viewer::parse_script("0 hold W 90\n90 hold L 20\n111 C\n", events, error), error);
    size_t next = 0;
    // As the viewer's frame loop runs a script: the frame's events, then the held keys move the camera.
    for (long frame = 0; frame < 113; ++frame) {
        for (; next < events.size() && events[next].frame <= frame; ++next)
            c.key(events[next].key, events[next].kind == viewer::ScriptEvent::Kind::Press ? GLFW_PRESS : GLFW_RELEASE);
        c.advance(1.0f / 30.0f);
        if (frame == 110) {   // flown forward and turned before C
            CHECK(glm::length(c.camera().eye - start.eye) > 0.1f);
            CHECK(glm::length(forward(c.camera()) - forward(start)) > 0.1f);
        }
    }
    CHECK(c.camera().eye == start.eye);
    CHECK(c.camera().target == start.target);
    CHECK(c.camera().znear == start.znear);
    CHECK(c.camera().zfar == start.zfar);
    // The next move flies from the start view again.
    hold(c, GLFW_KEY_W, 1);
    CHECK(glm::length(c.camera().eye - start.eye) < 0.1f);
    CHECK(glm::dot(forward(c.camera()), forward(start)) > 0.999f);
}

TEST_CASE("the overlay fits the window: at 480 px every line, the GPU line of six passes included") {
    Fixture f;
    viewer::Controls c = f.controls();
    if (c.state().settings.method != SSAO_METHOD_VISIBILITY) tap(c, GLFW_KEY_M);   // the longest settings line
    REQUIRE(c.state().settings.method == SSAO_METHOD_VISIBILITY);
    tap(c, GLFW_KEY_H);
    const ssao_timings t = all_pass_timings();
    for (const auto& [w, h] : std::vector<std::pair<int, int>>{{480, 360}, {480, 270}, {320, 240}, {800, 600}, {1920, 1080}}) {
        const std::vector<std::string> lines = viewer::overlay_lines(c.state(), t, w, h);
        const int scale = viewer::overlay_scale(w, h);
        for (const auto& l : lines) {
            INFO(w << "x" << h << " line '" << l << "'");
            CHECK(viewer::overlay_width(l, scale) <= w - 2 * scale);   // a margin on the right too
        }
        // Nothing lost: every pass, the total and the key help are still there.
        for (const char* part : {"GPU ms (frame 123456):", "clear 123.456", "grid 124.456", "vis 125.456", "blur x 126.456",
                                 "blur y 127.456", "up 128.456", "total 999.999", "estimator visibility", "Esc quit",
                                 "C start view"}) {
            INFO(w << "x" << h << ": " << std::string(part));
            CHECK(contains(lines, part));
        }
    }
    // Unfitted, the GPU line alone is wider than 480 px: the fitting is what makes it fit.
    const std::vector<std::string> wide = unwrapped(viewer::overlay_lines(c.state(), t, 480, 360));
    bool gpu_wider = false;
    for (const auto& l : wide)
        if (l.rfind("GPU ms", 0) == 0) gpu_wider = viewer::overlay_width(l, 1) > 480;
    CHECK(gpu_wider);
}

TEST_CASE("--help names every key the viewer answers and the shipped demo script") {
    const std::string help = viewer::help_text("scene.glb", "/data/viewer/demo.txt");
    const std::string keys = help.substr(help.find("keys:"));
    // Every key Controls::key acts on, by the name the help gives it.
    for (const char* key : {"W A S D", "Q Z", "I J K L", "E R T Y U", "1 2 3 4", "0 ", "B ", "V ", "O ", "M ", "H ", "X ",
                            "C ", "F12", "Esc"}) {
        INFO(std::string(key));
        CHECK(keys.find(std::string("  ") + key) != std::string::npos);
    }
    CHECK(keys.find("debug view") != std::string::npos);
    CHECK(keys.find("start view") != std::string::npos);
    CHECK(help.find("/data/viewer/demo.txt") != std::string::npos);
    // Every letter the controls answer is in the help (letters without a meaning are not).
    Fixture f;
    for (char letter = 'A'; letter <= 'Z'; ++letter) {
        viewer::Controls c = f.controls();
        const ssao_settings before = c.state().settings;
        const camera::Camera cam = c.camera();
        const int key = GLFW_KEY_A + (letter - 'A');
        c.key(key, GLFW_PRESS);
        c.advance(0.5f);
        c.key(key, GLFW_RELEASE);
        const bool acts = std::memcmp(&before, &c.state().settings, sizeof before) != 0 || c.camera().eye != cam.eye ||
                          c.camera().target != cam.target || c.state().mode != 0 || !c.state().overlay ||
                          c.state().view != viewer::View::Lit || !c.state().notice.empty();
        if (!acts) continue;
        INFO("key " << letter << " acts but the help does not name it");
        CHECK(keys.find(std::string(1, letter) + " ") != std::string::npos);
    }
}
