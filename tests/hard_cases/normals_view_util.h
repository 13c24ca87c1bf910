// normals_view_util.h - helpers for the depth-only input's tests
// (test_hc_normals_from_depth.cpp): the normal debug views read back in full
// float precision through a host RGBA32F output texture, an analytic sphere
// G-buffer (the quad scenes have no curved surface), and the depth
// conventions every test runs through.
#pragma once

#include "hc_util.h"

#include <ssao/ssao.h>

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace nfd {

struct Convention {
    std::string name;
    glm::dmat4 proj;
    ssao_clip_range clip;
    GLenum format;
    bool ortho;
    double half_height;  // perspective: tan(fovy / 2); orthographic: half the view height
};

// Every depth convention: GL [-1,1] and [0,1] clip ranges, reverse-Z ([0,1]
// and [-1,1]), infinite far (standard and reversed), orthographic (standard,
// [0,1], reversed), D16, D24, D24S8, D32F, D32FS8. Near 0.1, far 100.
std::vector<Convention> conventions(double aspect, double ortho_half_h);

struct ViewResult {
    ssao_status status = SSAO_OK;
    std::vector<glm::vec3> n;   // viewport-sized, bottom row first: the view's RGB unpacked (2 c - 1)
    std::vector<float> alpha;
    uint32_t passes_run = 0;
};

struct ViewOptions {
    ssao_debug_view view = SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS;
    bool depth_only = true;        // normal_texture = 0
    GLenum normal_format = GL_RGBA16F;
    ssao_normal_space normal_space = SSAO_NORMAL_SPACE_VIEW;
    glm::dmat4 view_matrix{1.0};   // world-space normals: the G-buffer's normals are stored rotated back
    int pad = 0;                   // garbage texels (a near depth, a skewed normal) around the viewport
};

// One execute of a normal debug view, read back as floats.
ViewResult run_view(testgl::Fixture& fx, const analytic::GBuffer& g, const glm::dmat4& proj, ssao_clip_range clip,
                    GLenum depth_format, const ViewOptions& o = {});

// A sphere (centre c, radius r, view space) in front of a wall z = wall_z
// facing the camera (wall_z >= 0: sky behind the sphere instead), ray-cast
// through every pixel centre of proj, depth in the clip convention.
analytic::GBuffer sphere_gbuffer(const glm::dmat4& proj, ssao_clip_range clip, int w, int h, glm::dvec3 c, double r,
                                 double wall_z);

// Angle in radians between two directions (0 for two zero vectors).
double angle(glm::dvec3 a, glm::dvec3 b);

// One pixel's footprint across the view direction at view distance t.
double pixel_size(const Convention& c, double t, int height);

}  // namespace nfd
