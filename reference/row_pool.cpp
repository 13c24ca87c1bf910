#include "row_pool.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

namespace row_pool {

double run(int rows, int threads, bool progress, const char* verb, const std::function<void(int y)>& row) {
    if (rows <= 0) return 0.0;
    const auto start = std::chrono::steady_clock::now();
    std::atomic<int> next_row{0}, rows_done{0};
    std::atomic<int64_t> finish_ns{0};  // when the last worker finished (the progress report may lag)
    auto worker = [&]() {
        for (;;) {
            const int y = next_row.fetch_add(1);
            if (y >= rows) break;
            row(y);
            rows_done.fetch_add(1);
        }
        const int64_t now =
            std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start).count();
        int64_t prev = finish_ns.load();
        while (now > prev && !finish_ns.compare_exchange_weak(prev, now)) {
        }
    };
    int n = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
    n = std::min(n, rows);
    std::vector<std::thread> pool;
    for (int i = 0; i < n; ++i) pool.emplace_back(worker);
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    if (progress && !isatty(fileno(stderr))) {
        // Not a terminal (a log file, CI): a line per 10% instead of a redrawn bar.
        int reported = 0;
        for (;;) {
            const int done = rows_done.load();
            const int tenth = int(int64_t(done) * 10 / rows);
            if (tenth > reported) {
                reported = tenth;
                std::fprintf(stderr, "%s %3d%% of the rows, %.1f s\n", verb, tenth * 10, elapsed());
                std::fflush(stderr);
            }
            if (done >= rows) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    } else if (progress) {
        for (;;) {
            const int done = rows_done.load();
            const double secs = elapsed();
            const int width = 40;
            const int filled = int(double(done) / rows * width);
            std::fprintf(stderr, "\r[%s%s] %3d%%  %.1f s", std::string(size_t(filled), '#').c_str(),
                         std::string(size_t(width - filled), ' ').c_str(), int(100.0 * done / rows), secs);
            if (done > 0 && done < rows) std::fprintf(stderr, ", about %.0f s left ", secs / done * (rows - done));
            std::fflush(stderr);
            if (done >= rows) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(250));
        }
        std::fprintf(stderr, "\n");
    }
    for (auto& t : pool) t.join();
    return double(finish_ns.load()) * 1e-9;
}

}  // namespace row_pool
