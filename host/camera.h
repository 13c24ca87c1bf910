// camera.h - the camera both the host and the reference render with.
#pragma once

#include "scene.h"

#include <glm/glm.hpp>

#include <optional>
#include <stdexcept>

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

// Command-line overrides (--eye, --target, --fov, --near, --far, --ortho,
// --reverse-z), applied the same way by ssao-host and ssao-reference.
struct Overrides {
    std::optional<glm::vec3> eye, target;
    std::optional<float> fov_deg;            // perspective vertical fov, degrees
    std::optional<float> znear, zfar;        // zfar may be +infinity (perspective)
    std::optional<float> ortho_half_height;  // switches to orthographic
    bool reverse_z = false;                  // sets reverse_z and zero_to_one
};

// A camera that cannot render: a near or far plane the command line gave
// that the other plane, given or fitted, contradicts (the message names the
// flag), or one initial() refuses.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// `c` with the overrides applied. When the eye or the target moved and near/far
// were not given, near and far are refitted to the scene's bounds (as choose does).
// Throws Error where a given --near or --far does not leave far beyond near.
Camera apply(const scene::Scene& s, Camera c, const Overrides& o);

// Where the starting camera came from.
enum class Source { Scene, Framed, Bundled };

// The bundled scene's three-quarter view of the cow (its bounds are dominated
// by the 8 x 8 ground, so framing them shows a small cow).
extern const glm::vec3 kBundledEye, kBundledTarget;

// The camera every tool starts from (ssao-host, ssao-reference, ssao-viewer):
// the scene's camera, else one framed from its bounds; but for the bundled
// scene (`bundled_scene`: no scene argument given) without --eye, --target or
// --ortho, the bundled view kBundledEye -> kBundledTarget. Then the overrides.
// `source` (optional) receives which of the three it was. Throws Error for a
// camera that cannot render: eye = target, far not beyond near, a perspective
// near <= 0, an orthographic infinite far, a non-finite view or projection.
Camera initial(const scene::Scene& s, float aspect, const Overrides& o, bool bundled_scene, Source* source = nullptr);

// "the scene's camera", "framed from the bounds" or "the bundled view of the cow".
const char* describe(Source s);

glm::mat4 view_matrix(const Camera& c);
// Column-major GL projection honouring orthographic, reverse_z, zero_to_one and
// an infinite zfar.
glm::mat4 projection_matrix(const Camera& c, float aspect);

}  // namespace camera
