// camera.cpp - camera choice and GL matrices shared by ssao-host and ssao-reference.
#include "camera.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace camera {
namespace {

bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string num(float v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

// Looks at the bounds' centre from above and in front, at the distance where all
// eight corners of the bounding box fit the field of view with a 5% margin.
Camera framed(const scene::Scene& s, float aspect) {
    Camera c;
    const glm::vec3 centre = 0.5f * (s.bounds_min + s.bounds_max);
    float radius = 0.5f * glm::length(s.bounds_max - s.bounds_min);
    if (!(radius > 0.0f) || !std::isfinite(radius)) radius = 1.0f;
    const float tan_v = std::tan(0.5f * c.yfov);
    const float tan_h = tan_v * std::max(aspect, 1e-3f);
    const glm::vec3 dir = glm::normalize(glm::vec3(0.0f, 0.55f, 1.0f));  // from the centre towards the eye
    const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), dir));
    const glm::vec3 up = glm::cross(dir, right);
    const float margin = 1.05f;
    float dist = 0.0f, half_height = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? s.bounds_max.x : s.bounds_min.x, (i & 2) ? s.bounds_max.y : s.bounds_min.y,
                               (i & 4) ? s.bounds_max.z : s.bounds_min.z);
        const glm::vec3 o = corner - centre;
        const float x = std::fabs(glm::dot(o, right)) * margin, y = std::fabs(glm::dot(o, up)) * margin;
        const float z = glm::dot(o, dir);
        dist = std::max({dist, z + x / tan_h, z + y / tan_v});
        half_height = std::max({half_height, y, x / std::max(aspect, 1e-3f)});
    }
    dist = std::max(dist, radius * 1e-3f);
    if (!std::isfinite(dist)) dist = radius * 3.0f;
    c.target = centre;
    c.eye = centre + dir * dist;
    c.znear = std::max(dist - radius * 1.5f, dist * 0.01f);
    c.zfar = dist + radius * 2.0f;
    c.ortho_half_height = half_height > 0.0f ? half_height : radius;
    return c;
}

}  // namespace

Camera choose(const scene::Scene& s, float aspect) {
    if (!(aspect > 0.0f) || !std::isfinite(aspect)) aspect = 1.0f;
    Camera auto_cam = framed(s, aspect);
    if (!s.camera) return auto_cam;

    const scene::GltfCamera& g = *s.camera;
    Camera c = auto_cam;
    const glm::mat4& m = g.world_from_camera;
    const glm::vec3 eye(m[3]);
    glm::vec3 fwd = -glm::vec3(m[2]);
    glm::vec3 up = glm::vec3(m[1]);
    if (!finite3(eye) || !finite3(fwd) || !finite3(up) || glm::length(fwd) < 1e-12f || glm::length(up) < 1e-12f)
        return auto_cam;
    fwd = glm::normalize(fwd);
    up = glm::normalize(up);
    // Target at the distance of the bounds centre along the view direction (any
    // point on the axis gives the same view matrix).
    const float along = std::max(glm::dot(0.5f * (s.bounds_min + s.bounds_max) - eye, fwd), 1.0f);
    c.eye = eye;
    c.target = eye + fwd * along;
    c.up = up;
    c.orthographic = g.orthographic;
    if (g.orthographic) {
        if (g.ymag > 0.0f && std::isfinite(g.ymag)) c.ortho_half_height = g.ymag;
        if (g.znear >= 0.0f && std::isfinite(g.znear)) c.znear = g.znear;
        if (g.zfar > c.znear && std::isfinite(g.zfar)) c.zfar = g.zfar;
        else c.zfar = c.znear + 2.0f * (auto_cam.zfar);
    } else {
        if (g.yfov > 0.0f && g.yfov < 3.1f) c.yfov = g.yfov;
        if (g.znear > 0.0f && std::isfinite(g.znear)) c.znear = g.znear;
        if (g.zfar == 0.0f || std::isinf(g.zfar)) c.zfar = std::numeric_limits<float>::infinity();
        else if (g.zfar > c.znear && std::isfinite(g.zfar)) c.zfar = g.zfar;
        else c.zfar = std::numeric_limits<float>::infinity();
    }
    return c;
}

Camera apply(const scene::Scene& s, Camera c, const Overrides& o) {
    if (o.eye) c.eye = *o.eye;
    if (o.target) c.target = *o.target;
    if (o.fov_deg && *o.fov_deg > 0.0f && *o.fov_deg < 180.0f) {
        c.yfov = glm::radians(*o.fov_deg);
        c.orthographic = false;
    }
    if (o.ortho_half_height && *o.ortho_half_height > 0.0f) {
        c.ortho_half_height = *o.ortho_half_height;
        c.orthographic = true;
    }
    if ((o.eye || o.target) && !(o.znear && o.zfar)) {
        // Refit to the bounding sphere as seen along the new view direction.
        const glm::vec3 centre = 0.5f * (s.bounds_min + s.bounds_max);
        float radius = 0.5f * glm::length(s.bounds_max - s.bounds_min);
        if (!(radius > 0.0f) || !std::isfinite(radius)) radius = 1.0f;
        glm::vec3 f = c.target - c.eye;
        f = glm::length(f) > 0.0f ? glm::normalize(f) : glm::vec3(0.0f, 0.0f, -1.0f);
        const float d = glm::dot(centre - c.eye, f);
        const float far_fit = std::max(d + radius * 1.5f, radius * 0.01f);
        const float near_fit = std::max(d - radius * 1.5f, far_fit * 0.001f);
        if (!o.znear) c.znear = c.orthographic ? std::max(d - radius * 1.5f, 0.0f) : near_fit;
        if (!o.zfar) c.zfar = far_fit;
        if (c.orthographic && !o.znear && c.znear <= 0.0f) c.znear = 0.0f;
    }
    if (o.znear) c.znear = *o.znear;
    if (o.zfar) c.zfar = *o.zfar;
    if (c.orthographic && std::isinf(c.zfar)) c.zfar = c.znear + 1e4f;
    if (!(c.zfar > c.znear)) {
        // A given plane is never replaced behind the user's back.
        if (o.znear && o.zfar) throw Error("--far " + num(*o.zfar) + " must be beyond --near " + num(*o.znear));
        if (o.zfar)
            throw Error("--far " + num(*o.zfar) + " is not beyond the near plane fitted to the scene (" +
                        num(c.znear) + "); give --near too");
        if (o.znear)
            throw Error("--near " + num(*o.znear) + " is not in front of the far plane fitted to the scene (" +
                        num(c.zfar) + "); give --far too");
        c.zfar = c.znear * 2.0f + 1.0f;
    }
    if (o.reverse_z) {
        c.reverse_z = true;
        c.zero_to_one = true;
    }
    return c;
}

const glm::vec3 kBundledEye(2.3f, 1.6f, -2.6f), kBundledTarget(0.0f, 0.65f, 0.0f);

namespace {

// Throws Error where the camera cannot render: one the tools would otherwise
// run with, getting NaN positions or an all-sky image.
void check_usable(const Camera& c, float aspect) {
    if (!(glm::length(c.target - c.eye) > 0.0f)) throw Error("the camera's eye and target are the same point");
    if (c.orthographic && std::isinf(c.zfar)) throw Error("an orthographic camera needs a finite far plane");
    if (!c.orthographic && !(c.znear > 0.0f)) throw Error("the near plane " + num(c.znear) + " must be > 0");
    if (!(c.zfar > c.znear))
        throw Error("the far plane " + num(c.zfar) + " must lie beyond the near plane " + num(c.znear));
    const glm::mat4 view = view_matrix(c), projection = projection_matrix(c, aspect);
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row)
            if (!std::isfinite(view[col][row]) || !std::isfinite(projection[col][row]))
                throw Error("the camera gives a non-finite view or projection matrix; check --eye, --target, --fov, "
                            "--ortho, --near, --far and the scene's camera");
}

}  // namespace

Camera initial(const scene::Scene& s, float aspect, const Overrides& o, bool bundled_scene, Source* source) {
    Overrides ov = o;
    Source from = s.camera ? Source::Scene : Source::Framed;
    if (bundled_scene && !ov.eye && !ov.target && !ov.ortho_half_height) {
        ov.eye = kBundledEye;
        ov.target = kBundledTarget;
        from = Source::Bundled;
    }
    if (source) *source = from;
    const Camera c = apply(s, choose(s, aspect), ov);
    check_usable(c, aspect);
    return c;
}

const char* describe(Source s) {
    switch (s) {
        case Source::Scene: return "the scene's camera";
        case Source::Framed: return "framed from the bounds";
        case Source::Bundled: return "the bundled view of the cow";
    }
    return "?";
}

glm::mat4 view_matrix(const Camera& c) {
    glm::vec3 f = c.target - c.eye;
    if (!(glm::length(f) > 0.0f)) f = glm::vec3(0.0f, 0.0f, -1.0f);
    f = glm::normalize(f);
    glm::vec3 up = c.up;
    if (!(glm::length(up) > 0.0f)) up = glm::vec3(0.0f, 1.0f, 0.0f);
    up = glm::normalize(up);
    if (std::fabs(glm::dot(f, up)) > 0.9999f)  // looking straight along up: pick another up
        up = std::fabs(f.z) < 0.9f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
    const glm::vec3 s = glm::normalize(glm::cross(f, up));
    const glm::vec3 u = glm::cross(s, f);
    glm::mat4 v(1.0f);
    v[0][0] = s.x; v[1][0] = s.y; v[2][0] = s.z;
    v[0][1] = u.x; v[1][1] = u.y; v[2][1] = u.z;
    v[0][2] = -f.x; v[1][2] = -f.y; v[2][2] = -f.z;
    v[3][0] = -glm::dot(s, c.eye);
    v[3][1] = -glm::dot(u, c.eye);
    v[3][2] = glm::dot(f, c.eye);
    return v;
}

glm::mat4 projection_matrix(const Camera& c, float aspect) {
    if (!(aspect > 0.0f) || !std::isfinite(aspect)) aspect = 1.0f;
    const double n = c.orthographic ? double(c.znear) : (c.znear > 0.0f ? double(c.znear) : 1e-3);
    double f = double(c.zfar);
    const bool infinite = std::isinf(f) || f <= 0.0;
    glm::mat4 p(0.0f);  // p[col][row]
    if (c.orthographic) {
        if (infinite || !(f > n)) f = n + std::max(std::fabs(n) * 1e4, 1000.0);
        const double h = c.ortho_half_height > 0.0f ? double(c.ortho_half_height) : 1.0;
        const double w = h * double(aspect);
        p[0][0] = float(1.0 / w);
        p[1][1] = float(1.0 / h);
        p[3][3] = 1.0f;
        const double d = f - n;
        if (c.reverse_z) {            // [0,1], near -> 1, far -> 0
            p[2][2] = float(1.0 / d);
            p[3][2] = float(f / d);
        } else if (c.zero_to_one) {   // [0,1], near -> 0, far -> 1
            p[2][2] = float(-1.0 / d);
            p[3][2] = float(-n / d);
        } else {                      // [-1,1]
            p[2][2] = float(-2.0 / d);
            p[3][2] = float(-(f + n) / d);
        }
        return p;
    }
    const double t = 1.0 / std::tan(0.5 * double(c.yfov));
    p[0][0] = float(t / double(aspect));
    p[1][1] = float(t);
    p[2][3] = -1.0f;
    if (!infinite && !(f > n)) f = n * 1e4;
    if (c.reverse_z) {                // [0,1], near -> 1, far -> 0 (infinite: depth = n / z)
        if (infinite) {
            p[2][2] = 0.0f;
            p[3][2] = float(n);
        } else {
            p[2][2] = float(n / (f - n));
            p[3][2] = float(f * n / (f - n));
        }
    } else if (c.zero_to_one) {       // [0,1], near -> 0, far -> 1
        if (infinite) {
            p[2][2] = -1.0f;
            p[3][2] = float(-n);
        } else {
            p[2][2] = float(f / (n - f));
            p[3][2] = float(f * n / (n - f));
        }
    } else {                          // [-1,1]
        if (infinite) {
            p[2][2] = -1.0f;
            p[3][2] = float(-2.0 * n);
        } else {
            p[2][2] = float((f + n) / (n - f));
            p[3][2] = float(2.0 * f * n / (n - f));
        }
    }
    return p;
}

}  // namespace camera
