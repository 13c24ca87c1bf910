// ssao-viewer: the SSAO plugin on a glTF scene in a window, driven by the
// reference demo's keys. The same scene loader, G-buffer, lighting and plugin
// (through dlopen and the C ABI) as ssao-host; see docs/tools.md, "ssao-viewer".
#include "controls.h"
#include "image_io.h"
#include "locate.h"
#include "flags.h"
#include "options.h"
#include "overlay.h"
#include "plugin_loader.h"
#include "renderer.h"
#include "run_setup.h"
#include "scene.h"
#include "script.h"
#include "window.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

constexpr float kScriptSecondsPerFrame = 1.0f / 30.0f;   // scripted runs move by fixed steps

// Resident memory of this process in KiB (VmRSS), 0 if unknown.
long resident_kib() {
    std::FILE* f = std::fopen("/proc/self/status", "r");
    if (!f) return 0;
    char line[256];
    long kib = 0;
    while (std::fgets(line, sizeof line, f))
        if (std::sscanf(line, "VmRSS: %ld kB", &kib) == 1) break;
    std::fclose(f);
    return kib;
}

void write_screenshot(viewer::Window& window, const std::string& dir, long frame, int width, int height) {
    char name[64];
    std::snprintf(name, sizeof name, "frame-%05ld.png", frame);
    image_io::StagedOutput out(dir);
    out.png(name, width, height, 3, window.read_pixels(width, height));
    out.commit();
    std::printf("screenshot: %s\n", (fs::absolute(dir) / name).lexically_normal().c_str());
    std::fflush(stdout);
}

scene::Scene load_scene(const viewer::Options& o, const std::string& path) {
    scene::Scene sc;
    scene::Limits limits;
    limits.allow_outside_files = o.allow_outside_files;
    std::string error;
    if (!scene::load(path, sc, error, limits)) throw std::runtime_error("cannot load the scene: " + error);
    if (sc.mesh.triangle_count() == 0) throw std::runtime_error("'" + path + "' has nothing to draw (no triangles)");
    return sc;
}

// Plays the script's events due at `frame`, each said as it happens so a
// scripted run leaves a log to check. False when one quits.
bool play_script(const std::vector<viewer::ScriptEvent>& script, size_t& next, long frame, viewer::Controls& controls,
                 viewer::Window& window, int width, int height) {
    for (; next < script.size() && script[next].frame <= frame; ++next) {
        const viewer::ScriptEvent& e = script[next];
        switch (e.kind) {
            case viewer::ScriptEvent::Kind::Press:
                std::printf("frame %ld: press %s\n", frame, viewer::key_name(e.key).c_str());
                controls.key(e.key, GLFW_PRESS);
                break;
            case viewer::ScriptEvent::Kind::Release:
                std::printf("frame %ld: release %s\n", frame, viewer::key_name(e.key).c_str());
                controls.key(e.key, GLFW_RELEASE);
                break;
            case viewer::ScriptEvent::Kind::Resize:
                std::printf("frame %ld: resize %d %d\n", frame, e.width, e.height);
                window.request_size(e.width, e.height);
                window.poll();
                break;
            case viewer::ScriptEvent::Kind::Memory:
                std::printf("frame %ld: %dx%d, resident %ld KiB\n", frame, width, height, resident_kib());
                std::fflush(stdout);
                break;
            case viewer::ScriptEvent::Kind::Quit:
                std::printf("frame %ld: quit\n", frame);
                std::fflush(stdout);
                return false;
        }
    }
    std::fflush(stdout);
    return true;
}

// Follows the window's framebuffer size into the renderer and the camera.
// False while it is minimised: nothing to draw until it comes back.
bool follow_size(viewer::Window& window, viewer::Renderer& renderer, viewer::Controls& controls, int& width,
                 int& height) {
    int w = 0, h = 0;
    window.framebuffer_size(w, h);
    if (w <= 0 || h <= 0) return false;
    if (w != width || h != height) {
        width = w;
        height = h;
        renderer.resize(width, height);
        controls.set_aspect(float(width) / float(height));
    }
    return true;
}

int run(const viewer::Options& o) {
    std::vector<viewer::ScriptEvent> script;
    std::string error;
    if (!o.script_path.empty() && !viewer::load_script(o.script_path, script, error)) throw std::runtime_error(error);

    const std::string scene_path = o.scene_path.empty() ? scene::default_path() : o.scene_path;
    plugin::Library library;
    if (!library.open_default(o.plugin_path, error)) throw std::runtime_error(error);
    const ssao_api& api = library.api();
    const scene::Scene sc = load_scene(o, scene_path);

    cli::Options base;
    base.scene_path = o.scene_path;
    base.preset = o.preset;
    viewer::Controls controls(api, base, sc, float(o.width) / float(o.height));

    auto window = viewer::Window::open(o.width, o.height, "ssao-viewer", error);
    if (!window) throw std::runtime_error(error);
    window->on_key([&](int key, int action) { controls.key(key, action); });
    GladGLContext& gl = window->gl();
    std::printf("ssao-viewer: %s on %s\n", fs::absolute(scene_path).lexically_normal().c_str(), window->renderer().c_str());
    std::fflush(stdout);

    int width = 0, height = 0;
    window->framebuffer_size(width, height);
    viewer::Renderer renderer(gl, api, viewer::Window::get_proc, sc, controls.state().settings, width, height);
    viewer::Overlay overlay(gl);
    controls.set_aspect(float(width) / float(height));

    size_t next_event = 0;
    auto last = std::chrono::steady_clock::now();
    for (long frame = 0; o.frames == 0 || frame < o.frames; ++frame) {
        window->poll();
        if (!play_script(script, next_event, frame, controls, *window, width, height)) return 0;
        if (window->should_close() || controls.quit()) break;

        const auto now = std::chrono::steady_clock::now();
        const float seconds = o.script_path.empty() ? std::min(std::chrono::duration<float>(now - last).count(), 0.1f)
                                                    : kScriptSecondsPerFrame;
        last = now;
        controls.advance(seconds);
        if (!follow_size(*window, renderer, controls, width, height)) {
            window->wait(0.1);
            continue;
        }

        renderer.render(controls.camera(), controls.state());
        if (controls.state().overlay)
            overlay.draw(viewer::overlay_lines(controls.state(), renderer.timings(), width, height), width, height,
                         viewer::overlay_scale(width, height));
        if (controls.take_screenshot()) {
            // A person at the window keeps the session; a script's run fails on it.
            try {
                write_screenshot(*window, o.screenshot_dir, frame, width, height);
            } catch (const std::exception& e) {
                if (!o.script_path.empty()) throw;
                std::fprintf(stderr, "ssao-viewer: screenshot not written: %s\n", e.what());
            }
        }
        window->swap();
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    viewer::Options options;
    std::string error;
    const viewer::Parse parsed = viewer::parse(argc, argv, options, error);
    return flags::finish_main(
        "ssao-viewer", parsed, error,
        [] { return viewer::help_text(scene::default_path(), locate::bundled(viewer::kDemoScript)); },
        [&] { return run(options); });
}
