#include "views.h"

#include "raytracer.h"

#include <cmath>

namespace bench {

const std::vector<std::string>& scene_files() {
    static const std::vector<std::string> files = {"models/spot-on-ground.glb", "models/teapot-on-ground.glb",
                                                   "scenes/corner.gltf",        "scenes/overhang.gltf",
                                                   "scenes/creases.gltf",       "scenes/clutter.gltf"};
    return files;
}

const char* view_name(View v) {
    switch (v) {
        case View::standard: return "standard";
        case View::high: return "high";
        case View::close: return "close-up";
    }
    return "?";
}

std::vector<View> all_views() { return {View::standard, View::high, View::close}; }

const std::vector<float>& radius_scales() {
    static const std::vector<float> scales = {0.5f, 1.0f, 2.0f};
    return scales;
}

namespace {

// Where the standard view's centre ray first meets the scene, and how far.
glm::vec3 focus_of(const camera::Camera& c, const raytrace::Tracer& tracer, float& distance) {
    glm::vec3 f = c.target - c.eye;
    distance = glm::length(f);
    if (!(distance > 0.0f)) {
        distance = 1.0f;
        return c.eye + glm::vec3(0.0f, 0.0f, -1.0f);
    }
    f /= distance;
    float t = 0.0f;
    glm::vec3 n;
    const float far = std::isfinite(c.zfar) ? c.zfar : 1e30f;
    if (tracer.ok() && tracer.intersect(c.eye, f, 0.0f, far, t, n) && t > 0.0f) {
        distance = t;
        return c.eye + f * t;
    }
    return c.target;
}

}  // namespace

camera::Camera view_camera(const scene::Scene& s, float aspect, View v, const raytrace::Tracer& tracer) {
    const camera::Camera standard = camera::choose(s, aspect);
    if (v == View::standard) return standard;
    float distance = 0.0f;
    const glm::vec3 focus = focus_of(standard, tracer, distance);
    camera::Camera c = standard;
    camera::Overrides o;
    o.target = focus;
    if (v == View::close) {
        o.eye = focus + (standard.eye - focus) * kCloseFraction;
        if (c.orthographic) c.ortho_half_height *= kCloseFraction;
    } else {
        // The standard view's bearing around the vertical, raised to look down steeply.
        glm::vec3 across = standard.eye - focus;
        across.y = 0.0f;
        across = glm::length(across) > 1e-6f ? glm::normalize(across) : glm::vec3(0.0f, 0.0f, 1.0f);
        const float e = glm::radians(kHighElevationDeg);
        o.eye = focus + distance * kHighFraction * (std::cos(e) * across + std::sin(e) * glm::vec3(0.0f, 1.0f, 0.0f));
        c.up = glm::vec3(0.0f, 1.0f, 0.0f);
    }
    // Near and far refitted to the bounds along the new view (the standard's
    // were the scene's own, fitted to where it stood).
    return camera::apply(s, c, o);
}

float radius_pixels(const camera::Camera& c, float radius, float depth, int height) {
    const float half = c.orthographic ? c.ortho_half_height : depth * std::tan(0.5f * c.yfov);
    return half > 0.0f ? radius / half * 0.5f * static_cast<float>(height) : 0.0f;
}

}  // namespace bench
