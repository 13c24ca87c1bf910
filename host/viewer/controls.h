// controls.h - what the viewer's keys do: the fly camera (WASD QZ, IJKL), the
// reference demo's modes (E R T Y U), presets (1..4, 0), blur (B), the view
// (V), back to the start view (C), the debug views (X: settings.debug_view, shown instead of the picture),
// the overlay (O), screenshots (F12) and quitting (Esc). No GL here, so
// it can be tested without a window.
#pragma once

#include "camera.h"
#include "cli.h"
#include "scene.h"

#include <ssao/ssao.h>

#include <glm/glm.hpp>

#include <optional>
#include <set>
#include <string>

namespace viewer {

enum class View { Lit, AoOnly };

// Everything the keys have chosen, read by the renderer and the overlay.
struct State {
    ssao_settings settings{};           // resolved; what the plugin runs with
    bool ssao = true;                   // false in mode E: lit without AO, no plugin pass
    char mode = 0;                      // the last mode key (E R T Y U), 0 = none yet
    std::optional<ssao_preset> preset;  // the last preset key (or --preset), none = the plugin's defaults
    View view = View::Lit;
    bool overlay = true;
    std::string notice;                 // one line for the overlay (e.g. a key this plugin cannot serve)
};

// Whether the frame shows the plugin's debug view (X) instead of the lit or AO picture.
inline bool debug_view_shown(const State& s) { return s.ssao && s.settings.debug_view != SSAO_DEBUG_VIEW_NONE; }

class Controls {
public:
    // `base` holds the scene path and the starting preset; the settings a
    // preset key gives are resolved like ssao-host's (run_setup::build_settings:
    // scene-scaled radius, scene hints). Throws run_setup::Error, and
    // camera::Error for a camera that cannot render (also from set_aspect,
    // which the window's resize calls: the viewer then ends with that line).
    Controls(const ssao_api& api, cli::Options base, const scene::Scene& scene, float aspect);

    // A key went down (GLFW_PRESS) or up (GLFW_RELEASE); repeats are ignored.
    void key(int glfw_key, int action);
    // Moves the camera by the held keys over `seconds`.
    void advance(float seconds);
    // The window's aspect changed: an unmoved camera is chosen again for it
    // (as a fresh start at that size would be).
    void set_aspect(float aspect);

    const State& state() const { return state_; }
    const camera::Camera& camera() const { return camera_; }
    // Taken (and cleared) once per frame.
    bool take_screenshot();
    bool quit() const { return quit_; }

private:
    void choose_preset(std::optional<ssao_preset> p);
    // C: the starting camera again (as chosen for the current aspect); the
    // next move flies from there.
    void reset_camera();
    void update_camera();

    const ssao_api& api_;
    cli::Options base_;
    const scene::Scene& scene_;
    State state_;
    std::set<int> held_;
    bool screenshot_ = false, quit_ = false;

    // The fly camera: the starting camera until the first move, then eye,
    // yaw and pitch with near/far refitted to the scene (camera::apply).
    camera::Camera start_, camera_;
    bool moved_ = false;
    glm::vec3 eye_{0.0f};
    float yaw_ = 0.0f, pitch_ = 0.0f, look_distance_ = 1.0f, speed_ = 1.0f;
};

}  // namespace viewer
