// fuzz_flags.cpp - libFuzzer target: the command-line parsers on arbitrary
// argument lists (the input after its first byte, split at '\0' bytes, is
// argv[1..]). The first byte picks the parser:
//   even: ssao-host's cli::parse (host/flags' argv walk plus the camera checks);
//   odd:  the shared walker and number parsers themselves (flags::walk,
//         flags::number with and without inf, flags::integer, flags::vec3),
//         with flags shaped like those of ssao-reference, ssao-error and
//         ssao-bench, whose own parse() functions live in their main files.
// A parse either succeeds, asks for help/version, or fails with a sentence;
// a parsed value is inside the range its parser was given, every float flag
// the host takes is 0 or a normal float (a denormal reaches shaders as 0),
// --fov gives a projection scale float shaders can use, and --msaa is a
// power of two.
#include "cli.h"
#include "flags.h"

#include "camera_flags.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace {

void check(bool ok) {
    if (!ok) __builtin_trap();
}

void host_cli(const std::vector<std::string>& args, const std::vector<const char*>& argv) {
    cli::Options options;
    std::string error;
    const cli::ParseResult r = cli::parse(int(args.size()), argv.data(), options, error);
    check(r != cli::ParseResult::Error || !error.empty());
    check(r == cli::ParseResult::Error || error.empty());
    check(error.find('\n') == std::string::npos);
    if (r != cli::ParseResult::Run) return;
    auto normal_or_zero = [](const std::optional<float>& v) {
        if (v) check(std::isfinite(*v) && (*v == 0.0f || std::fabs(*v) >= std::numeric_limits<float>::min()));
    };
    for (const auto* v : {&options.radius, &options.bias, &options.depth_step_bias, &options.power, &options.strength,
                          &options.blur_sigma, &options.blur_tolerance, &options.thickness, &options.fade_start,
                          &options.fade_end, &options.radius_pixels, &options.cam.fov_deg, &options.cam.znear,
                          &options.cam.ortho_half_height})
        normal_or_zero(*v);
    for (const auto* v : {&options.radius, &options.power, &options.cam.fov_deg}) check(!*v || **v > 0.0f);
    if (options.cam.fov_deg)
        check(1.0 / std::tan(double(*options.cam.fov_deg) * 3.14159265358979323846 / 360.0) <=
              flags::kMaxProjectionElement * 1.0000001);
    check(options.msaa >= 0 && (options.msaa & (options.msaa - 1)) == 0);
}

void shared_walker(const std::vector<std::string>& args, const std::vector<const char*>& argv) {
    double finite = 1.0, maybe_inf = 1.0;
    long long whole = 1;
    glm::vec3 v(0.0f);
    bool sw = false;
    std::vector<std::string> positional;
    const flags::Valued valued = {
        {"--radius", [&](const std::string& f, const std::string& t) { finite = flags::number(f, t); }},
        {"--far", [&](const std::string& f, const std::string& t) { maybe_inf = flags::number(f, t, true); }},
        {"--width", [&](const std::string& f, const std::string& t) { whole = flags::integer(f, t, 1, 16384); }},
        {"--seed", [&](const std::string& f, const std::string& t) { whole = flags::integer(f, t, 0, 4294967295LL); }},
        {"--eye", [&](const std::string& f, const std::string& t) { v = flags::vec3(f, t); }},
        {"--out", [&](const std::string& f, const std::string& t) {
             if (t.empty()) flags::fail(f + " needs a folder name");
         }},
    };
    const flags::Switches switches = {{"--quick", [&] { sw = true; }}, {"--limit", [&] { sw = !sw; }}};
    try {
        flags::walk(int(args.size()), argv.data(), valued, switches,
                    [&](const std::string& a) { positional.push_back(a); });
    } catch (const flags::Error& e) {
        check(!e.message.empty());
        return;
    }
    check(std::isfinite(finite));
    check(!std::isnan(maybe_inf));
    check(whole >= 0 && whole <= 4294967295LL);
    check(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    const bool walker = data[0] & 1;
    std::vector<std::string> args{"ssao-tool"};
    std::string cur;
    for (size_t i = 1; i < size; ++i) {
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
    if (walker)
        shared_walker(args, argv);
    else
        host_cli(args, argv);
    return 0;
}
