// The front the preset rule picks LOW from (bench/front.h).
#include "front.h"

#include <doctest/doctest.h>

#include <cmath>
#include <vector>

using bench::FrontPoint;
using bench::on_front;

TEST_SUITE_BEGIN("front");

TEST_CASE("a sweep configuration both faster and more accurate takes another off the front") {
    const std::vector<FrontPoint> p = {{0.20, 27.0, true}, {0.15, 27.5, true}, {0.30, 28.0, true}};
    CHECK_FALSE(on_front(p, 0));
    CHECK(on_front(p, 1));
    CHECK(on_front(p, 2));  // slower but more accurate: on it
}

TEST_CASE("a tie in both stays on the front, better in one of the two is enough to dominate") {
    const std::vector<FrontPoint> tie = {{0.2, 27.0, true}, {0.2, 27.0, true}};
    CHECK(on_front(tie, 0));
    CHECK(on_front(tie, 1));
    const std::vector<FrontPoint> faster = {{0.2, 27.0, true}, {0.19, 27.0, true}};
    CHECK_FALSE(on_front(faster, 0));
    const std::vector<FrontPoint> sharper = {{0.2, 27.0, true}, {0.2, 27.1, true}};
    CHECK_FALSE(on_front(sharper, 0));
}

TEST_CASE("a preset's row, timed a little faster than the sweep configuration it repeats, leaves it on the front") {
    // What a benchmark run showed: preset LOW (the same 4 x 8 at quarter
    // resolution as a sweep row) measured 0.146x against the sweep row's
    // 0.149x, which took the sweep row off the front and made the rule pick
    // a slower LOW.
    const std::vector<FrontPoint> p = {{0.149, 25.59, true}, {0.146, 25.59, false}, {0.172, 25.98, true}};
    CHECK(on_front(p, 0));
    CHECK(on_front(p, 1));  // the preset's own row may sit on the front; it takes nothing off it
    CHECK(on_front(p, 2));
}

TEST_CASE("a NaN accuracy (no error measured) takes nothing off the front") {
    const std::vector<FrontPoint> p = {{0.2, 27.0, true}, {0.1, std::nan(""), true}};
    CHECK(on_front(p, 0));
}

TEST_SUITE_END();
