// report.h - what the benchmark writes: bench.csv (every row), bench.md (the
// summary, both fronts, the preset targets and the scaling table), presets.txt
// (the presets the stated rule picks from the front), and the plot.
#pragma once

#include "measure.h"
#include "options.h"

#include <vector>

namespace bench {

// Creates o.out and checks that a file can be written there; throws
// std::runtime_error naming the folder. Run before measuring.
void prepare_output(const Options& o);

// Throws std::runtime_error naming a file that could not be written.
void write_report(const Options& o, const std::vector<Row>& rows);

}  // namespace bench
