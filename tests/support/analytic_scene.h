// analytic_scene.h - exact G-buffers for tests: parallelograms in view space
// ray-cast through each pixel centre of a given projection, giving the depth a
// rasteriser would store (before quantisation) and the view-space normal.
#pragma once

#include <ssao/ssao.h>

#include <glm/glm.hpp>

#include <vector>

namespace analytic {

// origin + a*u + b*v for a, b in [0,1]; the normal faces the camera.
struct Quad {
    glm::dvec3 origin, u, v;
};

struct Scene {
    std::vector<Quad> quads;
    void add_quad(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v) { quads.push_back({origin, u, v}); }
    // An axis-aligned box (six faces).
    void add_box(glm::dvec3 lo, glm::dvec3 hi);
};

struct GBuffer {
    int width = 0, height = 0;
    std::vector<float> depth;           // depth-buffer values; sky = the far value
    std::vector<glm::vec3> normal;      // view space, unit; (0,0,0) for sky
    std::vector<glm::dvec3> position;   // view space hit; NaN for sky
    bool sky(int x, int y) const { return std::isnan(position[static_cast<size_t>(y) * width + x].x); }
};

// Casts one ray per pixel centre through `proj` (column-major, right-handed,
// looking down -z) and stores depth in the given clip-range convention.
GBuffer render(const Scene& scene, const glm::dmat4& proj, ssao_clip_range clip, int width, int height);

// Projections used across the tests.
glm::dmat4 perspective(double fovy, double aspect, double n, double f);          // GL [-1,1]
glm::dmat4 perspective_zo(double fovy, double aspect, double n, double f);       // [0,1]
glm::dmat4 reverse_z(double fovy, double aspect, double n, double f);            // [0,1], near -> 1
glm::dmat4 reverse_z_infinite(double fovy, double aspect, double n);             // [0,1], near -> 1, far at infinity
glm::dmat4 infinite(double fovy, double aspect, double n);                       // GL [-1,1], far at infinity
glm::dmat4 orthographic(double half_w, double half_h, double n, double f);      // GL [-1,1]

void to_floats(const glm::dmat4& m, float out[16]);

}  // namespace analytic
