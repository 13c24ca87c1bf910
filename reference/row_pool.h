// row_pool.h - the reference tools' worker pool: image rows handed out in order
// to a fixed number of threads, with the progress report on stderr (a redrawn
// bar on a terminal, a line per 10% otherwise). Per-pixel work must depend only
// on the pixel (its own seed), so results do not depend on the thread count.
#pragma once

#include <functional>

namespace row_pool {

// Runs row(y) for every y in [0, rows) on `threads` workers (0 = all cores).
// With `progress`, reports on stderr; `verb` names the work ("traced",
// "marched"). Returns the seconds until the last worker finished.
double run(int rows, int threads, bool progress, const char* verb, const std::function<void(int y)>& row);

}  // namespace row_pool
