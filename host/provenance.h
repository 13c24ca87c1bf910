// provenance.h - what an AO image was made with (scene, size, projection,
// camera, radius, thickness), written by ssao-host and ssao-reference into
// their EXR headers as string attributes and compared by ssao-error, so two
// images of different views are not compared by accident.
#pragma once

#include "camera.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace provenance {

// (EXR attribute name, value), in a fixed order. Names start with kPrefix.
using Fields = std::vector<std::pair<std::string, std::string>>;
constexpr const char* kPrefix = "ssao:";

// The fields of an image of `width` x `height` pixels of the scene file
// `scene_path` (recorded by its file name, so runs from other folders or
// machines compare), seen by `c`, with AO radius `radius` and, where the
// estimator has one, the thickness of a depth layer (+inf allowed).
Fields describe(const std::string& scene_path, int width, int height, const camera::Camera& c, double radius,
                std::optional<double> thickness = std::nullopt);

struct Difference {
    std::string field;   // without kPrefix: "eye", "radius", ...
    std::string a, b;    // the two values
};

// The first field present in both `a` and `b` whose values differ, in
// describe()'s order (what was chosen before what follows from it: the eye
// before the near plane fitted to it). A field
// only one of them has (thickness, say) is not compared.
std::optional<Difference> compare(const Fields& a, const Fields& b);

}  // namespace provenance
