// geometry.h - procedural meshes for the reference tests.
#pragma once

#include "scene.h"

#include <cmath>

namespace testgeo {

// Adds the quad a, b, c, d (counter-clockwise seen from the side its normal faces).
inline void add_quad(scene::Mesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    const uint32_t base = uint32_t(m.positions.size());
    const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
    for (const auto& p : {a, b, c, d}) {
        m.positions.push_back(p);
        m.normals.push_back(n);
    }
    for (uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

// The floor y = 0 over [-L, L]^2, facing +y.
inline void add_floor(scene::Mesh& m, float L) {
    add_quad(m, {-L, 0, L}, {L, 0, L}, {L, 0, -L}, {-L, 0, -L});
}

// A UV sphere (vertices on the sphere).
inline void add_sphere(scene::Mesh& m, glm::vec3 centre, float r, int segments, int rings) {
    const uint32_t base = uint32_t(m.positions.size());
    const double pi = 3.14159265358979323846;
    for (int i = 0; i <= rings; ++i) {
        const double th = pi * i / rings;
        for (int j = 0; j <= segments; ++j) {
            const double ph = 2.0 * pi * j / segments;
            const glm::vec3 n(float(std::sin(th) * std::cos(ph)), float(std::cos(th)), float(std::sin(th) * std::sin(ph)));
            m.positions.push_back(centre + r * n);
            m.normals.push_back(n);
        }
    }
    const uint32_t row = uint32_t(segments + 1);
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            const uint32_t a = base + uint32_t(i) * row + uint32_t(j), b = a + 1, c = a + row, d = c + 1;
            for (uint32_t k : {a, c, b, b, c, d}) m.indices.push_back(k);
        }
}

}  // namespace testgeo
