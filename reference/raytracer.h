// raytracer.h - ground-truth ambient occlusion by ray tracing (Embree 3).
//
// V_R(p) = (1/pi) * integral over the hemisphere around n of [no hit within R] cos(theta),
// estimated with cosine-distributed occlusion rays (docs/reference.md: "Ground truth: the
// ray-traced reference").
// Samples: a Hammersley point set of N points, Cranley-Patterson rotated per
// pixel (or per call) by a hash of the seed, so results are deterministic for
// a given seed and independent of the thread count.
#pragma once

#include "camera.h"
#include "scene.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace raytrace {

struct Estimate {
    double visibility = 1.0;  // fraction of unoccluded rays (the estimate of V_R)
    double std_error = 0.0;   // sqrt(p (1 - p) / (N - 1)): the standard error of the mean
    int rays = 0;
};

struct RenderOptions {
    int width = 0, height = 0;
    float radius = 0.5f;      // R, scene units
    int samples = 1024;       // occlusion rays per pixel
    uint32_t seed = 1;
    int threads = 0;          // 0 = all cores
    bool progress = false;    // progress bar on stderr
};

// One image. Row 0 is the top row of the picture; pixel (x, y) is traced
// through its centre. Sky pixels (the primary ray hits nothing between the
// near and far planes) have mask 0, ao 1, std_error 0, depth +infinity (as
// ssao-host's view_depth.exr), normal 0, position NaN.
struct Image {
    int width = 0, height = 0;
    std::vector<float> ao;         // V_R
    std::vector<float> std_error;  // per-pixel standard error of ao
    std::vector<float> mask;       // 1 = geometry, 0 = sky
    std::vector<float> depth;      // view depth: -z_view of the hit (positive), +inf for sky
    std::vector<float> normal;     // 3 per pixel: view-space geometric normal facing the camera
    std::vector<float> position;   // 3 per pixel: view-space primary hit (NaN for sky)
    double seconds = 0.0;
    uint64_t rays = 0;             // primary + occlusion rays traced
};

class Tracer {
public:
    // Builds the BVH of the mesh. Check ok() / error() afterwards.
    explicit Tracer(const scene::Mesh& mesh);
    ~Tracer();
    Tracer(const Tracer&) = delete;
    Tracer& operator=(const Tracer&) = delete;

    bool ok() const;
    const std::string& error() const;

    // Length of the mesh's bounding-box diagonal (at least 1e-6).
    float scene_size() const;
    // The offset of ray origins from the surface (scaled to the scene).
    float epsilon() const;

    // AO at a surface point p with unit normal n (p is offset along n by epsilon()).
    // radius may be +infinity.
    Estimate ao_at(const glm::vec3& p, const glm::vec3& n, float radius, int samples, uint32_t seed) const;

    // Nearest hit along a ray; returns false on a miss. `normal` is the unit
    // geometric normal of the triangle hit (not oriented).
    bool intersect(const glm::vec3& origin, const glm::vec3& dir, float tnear, float tfar, float& t,
                   glm::vec3& normal) const;

    // Traces the image the host rasterises with camera `cam` at opts.width x opts.height:
    // primary rays from the inverse of projection * view, so orthographic,
    // reverse-Z and infinite far planes match the rasteriser exactly.
    bool render(const camera::Camera& cam, const RenderOptions& opts, Image& out, std::string& error) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace raytrace
