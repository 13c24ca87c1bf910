// run_setup.h - what a run of ssao-host or ssao-viewer starts from: the bundled
// scene, the SSAO settings the flags and the scene call for, and the camera.
// One definition for both programs, so the viewer's first frame is the host's
// picture.
#pragma once

#include "camera.h"
#include "cli.h"
#include "scene.h"

#include <ssao/ssao.h>

#include <glm/glm.hpp>

#include <stdexcept>
#include <string>

namespace run_setup {

// Thrown with one sentence naming the problem.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The scene used when none is given (assets/models/spot-on-ground.glb).
std::string default_scene_path();

// The resolved settings. Precedence: flags > scene hints > preset > plugin
// defaults; the radius is scene-scaled (scene::ao_radius). `radius_note` says
// where the radius came from. Throws Error.
ssao_settings build_settings(const ssao_api& api, const cli::Options& o, const scene::Scene& sc, std::string& radius_note);

// The bundled scene's three-quarter view of the cow (its bounds are dominated
// by the 8 x 8 ground, so framing them shows a small cow).
extern const glm::vec3 kBundledEye, kBundledTarget;

// The scene's camera or one framed from its bounds (the bundled view for the
// bundled scene without camera flags), with the flags' overrides; validated.
// `from_scene` tells whether the glTF had a camera. Throws Error.
camera::Camera build_camera(const cli::Options& o, const scene::Scene& sc, float aspect, bool& from_scene);

}  // namespace run_setup
