#include "timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>

namespace bench {

double process_cpu_ms() {
    timespec ts{};
    if (clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts) != 0) return NAN;
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

double wall_ms() {
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const double pos = std::clamp(q, 0.0, 1.0) * static_cast<double>(v.size() - 1);
    const size_t i = static_cast<size_t>(pos);
    const double f = pos - static_cast<double>(i);
    return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v[i];
}

double mean(const std::vector<double>& v) {
    if (v.empty()) return NAN;
    double s = 0;
    for (double x : v) s += x;
    return s / static_cast<double>(v.size());
}

RoundStats over_rounds(const std::vector<double>& per_round) {
    RoundStats r;
    r.rounds = static_cast<int>(per_round.size());
    if (per_round.empty()) {
        r.median = r.min = r.max = NAN;
        return r;
    }
    r.median = quantile(per_round, 0.5);
    r.min = *std::min_element(per_round.begin(), per_round.end());
    r.max = *std::max_element(per_round.begin(), per_round.end());
    return r;
}

}  // namespace bench
