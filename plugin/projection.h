// projection.h - what a projection matrix says about the depth it produced:
// perspective or orthographic, reversed or not, near and far distances, the
// depth value of the far plane (sky), and the inverse used to rebuild view
// positions. Everything the shaders need is derived here, once per frame,
// from the matrix and the clip range (after XeGTAO's single setup function).
#pragma once

#include <ssao/ssao.h>

#include <glm/glm.hpp>

#include <string>

namespace ssao_impl {

struct ProjectionInfo {
    glm::dmat4 proj{1.0};
    glm::dmat4 inverse{1.0};
    bool orthographic = false;
    bool reverse_z = false;
    bool infinite_far = false;
    double near_distance = 0.0;
    double far_distance = 0.0;   // +inf when infinite
    double ndc_per_depth = 2.0;  // d(ndc_z)/d(depth): 2 for [-1,1], 1 for [0,1]
    float sky_depth = 1.0f;      // the depth-buffer value of the far plane
};

// Fails with INVALID_PROJECTION (and a sentence) for a matrix that is not a
// finite, invertible, right-handed (camera looks down -z) perspective or
// orthographic projection.
ssao_status analyse_projection(const float m[16], ssao_clip_range clip, ProjectionInfo& out,
                               std::string& why);

// View position from view z by multiply-adds (after XeGTAO's NDCToViewMul/Add):
// for viewport pixel coordinates px (a pixel's centre is +0.5),
//   view xy = (mul_z * px + add_z) * z + (mul_1 * px + add_1).
// Exact for every projection analyse_projection accepts (clip w does not
// depend on view x or y: w = w_z * z + w_1), off-centre and sheared ones
// included: perspective has mul_1 = 0 (xy proportional to z, plus a constant
// only for a translated frustum), orthographic mul_z = add_z = 0. mat2s are
// column-major ([column][row]), as GLSL's.
struct ViewFromZ {
    glm::dmat2 mul_z{0.0}, mul_1{0.0};
    glm::dvec2 add_z{0.0}, add_1{0.0};
    // Depth-step constants: clip w = w_z * z + w_1, clip z = z_z * z + z_1;
    // d(ndc z)/d(view z) = det / w^2 with det = z_z * w_1 - z_1 * w_z.
    double w_z = 0.0, w_1 = 0.0, z_z = 0.0, z_1 = 0.0, det = 0.0;
};
ViewFromZ view_from_z(const ProjectionInfo& p, int viewport_width, int viewport_height);
glm::dvec3 view_position_from_z(const ViewFromZ& c, double px_x, double px_y, double view_z);

// The depth-buffer value d -> view-space position at NDC (x, y), as the shader does.
glm::dvec3 view_position(const ProjectionInfo& p, double ndc_x, double ndc_y, double depth);
// The depth-buffer value of a view-space point (for tests and tools).
double depth_of(const ProjectionInfo& p, const glm::dvec3& view);

}  // namespace ssao_impl
