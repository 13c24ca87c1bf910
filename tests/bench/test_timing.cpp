// The statistics the benchmark's CPU-time figures are made of.
#include "timing.h"

#include <doctest/doctest.h>

#include <chrono>
#include <cmath>
#include <thread>

TEST_SUITE("timing") {

TEST_CASE("quantile interpolates between order statistics, whatever the input order") {
    CHECK(bench::quantile({5, 1, 4, 2, 3}, 0.5) == doctest::Approx(3.0));
    CHECK(bench::quantile({5, 1, 4, 2, 3}, 0.1) == doctest::Approx(1.4));
    CHECK(bench::quantile({5, 1, 4, 2, 3}, 0.9) == doctest::Approx(4.6));
    CHECK(bench::quantile({4, 2}, 0.5) == doctest::Approx(3.0));
    CHECK(bench::quantile({7}, 0.9) == doctest::Approx(7.0));
    CHECK(std::isnan(bench::quantile({}, 0.5)));
    CHECK(bench::mean({1, 2, 6}) == doctest::Approx(3.0));
    CHECK(std::isnan(bench::mean({})));
}

TEST_CASE("over rounds: the median round, the lowest and the highest") {
    const bench::RoundStats a = bench::over_rounds({12.0, 10.0, 30.0});
    CHECK(a.rounds == 3);
    CHECK(a.median == doctest::Approx(12.0));  // one slow round does not move the median
    CHECK(a.min == doctest::Approx(10.0));
    CHECK(a.max == doctest::Approx(30.0));
    const bench::RoundStats b = bench::over_rounds({4.0, 2.0, 8.0, 6.0});
    CHECK(b.median == doctest::Approx(5.0));
    CHECK(b.min == doctest::Approx(2.0));
    CHECK(b.max == doctest::Approx(8.0));
    const bench::RoundStats none = bench::over_rounds({});
    CHECK(none.rounds == 0);
    CHECK(std::isnan(none.median));
    CHECK(std::isnan(none.min));
    CHECK(std::isnan(none.max));
}

TEST_CASE("process CPU time counts work done, not time waited") {
    const double c0 = bench::process_cpu_ms(), w0 = bench::wall_ms();
    std::this_thread::sleep_for(std::chrono::milliseconds(120));
    const double c1 = bench::process_cpu_ms(), w1 = bench::wall_ms();
    CHECK(w1 - w0 >= 110.0);
    CHECK(c1 - c0 < 40.0);  // asleep: next to no CPU time
    volatile double sink = 0;
    const double c2 = bench::process_cpu_ms();
    while (bench::process_cpu_ms() - c2 < 30.0) sink = sink + 1.0;
    CHECK(bench::process_cpu_ms() - c2 >= 30.0);
}

}  // TEST_SUITE
