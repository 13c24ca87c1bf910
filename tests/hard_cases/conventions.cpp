#include "conventions.h"

#include "analytic_scene.h"

#include <doctest/doctest.h>

#include <cmath>
#include <stdexcept>

namespace hc {

namespace {

GLenum format_named(const std::string& name, const std::string& whole) {
    if (name == "D16") return GL_DEPTH_COMPONENT16;
    if (name == "D24") return GL_DEPTH_COMPONENT24;
    if (name == "D24S8") return GL_DEPTH24_STENCIL8;
    if (name == "D32F") return GL_DEPTH_COMPONENT32F;
    if (name == "D32FS8") return GL_DEPTH32F_STENCIL8;
    throw std::invalid_argument("no depth format in the convention \"" + whole + "\"");
}

// The convention's name split at its last space: projection and format.
Convention named(const char* name, std::string& projection) {
    const std::string whole = name;
    const size_t space = whole.rfind(' ');
    if (space == std::string::npos) throw std::invalid_argument("no depth format in the convention \"" + whole + "\"");
    projection = whole.substr(0, space);
    Convention c;
    c.name = name;
    c.format = format_named(whole.substr(space + 1), whole);
    return c;
}

}  // namespace

std::vector<Convention> perspective_conventions(double aspect, double n, double f,
                                                std::initializer_list<const char*> names) {
    std::vector<Convention> out;
    for (const char* name : names) {
        std::string projection;
        Convention c = named(name, projection);
        c.n = n;
        c.f = f;
        const ssao_clip_range gl = SSAO_CLIP_NEGATIVE_ONE_TO_ONE, zo = SSAO_CLIP_ZERO_TO_ONE;
        if (projection == "GL [-1,1]") {
            c.proj = analytic::perspective(kFov, aspect, n, f);
            c.clip = gl;
        } else if (projection == "[0,1]") {
            c.proj = analytic::perspective_zo(kFov, aspect, n, f);
            c.clip = zo;
        } else if (projection == "reverse-Z [0,1]") {
            c.proj = analytic::reverse_z(kFov, aspect, n, f);
            c.clip = zo;
            c.reverse = true;
        } else if (projection == "reverse-Z [-1,1]") {
            c.proj = reverse_z_gl(kFov, aspect, n, f);
            c.clip = gl;
            c.reverse = true;
        } else if (projection == "GL infinite") {
            c.proj = analytic::infinite(kFov, aspect, n);
            c.clip = gl;
            c.infinite = true;
            c.f = INFINITY;
        } else if (projection == "reverse-Z infinite") {
            c.proj = analytic::reverse_z_infinite(kFov, aspect, n);
            c.clip = zo;
            c.reverse = c.infinite = true;
            c.f = INFINITY;
        } else {
            throw std::invalid_argument(std::string("no perspective projection in the convention \"") + name + "\"");
        }
        out.push_back(c);
    }
    return out;
}

std::vector<Convention> ortho_conventions(double hw, double hh, double n, double f,
                                          std::initializer_list<const char*> names) {
    std::vector<Convention> out;
    for (const char* name : names) {
        std::string projection;
        Convention c = named(name, projection);
        c.ortho = true;
        c.n = n;
        c.f = f;
        if (projection == "ortho GL [-1,1]") {
            c.proj = analytic::orthographic(hw, hh, n, f);
            c.clip = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
        } else if (projection == "ortho [0,1]") {
            c.proj = ortho_zo(hw, hh, n, f);
            c.clip = SSAO_CLIP_ZERO_TO_ONE;
        } else if (projection == "ortho reverse [0,1]") {
            c.proj = ortho_reverse(hw, hh, n, f);
            c.clip = SSAO_CLIP_ZERO_TO_ONE;
            c.reverse = true;
        } else {
            throw std::invalid_argument(std::string("no orthographic projection in the convention \"") + name + "\"");
        }
        out.push_back(c);
    }
    return out;
}

std::vector<Convention> operator+(std::vector<Convention> a, const std::vector<Convention>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

Out run(testgl::Fixture& fx, const analytic::GBuffer& g, const Convention& c, const RunOptions& base) {
    RunOptions o = base;
    o.depth_format = c.format;
    return run(fx, g, c.proj, c.clip, o);
}

void check_same_ao(const std::vector<float>& ref, const std::vector<float>& ao, uint32_t sample_count,
                   const std::string& what) {
    const Diff d = diff(ref, ao, {}, 1.0 / sample_count);
    MESSAGE(what << ": mean |diff| " << d.mean_abs << ", worst " << d.worst << ", " << d.over_1e3 << " px > 1e-3, "
                 << d.over_one_sample << " px > one sample, of " << d.compared);
    CHECK(d.compared > 0);
    CHECK(d.mean_abs < 0.004);
    CHECK(d.over_one_sample <= d.compared / 100);
    CHECK(d.worst <= 2.0 / sample_count + 2e-3);
}

}  // namespace hc
