#include "kernel.h"

#include <cmath>

namespace ssao_impl {

uint64_t Random::next_u64() {
    uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

float Random::next_float() {
    return static_cast<float>(next_u64() >> 40) * (1.0f / 16777216.0f);
}

namespace {

float lerp(float a, float b, float t) { return a + (b - a) * t; }

// A random direction in the set the shape allows, never (near) zero length.
glm::vec3 direction(Random& rng, ssao_kernel_shape shape, int plane) {
    for (;;) {
        // One draw per statement: the order in which a constructor's
        // arguments are evaluated is unspecified (GCC goes right to left,
        // clang left to right), and the kernel must not depend on the
        // compiler. This is GCC's order, which the reference kernels and golden images were made with.
        const float z = rng.next_float();
        const float y = rng.next_float() * 2.0f - 1.0f;
        const float x = rng.next_float() * 2.0f - 1.0f;
        glm::vec3 v(x, y, z);
        if (shape == SSAO_KERNEL_SPHERE) v.z = v.z * 2.0f - 1.0f;
        if (shape == SSAO_KERNEL_SEPARABLE) (plane == 0 ? v.y : v.x) = 0.0f;
        const float len = glm::length(v);
        if (len > 1e-3f && len <= 1.0f) return v / len;  // rejection keeps directions uniform
    }
}

}  // namespace

std::vector<glm::vec3> make_kernel(const ssao_settings& s) {
    Random rng(0x5ea0u ^ (static_cast<uint64_t>(s.seed) << 32));
    const int total = static_cast<int>(s.sample_count);
    const bool separable = s.kernel_shape == SSAO_KERNEL_SEPARABLE;
    const int first = separable ? (total + 1) / 2 : total;
    std::vector<glm::vec3> kernel;
    kernel.reserve(total);
    for (int i = 0; i < total; ++i) {
        const int plane = i < first ? 0 : 1;
        const int index = plane == 0 ? i : i - first;
        const int count = plane == 0 ? first : total - first;
        const glm::vec3 dir = direction(rng, s.kernel_shape, plane);
        const float u = rng.next_float();
        float length;
        if (s.distribution == SSAO_DISTRIBUTION_ACCELERATING) {
            const float t = static_cast<float>(index) / static_cast<float>(count);
            length = u * lerp(0.1f, 1.0f, t * t);
        } else {
            length = separable ? std::sqrt(u) : std::cbrt(u);
        }
        kernel.push_back(dir * length);
    }
    return kernel;
}

std::vector<glm::vec3> make_directions(const ssao_settings& s) {
    Random rng(0xd1c5ull ^ (static_cast<uint64_t>(s.seed) << 32));
    const float start = rng.next_float();
    const int n = static_cast<int>(s.sample_count);
    constexpr float kGoldenFraction = 0.6180339887f;
    std::vector<glm::vec3> dirs;
    dirs.reserve(n);
    for (int i = 0; i < n; ++i) {
        const float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(n);  // sin^2 theta
        float turn = start + kGoldenFraction * static_cast<float>(i);
        turn -= std::floor(turn);
        const float a = turn * 6.28318530718f, r = std::sqrt(u);
        dirs.emplace_back(r * std::cos(a), r * std::sin(a), std::sqrt(1.0f - u));
    }
    return dirs;
}

float step_jitter(ssao_rotation rotation, uint32_t x, uint32_t y, uint32_t seed) {
    if (rotation == SSAO_ROTATION_NOISE_4X4) {
        static const int kBayer[16] = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
        return (static_cast<float>(kBayer[(y & 3u) * 4u + (x & 3u)]) + 0.5f) / 16.0f;
    }
    if (rotation == SSAO_ROTATION_HASH) return pixel_hash(y, x, seed ^ 0x5bd1e995u) * 0.9999f + 0.00005f;
    if (rotation == SSAO_ROTATION_GRADIENT_NOISE)
        return gradient_noise(static_cast<float>(y), static_cast<float>(x)) * 0.9999f + 0.00005f;
    return 0.5f;
}

float gradient_noise(float x, float y) {
    const auto fract = [](float v) { return v - std::floor(v); };
    return fract(52.9829189f * fract(x * 0.06711056f + y * 0.00583715f));
}

std::vector<glm::vec2> make_noise(uint32_t seed) {
    Random rng(0x4015eull ^ (static_cast<uint64_t>(seed) << 32));
    std::vector<glm::vec2> noise;
    for (int i = 0; i < 16; ++i) {
        const float a = rng.next_float() * 6.28318530718f;
        noise.emplace_back(std::cos(a), std::sin(a));
    }
    return noise;
}

float pixel_hash(uint32_t x, uint32_t y, uint32_t seed) {
    // PCG-style integer hash; shaders/sampling.glsl pixel_hash computes exactly this.
    uint32_t v = x * 1973u + y * 9277u + seed * 26699u;
    v = v * 747796405u + 2891336453u;
    uint32_t w = ((v >> ((v >> 28u) + 4u)) ^ v) * 277803737u;
    w = (w >> 22u) ^ w;
    return static_cast<float>(w >> 8) * (1.0f / 16777216.0f);
}

glm::dvec2 frame_noise_offsets(uint32_t frame_index) {
    // round(2^32 / g) and round(2^32 / g^2): the products wrap mod 2^32,
    // which is exactly the fractional part in 32-bit fixed point.
    const uint32_t a = frame_index * 3242174889u;
    const uint32_t b = frame_index * 2447445414u;
    return glm::dvec2(a, b) / 4294967296.0;
}

}  // namespace ssao_impl
