#include "camera_flags.h"

#include <cmath>

namespace flags {

void check_camera(const camera::Overrides& o) {
    if (o.ortho_half_height && o.fov_deg) fail("--ortho and --fov exclude each other");
    if (o.ortho_half_height && o.zfar && std::isinf(*o.zfar)) fail("--far inf needs a perspective camera (not --ortho)");
    if (o.znear && o.zfar && !(*o.zfar > *o.znear)) fail("--far must be greater than --near");
    if (o.eye && o.target && glm::all(glm::equal(*o.eye, *o.target))) fail("--eye and --target are the same point");
}

}  // namespace flags
