// fuzz_flags.cpp - libFuzzer target: the command-line parsers (ssao-host's
// cli::parse, which walks argv with host/flags and checks the camera flags)
// on arbitrary argument lists: the input split at '\0' bytes is argv[1..].
// A parse either succeeds, asks for help, or fails with a sentence.
#include "cli.h"

#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> args{"ssao-host"};
    std::string cur;
    for (size_t i = 0; i < size; ++i) {
        if (data[i] == 0) {
            args.push_back(cur);
            cur.clear();
        } else {
            cur += char(data[i]);
        }
    }
    if (!cur.empty()) args.push_back(cur);
    if (args.size() > 64) return 0;
    std::vector<const char*> argv;
    for (const auto& a : args) argv.push_back(a.c_str());
    argv.push_back(nullptr);
    cli::Options options;
    std::string error;
    const cli::ParseResult r = cli::parse(int(args.size()), argv.data(), options, error);
    if (r == cli::ParseResult::Error && error.empty()) __builtin_trap();
    if (r != cli::ParseResult::Error && !error.empty()) __builtin_trap();
    return 0;
}
