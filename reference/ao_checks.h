// ao_checks.h - whether an image read as AO can be compared at all: every
// value ssao-error compares must be finite and within [0, 1] (up to
// kAoTolerance, for the rounding of encoders), and there must be something
// to compare. A NaN reference once compared "0 pixels" with exit 0, and test
// values of -1e38 gave an RMSE of 1e38 with exit 0.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace aocheck {

// How far outside [0, 1] an AO value may lie and still be taken as AO.
constexpr float kAoTolerance = 1e-3f;

// Checks `values` (width x height, row-major) at the pixels where `use` is
// non-zero (every pixel when `use` is null). Returns an empty string when all
// are finite and within [-kAoTolerance, 1 + kAoTolerance]; otherwise one
// sentence without a final period that counts the bad pixels and gives the
// first one, e.g. "3 of 1024 compared pixels are NaN or infinite (the first
// at x 4, y 0)".
std::string check_values(const std::vector<float>& values, int width, const std::vector<uint8_t>* use);

}  // namespace aocheck
