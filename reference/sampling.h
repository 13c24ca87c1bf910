// sampling.h - the sample patterns the reference tools share: a 32-bit hash for
// per-pixel seeds, the Hammersley point set with Cranley-Patterson rotation, and
// cosine-weighted directions around a normal. Used by the ray tracer (V_R) and
// the depth-only limit, so both integrate the hemisphere the same way.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace sampling {

constexpr double kPi = 3.14159265358979323846;

inline uint32_t hash32(uint32_t x) {  // lowbias32
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

// Van der Corput radical inverse in base 2.
inline double radical_inverse2(uint32_t i) {
    i = (i << 16) | (i >> 16);
    i = ((i & 0x55555555u) << 1) | ((i & 0xAAAAAAAAu) >> 1);
    i = ((i & 0x33333333u) << 2) | ((i & 0xCCCCCCCCu) >> 2);
    i = ((i & 0x0F0F0F0Fu) << 4) | ((i & 0xF0F0F0F0u) >> 4);
    i = ((i & 0x00FF00FFu) << 8) | ((i & 0xFF00FF00u) >> 8);
    return double(i) * (1.0 / 4294967296.0);
}

inline double to_unit(uint32_t h) { return double(h) * (1.0 / 4294967296.0); }

// Orthonormal basis around unit n (Duff et al. 2017): no degenerate case.
template <typename V>
void basis(const V& n, V& t, V& b) {
    using S = typename V::value_type;
    const S sign = std::copysign(S(1), n.z);
    const S a = S(-1) / (sign + n.z);
    const S bb = n.x * n.y * a;
    t = V(S(1) + sign * n.x * n.x * a, sign * bb, -sign * n.x);
    b = V(bb, sign + n.y * n.y * a, -n.y);
}

// The Cranley-Patterson shift of a pattern, from a hash.
struct Shift {
    double u1 = 0.0, u2 = 0.0;
};
inline Shift shift_from(uint32_t rot_hash) {
    return {to_unit(hash32(rot_hash ^ 0x9e3779b9u)), to_unit(hash32(rot_hash + 0x632be5abu))};
}

// Point i of the N-point Hammersley set ((i + 1/2)/N, radical_inverse(i)),
// shifted modulo 1, mapped to a cosine-weighted direction (Malley) in the
// tangent frame (t, b, n). Returns the direction's components (x along t,
// y along b, z along n).
inline glm::dvec3 cosine_direction(int i, int N, const Shift& s) {
    double u1 = (double(i) + 0.5) / double(N) + s.u1;
    double u2 = radical_inverse2(uint32_t(i)) + s.u2;
    u1 -= std::floor(u1);
    u2 -= std::floor(u2);
    const double r = std::sqrt(u1);
    const double phi = 2.0 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1))};
}

}  // namespace sampling
