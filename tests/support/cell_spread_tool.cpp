// ssao-cell-spread - the fixed-pattern figure (cell_spread.h) of an AO image
// against the ray-traced reference, for ssao-host's ao.exr (or the depth-only
// limit's limit_ao.exr) and ssao-reference's reference_ao.exr.
//   ssao-cell-spread TEST.exr REFERENCE.exr   prints "range R stddev S positions N"
#include "cell_spread.h"

#include <image_io.h>

#include <cstdio>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: ssao-cell-spread TEST.exr REFERENCE.exr\n");
        return 2;
    }
    std::vector<float> test, ref, coverage;
    int tw = 0, th = 0, rw = 0, rh = 0, cw = 0, ch = 0;
    std::string error;
    if (!refio::read_exr_channel(argv[1], {"Y", "R"}, test, tw, th, error) ||
        !refio::read_exr_channel(argv[2], {"Y", "R"}, ref, rw, rh, error)) {
        std::fprintf(stderr, "ssao-cell-spread: %s\n", error.c_str());
        return 1;
    }
    if (tw != rw || th != rh) {
        std::fprintf(stderr, "ssao-cell-spread: the images differ in size (%dx%d, %dx%d)\n", tw, th, rw, rh);
        return 1;
    }
    // The reference's coverage (A: 0 for sky); without it every pixel counts.
    if (refio::exr_has_channel(argv[2], "A") &&
        !refio::read_exr_channel(argv[2], {"A"}, coverage, cw, ch, error)) {
        std::fprintf(stderr, "ssao-cell-spread: %s\n", error.c_str());
        return 1;
    }
    const cell_spread::Result r = cell_spread::measure(test, ref, coverage, tw, th);
    std::printf("range %.5f stddev %.5f positions %d\n", r.range, r.stddev, r.positions);
    return 0;
}
