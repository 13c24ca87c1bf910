// limit_oracle.h - a second, independent implementation of the depth-only limit
// (reference/depth_limit.h), for tests: a brute-force march written from the
// definition, sharing no code with depth_limit.cpp.
//
// The definition, per geometry pixel P (view-space primary hit p, unit face
// normal n facing the camera), radius R and thickness T:
//   V_limit(P) = the cosine-weighted fraction of directions w around n whose
//                segment p + s w, 0 < s < R, has no blocked point.
// A view-space point S is read against the depth layer so:
//   - S projects (the camera's projection; window coordinates with row 0 at the
//     top) into texel (floor(x), floor(y)). Behind the eye or off the image:
//     open. A sky texel: open.
//   - a texel's plane read at S: the view depth (-z) where the eye ray through S
//     (orthographic: the line through S along the view axis) meets the plane
//     through the texel's hit with its normal; where that ray runs within 1e-3
//     of parallel to the plane, or meets it behind the eye, the texel's own depth.
//   - the surface depth under S, d_surf, is the largest of the plane reads of S's
//     texel Q and of each edge neighbour N that continues Q's surface over a
//     convex edge: N is geometry, |d_N - d_Q| <= 0.05 d_Q, and each hit lies
//     strictly behind the other's plane (n_Q.(N - Q) < 0 and n_N.(Q - N) < 0).
//   - the gap Delta = depth(S) - d_surf, both view depths (-z: along the view
//     axis, not the eye ray), scene units. S is blocked when 1e-5 d_Q < Delta < T.
// The march takes `steps` evenly spaced points s = (i + 1/2) R / steps,
// i = 0 .. steps - 1, in double precision; a segment is blocked when any of
// them is. A blocked interval shorter than R / steps may be missed: that is the
// oracle's only approximation, and what comparing it with the exact marcher measures.
#pragma once

#include "camera.h"
#include "raytracer.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace limit_oracle {

struct Options {
    double radius = 0.5;
    double thickness = 0.25;
    int steps = 512;
};

class DepthLayer {
public:
    DepthLayer(const camera::Camera& cam, const raytrace::Image& img);

    bool geometry(int x, int y) const { return geo_[idx(x, y)] != 0; }
    glm::dvec3 normal(int x, int y) const { return n_[idx(x, y)]; }

    // Whether view-space point s is blocked (the rule above).
    bool blocked(const glm::dvec3& s, double thickness) const;
    // Whether no march point of p + s w, 0 < s < R, is blocked.
    bool segment_open(const glm::dvec3& p, const glm::dvec3& w, const Options& o) const;
    // The fraction of `dirs` (unit view-space directions) whose segment from pixel
    // (x, y)'s hit is open; 1 for sky.
    double visibility(int x, int y, const std::vector<glm::dvec3>& dirs, const Options& o) const;

private:
    size_t idx(int x, int y) const { return size_t(y) * size_t(w_) + size_t(x); }
    double plane_read(size_t i, const glm::dvec3& s) const;

    int w_ = 0, h_ = 0;
    bool ortho_ = false;
    glm::dmat4 proj_{1.0};
    std::vector<glm::dvec3> q_, n_;
    std::vector<uint8_t> geo_;
    std::vector<std::vector<size_t>> convex_neighbours_;  // per texel
};

}  // namespace limit_oracle
