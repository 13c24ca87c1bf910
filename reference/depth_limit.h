// depth_limit.h - the depth-only limit: the AO an ideal ray-marcher gets from a
// single depth layer (the reference's own primary hits and face normals), the
// yardstick for every screen-space estimator. docs/reference.md: "The depth-only limit".
//
// The rule, per pixel P (view-space primary hit, unit face normal n facing the
// camera) and radius R:
//   V_limit(P) = fraction of cosine-weighted directions w around n whose
//                segment P + s w, 0 < s < R, has no blocked point.
// A point S (view space) is read against the depth layer like this:
//   - project S with the camera's projection; behind the eye (clip w <= 0) or
//     outside the image: open. Its texel is the pixel the projection falls in
//     (floor of the window coordinates, row 0 at the top). A sky texel: open.
//   - a texel's plane read: for texel Q (primary hit Q, normal n_Q, depth
//     d_Q = -Q.z), the depth where the eye ray through S (orthographic: the line
//     through S along the view axis) meets the plane through Q with normal n_Q.
//     Where that plane is within kEdgeOn of edge-on along the ray (perspective:
//     n_Q.S >= -kEdgeOn * depth(S); orthographic: n_Q.z <= kEdgeOn), d_Q instead.
//   - the surface depth under S, d_surf, is the farthest (largest) of the plane
//     reads of S's texel and of those of its 4 edge neighbours N that continue
//     its surface over a convex edge: N is geometry, |d_N - d_Q| <= kContinuity * d_Q,
//     and each hit lies behind the other's plane (n_Q.(N - Q) < 0 and
//     n_N.(Q - N) < 0). A texel's plane, extrapolated over its pixel's footprint,
//     lies in front of a surface that curves away from it (faceted or smooth,
//     worst where the surface is seen at a grazing angle: limbs, silhouettes),
//     so by itself it blocks points just above the real surface; on a convex
//     surface the real depth is behind every neighbour's tangent plane, and the
//     farthest of them is the tightest such bound. Concave neighbours (creases,
//     contact with the floor) do not join: there the texel's own plane is kept.
//   - Delta = depth(S) - d_surf (view depth, i.e. -z_view, along the view axis,
//     not along the eye ray; scene units). S is blocked when
//         kSelfEpsilon * d_Q < Delta < thickness.
// kSelfEpsilon only absorbs float rounding of the stored hits (about 1e-7
// relative): without it a point on P's own plane, or on a coplanar neighbour's,
// could read as a hair behind it. Any real occluder puts points far deeper.
//
// The marcher is exact, the limit of infinitely many steps: it walks the
// segment texel by texel (every pixel boundary its projection crosses) and, in
// each texel, solves for the points where the rule can change (any plane's
// Delta = eps or = thickness, any plane's edge-on switch), then tests the rule
// between them. tests/reference/limit_oracle.h implements the same rule
// independently by brute force (reference.limit_oracle).
#pragma once

#include "camera.h"
#include "raytracer.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace depth_limit {

// One source of truth for the defaults (ssao-reference's --help and the README quote them).
constexpr int kDefaultDirections = 1024;   // per pixel
constexpr int kReplicas = 8;               // independently rotated sets the directions are split into
constexpr double kDefaultThicknessOfR = 0.5;  // thickness = R / 2
constexpr double kEdgeOn = 1e-3;
constexpr double kSelfEpsilon = 1e-5;
constexpr double kContinuity = 0.05;  // relative depth step up to which a neighbour continues a surface

// One texel of the depth layer.
struct Texel {
    glm::dvec3 q{0.0};  // view-space surface point (the primary hit)
    glm::dvec3 n{0.0, 0.0, 1.0};  // unit view-space normal facing the camera
};

// The texel's plane read at view-space point s (see the rule above).
double surface_depth(const Texel& t, const glm::dvec3& s, bool ortho);
// Whether s is blocked by this texel's plane alone (a texel no neighbour joins):
// kSelfEpsilon * d_Q < depth(s) - surface_depth < thickness.
// thickness may be +infinity (a height field).
bool blocked_by(const Texel& t, const glm::dvec3& s, double thickness, bool ortho);

struct Estimate {
    double visibility = 1.0;
    double std_error = 0.0;  // standard error of the mean over the kReplicas rotated sets
};

// The depth layer of a reference image: positions, normals and coverage of
// raytrace::Image, with the camera's projection.
class Layer {
public:
    Layer(const camera::Camera& cam, const raytrace::Image& img);

    int width() const { return width_; }
    int height() const { return height_; }
    bool orthographic() const { return ortho_; }

    // The texel under view-space point s; false when behind the eye or off the image.
    bool pixel_of(const glm::dvec3& s, int& x, int& y) const;
    // False for sky.
    bool texel(int x, int y, Texel& t) const;
    // d_surf under view-space point s: the farthest plane read of its texel and the
    // joined neighbours; +infinity where s is open whatever its depth (sky, off the image).
    double surface_depth_at(const glm::dvec3& s) const;
    // The whole per-point rule: project, read the texel, compare.
    bool point_blocked(const glm::dvec3& s, double thickness) const;
    // Whether any point of p + s dir, 0 < s < radius, is blocked (exact traversal).
    bool segment_blocked(const glm::dvec3& p, const glm::dvec3& dir, double radius, double thickness) const;
    // V_limit at pixel (x, y) with `directions` (a multiple of kReplicas) cosine-weighted
    // directions; pixel_seed picks the rotations. Sky: visibility 1, std_error 0.
    Estimate visibility(int x, int y, double radius, double thickness, int directions, uint32_t pixel_seed) const;

private:
    int width_ = 0, height_ = 0;
    bool ortho_ = false;
    glm::dmat4 proj_{1.0};
    std::vector<Texel> texels_;   // per pixel, normals normalised once
    std::vector<uint8_t> geometry_;
    std::vector<uint8_t> joined_;  // per texel, bit k: edge neighbour k's plane joins the read

    // The texel's plane first, then the joined neighbours'; 0 for sky.
    int planes(int x, int y, Texel out[5]) const;
};

struct Options {
    double radius = 0.5;     // R, scene units
    double thickness = 0.25; // scene units, > 0, may be +infinity
    int directions = kDefaultDirections;
    uint32_t seed = 1;
    int threads = 0;         // 0 = all cores
    bool progress = false;
};

struct Image {
    std::vector<float> ao;         // V_limit; 1 for sky
    std::vector<float> std_error;  // 0 for sky
    double seconds = 0.0;
};

// The per-pixel seed `compute` gives pixel (x, y) of a width-wide image.
uint32_t pixel_seed(uint32_t seed, int x, int y, int width);

// "" when the options are valid, else why not.
std::string check(const Options& o);

// The limit for every pixel of a reference image traced with `cam`.
// Deterministic for a seed, independent of the thread count.
bool compute(const camera::Camera& cam, const raytrace::Image& img, const Options& o, Image& out, std::string& error);

}  // namespace depth_limit
