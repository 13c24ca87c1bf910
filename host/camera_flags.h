// camera_flags.h - the checks of the camera flags ssao-host and ssao-reference
// share (the flags themselves are parsed with flags.h).
#pragma once

#include "camera.h"
#include "flags.h"

namespace flags {

// The camera flags' combinations that make no camera. Throws Error.
void check_camera(const camera::Overrides& o);

// The largest projection element the plugin accepts (plugin/projection.cpp,
// kMaxElement): past it a 32-bit float shader overflows with ordinary view
// positions.
constexpr double kMaxProjectionElement = 1e30;

// --fov DEG: a vertical field of view in (0, 180) whose projection scale
// 1/tan(fov/2) stays within kMaxProjectionElement (a narrower one, 1e-30
// degrees say, the plugin refuses after the whole setup). Throws Error.
float fov_degrees(const std::string& flag, const std::string& text);

}  // namespace flags
