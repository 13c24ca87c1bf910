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

// The resolved settings. Precedence: flags > scene hints > preset > plugin
// defaults; the radius is scene-scaled (scene::ao_radius). `radius_note` says
// where the radius came from. Throws Error.
ssao_settings build_settings(const ssao_api& api, const cli::Options& o, const scene::Scene& sc, std::string& radius_note);

// camera::initial for these options (the bundled view when no scene was
// given). `source` receives where it came from. Throws camera::Error.
camera::Camera build_camera(const cli::Options& o, const scene::Scene& sc, float aspect, camera::Source& source);

}  // namespace run_setup
