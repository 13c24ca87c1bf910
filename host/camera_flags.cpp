#include "camera_flags.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace flags {

void check_camera(const camera::Overrides& o) {
    if (o.ortho_half_height && o.fov_deg) fail("--ortho and --fov exclude each other");
    if (o.ortho_half_height && o.zfar && std::isinf(*o.zfar)) fail("--far inf needs a perspective camera (not --ortho)");
    if (o.znear && o.zfar && !(*o.zfar > *o.znear)) fail("--far must be greater than --near");
    if (o.eye && o.target && glm::all(glm::equal(*o.eye, *o.target))) fail("--eye and --target are the same point");
}

}  // namespace flags

namespace flags {

float fov_degrees(const std::string& flag, const std::string& text) {
    const double deg = number(flag, text);
    if (!(deg > 0.0 && deg < 180.0)) fail(flag + " " + text + " is out of range (0, 180)");
    check_normal_float(flag, text, deg);
    const double scale = 1.0 / std::tan(deg * 3.14159265358979323846 / 360.0);
    if (!(scale <= kMaxProjectionElement)) {
        std::ostringstream s;
        s << kMaxProjectionElement;
        fail(flag + " " + text + " is too narrow: its projection scale 1/tan(fov/2) exceeds " + s.str() +
             ", more than 32-bit float shaders can use");
    }
    return static_cast<float>(deg);
}

float far_plane(const std::string& flag, const std::string& text) {
    const double d = number(flag, text, true);
    if (!(d > 0.0)) fail(flag + " " + text + " must be > 0 (or 'inf')");
    if (std::isfinite(d) && d > static_cast<double>(std::numeric_limits<float>::max()))
        fail(flag + " " + text + " is beyond 32-bit float range (3.4e38); 'inf' gives an infinite far plane");
    return static_cast<float>(d);
}

}  // namespace flags
