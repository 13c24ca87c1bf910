// cell_spread.h - the fixed-pattern ("stipple") figure of an AO image: the
// error (AO minus a reference) averaged separately at each of the 64
// positions of an 8x8 cell of viewport pixels, and the spread of those 64
// means. A rotation pattern that repeats every 8 pixels (the 4x4 tile on a
// half-resolution grid) shows as a spread well above what the reference's
// own noise and the scene's content leave.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace cell_spread {

struct Result {
    double range = 0.0;   // largest minus smallest of the 64 position means
    double stddev = 0.0;  // their standard deviation
    int positions = 0;    // positions with at least one pixel
};

// `test` and `ref` are width * height values; pixels where `mask` is 0 (sky)
// are left out; `mask` may be empty (every pixel counts). `ref` may be empty:
// the figure is then that of `test` itself (for a scene whose AO is not
// tied to the cell, such as a surface with features at every scale).
inline Result measure(const std::vector<float>& test, const std::vector<float>& ref, const std::vector<float>& mask,
                      int width, int height, int cell = 8) {
    std::vector<double> sum(static_cast<size_t>(cell * cell), 0.0);
    std::vector<int> count(sum.size(), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t i = static_cast<size_t>(y) * width + x;
            if (!mask.empty() && !(mask[i] > 0.0f)) continue;
            const size_t k = static_cast<size_t>((y % cell) * cell + x % cell);
            sum[k] += test[i] - (ref.empty() ? 0.0 : ref[i]);
            ++count[k];
        }
    Result r;
    std::vector<double> means;
    for (size_t k = 0; k < sum.size(); ++k)
        if (count[k] > 0) means.push_back(sum[k] / count[k]);
    r.positions = static_cast<int>(means.size());
    if (means.empty()) return r;
    const auto mm = std::minmax_element(means.begin(), means.end());
    r.range = *mm.second - *mm.first;
    double mean = 0.0;
    for (double m : means) mean += m;
    mean /= means.size();
    double var = 0.0;
    for (double m : means) var += (m - mean) * (m - mean);
    r.stddev = std::sqrt(var / means.size());
    return r;
}

}  // namespace cell_spread
