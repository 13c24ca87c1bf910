// timing.h - the clocks and statistics the benchmark times with. On llvmpipe
// the CPU is the device and other processes share it, so the figure the
// targets use is this process's CPU time per frame (CLOCK_PROCESS_CPUTIME_ID
// around submission + glFinish): time spent by other processes on the same
// cores does not count in it, where it does in the wall clock and in the GPU
// timers. Configurations are interleaved over rounds (each round times every
// configuration once, in turn) so a slow spell of the machine hits all of
// them alike; a configuration's figure is the median over rounds, its spread
// the lowest and highest round.
#pragma once

#include <vector>

namespace bench {

// This process's CPU time so far (all its threads), in ms.
double process_cpu_ms();
// Monotonic wall clock, in ms.
double wall_ms();

// The q-quantile (0..1) of v, linear between order statistics; NaN when empty.
double quantile(std::vector<double> v, double q);
// The mean of v; NaN when empty.
double mean(const std::vector<double>& v);

// A configuration's per-frame figure over rounds: each round contributes one
// value (its frames' mean); the median of those and the lowest and highest.
struct RoundStats {
    double median = 0, min = 0, max = 0;  // NaN when there are no rounds
    int rounds = 0;
};
RoundStats over_rounds(const std::vector<double>& per_round);

}  // namespace bench
