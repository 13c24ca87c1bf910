// fuzz_exr.cpp - libFuzzer target: the EXR reader of ssao-error
// (refio::read_exr_channel and exr_has_channel, through tinyexr) on
// arbitrary bytes. ssao-error reads only EXR (its PNGs are outputs). A
// successful read must hand back width x height finite-size data.
#include "image_io.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

// The readers take a path: each input goes through one file in /dev/shm
// (or /tmp), rewritten per input.
const std::string& scratch() {
    static const std::string path = [] {
        const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
        return std::string(dir) + "/ssao_fuzz_exr_" + std::to_string(getpid()) + ".exr";
    }();
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    FILE* f = std::fopen(scratch().c_str(), "wb");
    if (!f) return 0;
    std::fwrite(data, 1, size, f);
    std::fclose(f);
    std::vector<float> px;
    int w = 0, h = 0;
    std::string error, used;
    const bool ok = refio::read_exr_channel(scratch(), {"Y", "R", "AO"}, px, w, h, error, &used);
    if (ok && (w <= 0 || h <= 0 || px.size() != size_t(w) * size_t(h) || used.empty())) __builtin_trap();
    if (!ok && error.empty()) __builtin_trap();
    (void)refio::exr_has_channel(scratch(), "A");
    return 0;
}
