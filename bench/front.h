// front.h - the accuracy-versus-time front the preset rule picks LOW from and
// the plot draws: the configurations no other is both faster and more
// accurate than.
#pragma once

#include <cstddef>
#include <vector>

namespace bench {

struct FrontPoint {
    double time = 0;      // x textbook pass (CPU time)
    double accuracy = 0;  // mean PSNR, dB
    bool sweep = false;   // a sweep configuration; a preset's row repeats one and does not count against it
};

// Whether points[i] is on the front: no other sweep configuration is at least
// as fast and at least as accurate, and strictly better in one of the two.
bool on_front(const std::vector<FrontPoint>& points, std::size_t i);

}  // namespace bench
