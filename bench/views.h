// views.h - the scenes the benchmark measures by default, and the cameras and
// radii it measures every scene at.
// Screen-space AO fails differently by view: the standard view (the scene's
// camera, or one framed from its bounds, as every tool starts from), a high
// view looking down steeply (floors and tops face the camera, walls and
// contact shadows are foreshortened), and a close-up whose radius covers many
// pixels (where too few march steps show). Each at 0.5x, 1x and 2x the
// scene's AO radius.
#pragma once

#include "camera.h"
#include "scene.h"

#include <string>
#include <vector>

namespace raytrace { class Tracer; }

namespace bench {

// The benchmark's default scenes, as paths under assets/ (ssao-bench's
// default list, and the tests that cover every bench scene).
const std::vector<std::string>& scene_files();

enum class View { standard, high, close };

const char* view_name(View v);  // "standard", "high", "close-up"
std::vector<View> all_views();

// The radius multiples every scene and view is measured at (they span 4x).
const std::vector<float>& radius_scales();

// How steeply the high view looks down (degrees below the horizon) and from how
// far, and how near the close-up comes: distances to the point the standard
// view looks at, as fractions of the standard view's.
constexpr float kHighElevationDeg = 65.0f;
constexpr float kHighFraction = 0.7f;
constexpr float kCloseFraction = 0.25f;

// The camera of view `v` for scene `s` at aspect `aspect`. The close-up and
// the high view look at the point the standard view's centre ray hits (found
// with `tracer`; the standard camera's target where it hits nothing), keep its
// field of view, and have near and far refitted to the scene as camera::apply
// does.
camera::Camera view_camera(const scene::Scene& s, float aspect, View v, const raytrace::Tracer& tracer);

// The AO radius in pixels at view depth `depth` for a perspective camera
// rendering `height` pixel rows (the radius's half-height in the image).
float radius_pixels(const camera::Camera& c, float radius, float depth, int height);

}  // namespace bench
