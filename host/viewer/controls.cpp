#include "controls.h"

#include "debug_view_text.h"
#include "modes.h"
#include "run_setup.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cmath>

namespace viewer {

namespace {

constexpr float kTurnDegreesPerSecond = 60.0f;
constexpr float kSpeedPerDiagonal = 0.15f;   // move a seventh of the scene a second
constexpr float kMaxPitch = glm::radians(89.0f);

// The blur kinds B steps through, in this order.
constexpr ssao_blur kBlurCycle[] = {SSAO_BLUR_DEPTH_AWARE, SSAO_BLUR_BOX_4X4, SSAO_BLUR_GAUSSIAN, SSAO_BLUR_NONE};

glm::vec3 direction(float yaw, float pitch) {
    return glm::vec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch), -std::cos(pitch) * std::cos(yaw));
}

}  // namespace

Controls::Controls(const ssao_api& api, cli::Options base, const scene::Scene& scene, float aspect)
    : api_(api), base_(std::move(base)), scene_(scene) {
    choose_preset(base_.preset);
    camera::Source from_scene = camera::Source::Framed;
    start_ = camera_ = run_setup::build_camera(base_, scene_, aspect, from_scene);
    const float diagonal = glm::length(scene_.bounds_max - scene_.bounds_min);
    speed_ = kSpeedPerDiagonal * (diagonal > 0.0f && std::isfinite(diagonal) ? diagonal : 1.0f);
}

void Controls::choose_preset(std::optional<ssao_preset> p) {
    cli::Options o = base_;
    o.preset = p;
    std::string radius_note;
    const ssao_debug_view debug_view = state_.settings.debug_view;  // X's choice outlives a preset key
    state_.settings = run_setup::build_settings(api_, o, scene_, radius_note);
    state_.settings.debug_view = debug_view;
    state_.preset = p;
    state_.ssao = true;
    state_.mode = 0;
}

void Controls::key(int k, int action) {
    if (k >= GLFW_KEY_KP_0 && k <= GLFW_KEY_KP_9) k = GLFW_KEY_0 + (k - GLFW_KEY_KP_0);   // the keypad's digits too
    if (action == GLFW_RELEASE) {
        held_.erase(k);
        return;
    }
    if (action != GLFW_PRESS) return;
    held_.insert(k);
    state_.notice.clear();
    if (k >= GLFW_KEY_A && k <= GLFW_KEY_Z) {
        if (const modes::Mode* m = modes::find(static_cast<char>('A' + (k - GLFW_KEY_A)))) {
            state_.mode = m->letter;
            state_.ssao = m->ssao;
            if (m->ssao) modes::apply(*m, state_.settings);
            return;
        }
    }
    switch (k) {
        case GLFW_KEY_0: choose_preset(std::nullopt); break;
        case GLFW_KEY_1: choose_preset(SSAO_PRESET_LOW); break;
        case GLFW_KEY_2: choose_preset(SSAO_PRESET_MEDIUM); break;
        case GLFW_KEY_3: choose_preset(SSAO_PRESET_HIGH); break;
        case GLFW_KEY_4: choose_preset(SSAO_PRESET_ULTRA); break;
        case GLFW_KEY_B: {
            const ssao_blur* end = std::end(kBlurCycle);
            const ssao_blur* at = std::find(std::begin(kBlurCycle), end, state_.settings.blur);
            state_.settings.blur = (at == end || at + 1 == end) ? kBlurCycle[0] : at[1];
            break;
        }
        case GLFW_KEY_X:
            // The debug views in debug_view_text's order: none -> normals ->
            // reconstructed normals -> raw AO -> blur weights -> none.
            state_.settings.debug_view = debug_view_text::next(state_.settings.debug_view);
            break;
        case GLFW_KEY_C: reset_camera(); break;
        case GLFW_KEY_V: state_.view = state_.view == View::Lit ? View::AoOnly : View::Lit; break;
        case GLFW_KEY_O: state_.overlay = !state_.overlay; break;
        case GLFW_KEY_F12: screenshot_ = true; break;
        case GLFW_KEY_ESCAPE: quit_ = true; break;
        case GLFW_KEY_M:
            // The estimator: the chapter's point kernel or ray-marched visibility
            // (resolved settings already hold the visibility's thickness and steps).
            state_.settings.method =
                state_.settings.method == SSAO_METHOD_VISIBILITY ? SSAO_METHOD_KERNEL : SSAO_METHOD_VISIBILITY;
            break;
        case GLFW_KEY_H:
            // The grid the sampling pass runs on: full -> half -> quarter -> full.
            state_.settings.resolution = state_.settings.resolution == SSAO_RESOLUTION_HALF      ? SSAO_RESOLUTION_QUARTER
                                         : state_.settings.resolution == SSAO_RESOLUTION_QUARTER ? SSAO_RESOLUTION_FULL
                                                                                                 : SSAO_RESOLUTION_HALF;
            break;
        default: break;
    }
}

void Controls::advance(float seconds) {
    auto held = [&](int k) { return held_.count(k) != 0; };
    const float turn = glm::radians(kTurnDegreesPerSecond) * seconds;
    const float step = speed_ * seconds;
    const float yaw_delta = (held(GLFW_KEY_L) ? turn : 0.0f) - (held(GLFW_KEY_J) ? turn : 0.0f);
    const float pitch_delta = (held(GLFW_KEY_I) ? turn : 0.0f) - (held(GLFW_KEY_K) ? turn : 0.0f);
    const float forward = (held(GLFW_KEY_W) ? step : 0.0f) - (held(GLFW_KEY_S) ? step : 0.0f);
    const float right = (held(GLFW_KEY_D) ? step : 0.0f) - (held(GLFW_KEY_A) ? step : 0.0f);
    const float up = (held(GLFW_KEY_Q) ? step : 0.0f) - (held(GLFW_KEY_Z) ? step : 0.0f);
    if (yaw_delta == 0.0f && pitch_delta == 0.0f && forward == 0.0f && right == 0.0f && up == 0.0f) return;
    if (!moved_) {
        // The first move: fly from the starting camera.
        eye_ = start_.eye;
        const glm::vec3 f = start_.target - start_.eye;
        look_distance_ = glm::length(f);
        const glm::vec3 d = f / look_distance_;
        yaw_ = std::atan2(d.x, -d.z);
        pitch_ = std::asin(std::clamp(d.y, -1.0f, 1.0f));
        moved_ = true;
    }
    yaw_ += yaw_delta;
    pitch_ = std::clamp(pitch_ + pitch_delta, -kMaxPitch, kMaxPitch);
    const glm::vec3 f = direction(yaw_, pitch_);
    const glm::vec3 world_up(0.0f, 1.0f, 0.0f);
    const glm::vec3 r = glm::normalize(glm::cross(f, world_up));
    eye_ += f * forward + r * right + world_up * up;
    update_camera();
}

void Controls::update_camera() {
    camera::Overrides o;
    o.eye = eye_;
    o.target = eye_ + direction(yaw_, pitch_) * look_distance_;
    camera::Camera start = start_;
    start.up = glm::vec3(0.0f, 1.0f, 0.0f);
    camera_ = camera::apply(scene_, start, o);
}

void Controls::reset_camera() {
    moved_ = false;
    camera_ = start_;
}

void Controls::set_aspect(float aspect) {
    if (moved_) return;
    camera::Source from_scene = camera::Source::Framed;
    start_ = camera_ = run_setup::build_camera(base_, scene_, aspect, from_scene);
}

bool Controls::take_screenshot() {
    const bool s = screenshot_;
    screenshot_ = false;
    return s;
}

}  // namespace viewer
