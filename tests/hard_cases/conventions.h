// conventions.h - the depth conventions the hard cases run one scene under:
// a projection, its clip range and a depth format, named as the cases report
// them, so that every case builds the same convention the same way.
#pragma once

#include "gl_fixture.h"
#include "hc_util.h"

#include <ssao/ssao.h>

#include <glm/glm.hpp>

#include <initializer_list>
#include <string>
#include <vector>

namespace hc {

struct Convention {
    const char* name = "";  // one of the names asked for (string literals)
    glm::dmat4 proj{1.0};
    ssao_clip_range clip = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
    GLenum format = GL_DEPTH_COMPONENT32F;
    bool ortho = false, reverse = false, infinite = false;
    double n = 0.0, f = 0.0;  // f is INFINITY for the infinite projections
};

// The named perspective conventions, in the order named, with the hard
// cases' 60-degree field of view. A name is "<projection> <format>" with the
// projection one of "GL [-1,1]", "[0,1]", "reverse-Z [0,1]",
// "reverse-Z [-1,1]", "GL infinite", "reverse-Z infinite" and the format one
// of D16, D24, D24S8, D32F, D32FS8. Throws on any other name.
std::vector<Convention> perspective_conventions(double aspect, double n, double f,
                                                std::initializer_list<const char*> names);

// The named orthographic conventions (half extents hw x hh), the projection
// one of "ortho GL [-1,1]", "ortho [0,1]", "ortho reverse [0,1]".
std::vector<Convention> ortho_conventions(double hw, double hh, double n, double f,
                                          std::initializer_list<const char*> names);

// `a` then `b`.
std::vector<Convention> operator+(std::vector<Convention> a, const std::vector<Convention>& b);

// One execute of the G-buffer rendered under `c`, its depth in c's format.
Out run(testgl::Fixture& fx, const analytic::GBuffer& g, const Convention& c, const RunOptions& base = {});

// CHECKs that `ao` is the reference convention's AO up to depth precision,
// which only moves samples lying within a few depth steps of a comparison
// threshold: at most one sample flips at a pixel, rarely (mean |diff| below
// 0.004, at most 1 % of the pixels off by more than one sample, none by more
// than two). Reports the difference, labelled `what`.
void check_same_ao(const std::vector<float>& ref, const std::vector<float>& ao, uint32_t sample_count,
                   const std::string& what);

}  // namespace hc
