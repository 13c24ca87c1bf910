// camera_flags.h - the checks of the camera flags ssao-host and ssao-reference
// share (the flags themselves are parsed with flags.h).
#pragma once

#include "camera.h"
#include "flags.h"

namespace flags {

// The camera flags' combinations that make no camera. Throws Error.
void check_camera(const camera::Overrides& o);

// The plugin scales a projection so that its largest element lies in [1, 2)
// and refuses one whose inverse then has an element past this
// (plugin/projection.cpp, kMaxElement): a 32-bit float shader would overflow.
constexpr double kMaxProjectionElement = 1e30;

// --fov DEG: a vertical field of view in (0, 180) whose projection scale
// 1/tan(fov/2) stays within kMaxProjectionElement (a narrower one, 1e-30
// degrees say, the plugin refuses after the whole setup). Throws Error.
float fov_degrees(const std::string& flag, const std::string& text);

// --far F: a number > 0 within 32-bit float range, or 'inf' (an infinite far
// plane). A larger finite one would become inf unasked. Throws Error.
float far_plane(const std::string& flag, const std::string& text);

}  // namespace flags
