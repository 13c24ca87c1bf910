// camera.h - the camera both the host and the reference render with.
#pragma once

#include "scene.h"

#include <glm/glm.hpp>

namespace camera {

struct Camera {
    glm::vec3 eye{0.0f, 1.0f, 4.0f};
    glm::vec3 target{0.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float yfov = 0.7854f;           // radians, perspective
    float ortho_half_height = 1.0f; // view units, orthographic
    float znear = 0.1f;
    float zfar = 100.0f;            // may be +infinity (perspective only)
    bool orthographic = false;
    bool reverse_z = false;         // depth 1 at near, 0 at far; implies a [0,1] clip range
    bool zero_to_one = false;       // glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)
};

// The scene's own camera if it has one, otherwise one framed from the bounds
// (looking at the centre from above and in front, near/far fitted to them).
Camera choose(const scene::Scene& s, float aspect);

glm::mat4 view_matrix(const Camera& c);
// Column-major GL projection honouring orthographic, reverse_z, zero_to_one and
// an infinite zfar.
glm::mat4 projection_matrix(const Camera& c, float aspect);

}  // namespace camera
