// test_scenes.h - analytic scenes and settings shared by the GL tests.
#pragma once

#include "analytic_scene.h"

#include <ssao/ssao.h>

#include <glm/gtc/matrix_transform.hpp>

namespace testscenes {

inline const double kFov = 1.0471975512;  // 60 degrees

// Floor y = 0 (normal +y) meeting a wall z = -6 (normal +z): a 90-degree
// crease, seen from a camera 2 units above the floor pitched 25 degrees down.
// Quads are given in view space: `view` maps the world into it.
inline const glm::dmat4 kCreaseView = glm::rotate(glm::dmat4(1.0), 0.436, glm::dvec3(1, 0, 0)) *
                               glm::translate(glm::dmat4(1.0), glm::dvec3(0, -2, 0));

inline analytic::Scene crease_scene() {
    analytic::Scene s;
    auto add = [&](glm::dvec3 o, glm::dvec3 u, glm::dvec3 v) {
        s.add_quad(glm::dvec3(kCreaseView * glm::dvec4(o, 1.0)), glm::dvec3(kCreaseView * glm::dvec4(u, 0.0)),
                   glm::dvec3(kCreaseView * glm::dvec4(v, 0.0)));
    };
    add({-50, 0, 50}, {100, 0, 0}, {0, 0, -56});  // floor up to the wall
    add({-50, 0, -6}, {100, 0, 0}, {0, 50, 0});   // the wall
    return s;
}

inline ssao_settings make(uint32_t samples, ssao_blur blur, ssao_rotation rotation = SSAO_ROTATION_DEFAULT) {
    ssao_settings s{};
    s.size = sizeof s;
    // The kernel estimator with the accelerating distribution, as these cases
    // were written for (a zeroed struct is the DEFAULT preset, which may not be).
    s.method = SSAO_METHOD_KERNEL;
    s.distribution = SSAO_DISTRIBUTION_ACCELERATING;
    s.resolution = SSAO_RESOLUTION_FULL;  // full resolution: the CPU formula is per pixel
    s.sample_count = samples;
    // DEFAULT meant the depth-aware blur when these cases were written (the
    // kernel method's own default is now the chapter's box).
    s.blur = blur == SSAO_BLUR_DEFAULT ? SSAO_BLUR_DEPTH_AWARE : blur;
    s.rotation = rotation;
    return s;
}

}  // namespace testscenes
