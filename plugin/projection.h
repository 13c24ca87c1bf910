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

// The depth-buffer value d -> view-space position at NDC (x, y), as the shader does.
glm::dvec3 view_position(const ProjectionInfo& p, double ndc_x, double ndc_y, double depth);
// The depth-buffer value of a view-space point (for tests and tools).
double depth_of(const ProjectionInfo& p, const glm::dvec3& view);

}  // namespace ssao_impl
