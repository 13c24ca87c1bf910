// camera_flags.h - the checks of the camera flags ssao-host and ssao-reference
// share (the flags themselves are parsed with flags.h).
#pragma once

#include "camera.h"
#include "flags.h"

namespace flags {

// The camera flags' combinations that make no camera. Throws Error.
void check_camera(const camera::Overrides& o);

}  // namespace flags
