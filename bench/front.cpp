#include "front.h"

namespace bench {

bool on_front(const std::vector<FrontPoint>& points, std::size_t i) {
    const FrontPoint& a = points[i];
    for (std::size_t j = 0; j < points.size(); ++j) {
        const FrontPoint& b = points[j];
        if (j == i || !b.sweep) continue;
        const bool no_worse = b.time <= a.time && b.accuracy >= a.accuracy;
        const bool better = b.time < a.time || b.accuracy > a.accuracy;
        if (no_worse && better) return false;
    }
    return true;
}

}  // namespace bench
