// kernel.h - the sample kernel, the rotation noise and the per-pixel hash,
// all from a deterministic seed (our own generator: std::uniform_*_distribution
// differs between standard libraries, and kernels must be reproducible).
#pragma once

#include <ssao/ssao.h>

#include <glm/glm.hpp>

#include <vector>

namespace ssao_impl {

// A small, well-mixed generator (splitmix64) giving floats in [0, 1).
class Random {
public:
    explicit Random(uint64_t seed) : state_(seed) {}
    uint64_t next_u64();
    float next_float();  // [0, 1)

private:
    uint64_t state_;
};

// resolved.sample_count samples in tangent space (z along the normal), |k| <= 1.
// Hemisphere: z >= 0. Sphere: any z. Separable: the first ceil(N/2) samples in
// the x-z plane (y = 0), the rest in the y-z plane (x = 0), z >= 0.
// Accelerating: length u * lerp(0.1, 1, (i/n)^2) (u uniform, i the index
// within its set of n); uniform: uniform in the volume (area for the planes).
std::vector<glm::vec3> make_kernel(const ssao_settings& resolved);

// Visibility method: resolved.sample_count unit directions in tangent space,
// cosine-distributed over the hemisphere (z = cos theta) as a Fibonacci
// lattice: cos^2 theta stratified at (i + 0.5) / N, azimuth advancing by the
// golden angle from a seed-dependent start. Low-discrepancy, so a few
// directions already cover the hemisphere evenly.
std::vector<glm::vec3> make_directions(const ssao_settings& resolved);

// Per-pixel step jitter in (0, 1) for the visibility method, for pixel (x, y)
// of the viewport: a 4x4 ordered (Bayer) pattern for the 4x4 noise rotation
// (so a 4x4 box averages 16 offsets), a second hash for the hash rotation,
// the gradient noise at (y, x) for the gradient-noise rotation (swapped so
// that it is not tied to the angle: shaders/sampling.glsl), 0.5 without
// rotation. shaders/sampling.glsl computes the same at full resolution;
// below it the 4x4 noise rotation takes its angle and jitter from the
// gradient noise on the grid instead (gradient_noise() there: a 4x4 tile on
// a half-resolution grid would repeat every 8 pixels).
float step_jitter(ssao_rotation rotation, uint32_t x, uint32_t y, uint32_t seed);

// Interleaved gradient noise (Jimenez 2014) at (x, y), in [0, 1), in the
// shader's float arithmetic: the gradient-noise rotation turns pixel (x, y)
// by this many turns.
float gradient_noise(float x, float y);

// The 4x4 rotation noise: unit vectors (cos a, sin a) by row, y-major (index y*4+x).
std::vector<glm::vec2> make_noise(uint32_t seed);

// The per-pixel hash the shader uses (same integer arithmetic), in [0, 1).
float pixel_hash(uint32_t x, uint32_t y, uint32_t seed);

// Noise for TAA hosts (inputs.frame_index, variant FRAME_NOISE): frame n's
// offsets of the R2 sequence (Roberts 2018, the plastic number's 2D
// generalisation of the golden ratio), fract(n / g) and fract(n / g^2) with
// g = 1.3247179572: x turns the per-pixel rotation by x * 2 pi, y is added
// to the step jitter mod 1. Computed in 32-bit fixed point, so every uint32
// index is exact and consecutive frames stay evenly spread.
glm::dvec2 frame_noise_offsets(uint32_t frame_index);

}  // namespace ssao_impl
