#include "provenance.h"

#include <cmath>
#include <sstream>

namespace provenance {
namespace {

// Six significant digits (the stream's default): what both tools compute from the same inputs
// agrees to far more, and the values stay readable in a header dump.
std::string num(double v) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    std::ostringstream s;
    s << v;
    return s.str();
}

// Five digits: the default 0.7854 rad and --fov 45 both read "45".
std::string fov(float radians) {
    std::ostringstream s;
    s.precision(5);
    s << glm::degrees(double(radians));
    return s.str();
}

std::string vec(const glm::vec3& v) { return num(v.x) + "," + num(v.y) + "," + num(v.z); }

std::string file_name(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

Fields describe(const std::string& scene_path, int width, int height, const camera::Camera& c, double radius,
                std::optional<double> thickness) {
    const std::string p = kPrefix;
    Fields f = {
        {p + "scene", file_name(scene_path)},
        {p + "size", std::to_string(width) + "x" + std::to_string(height)},
        {p + "projection", c.orthographic ? "orthographic half-height " + num(c.ortho_half_height)
                                          : "perspective fov " + fov(c.yfov) + " deg"},
        {p + "eye", vec(c.eye)},
        {p + "target", vec(c.target)},
        {p + "up", vec(c.up)},
        {p + "near", num(c.znear)},
        {p + "far", num(c.zfar)},
        {p + "depth", c.reverse_z ? "reverse-Z [0,1]" : c.zero_to_one ? "[0,1]" : "[-1,1]"},
        {p + "radius", num(radius)},
    };
    if (thickness) f.emplace_back(p + "thickness", num(*thickness));
    return f;
}

std::optional<Difference> compare(const Fields& a, const Fields& b) {
    const std::string p = kPrefix;
    for (const auto& fa : a)
        for (const auto& fb : b)
            if (fa.first == fb.first && fa.second != fb.second) {
                const std::string name = fa.first.rfind(p, 0) == 0 ? fa.first.substr(p.size()) : fa.first;
                return Difference{name, fa.second, fb.second};
            }
    return std::nullopt;
}

}  // namespace provenance
