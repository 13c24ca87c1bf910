// ao_checks.cpp - see ao_checks.h.
#include "ao_checks.h"

#include <cmath>
#include <sstream>

namespace aocheck {

std::string check_values(const std::vector<float>& values, int width, const std::vector<uint8_t>* use) {
    size_t used = 0, non_finite = 0, outside = 0, first_bad = 0;
    bool first_is_non_finite = false;
    for (size_t i = 0; i < values.size(); ++i) {
        if (use && (i >= use->size() || !(*use)[i])) continue;
        ++used;
        const float v = values[i];
        const bool bad_number = !std::isfinite(v);
        const bool bad_range = !bad_number && (v < -kAoTolerance || v > 1.0f + kAoTolerance);
        if (!bad_number && !bad_range) continue;
        if (non_finite + outside == 0) {
            first_bad = i;
            first_is_non_finite = bad_number;
        }
        non_finite += bad_number;
        outside += bad_range;
    }
    if (non_finite + outside == 0) return {};
    const size_t w = width > 0 ? size_t(width) : 1;
    std::ostringstream s;
    s << (non_finite + outside) << " of " << used << " compared pixels ";
    if (non_finite && outside) s << "are NaN, infinite or outside [0, 1] by more than " << kAoTolerance;
    else if (non_finite) s << "are NaN or infinite";
    else s << "are outside [0, 1] by more than " << kAoTolerance;
    s << " (the first";
    if (!first_is_non_finite) s << ", " << values[first_bad] << ",";
    s << " at x " << first_bad % w << ", y " << first_bad / w << ")";
    return s.str();
}

}  // namespace aocheck
