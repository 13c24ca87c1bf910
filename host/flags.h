// flags.h - the command-line plumbing ssao-host and ssao-reference share: one
// argv walk (--flag value, --flag=value, switches, one positional scene) and
// number parsers whose messages name the flag and the text they refused.
#pragma once

#include "camera.h"

#include <glm/glm.hpp>

#include <functional>
#include <map>
#include <string>

namespace flags {

// Thrown by every parser; the tools print `message` and exit non-zero.
struct Error {
    std::string message;
};
[[noreturn]] void fail(const std::string& message);
std::string quoted(const std::string& s);

// A finite number ("inf" too when allowed).
double number(const std::string& flag, const std::string& text, bool allow_inf = false);
// A whole number in [lo, hi].
long long integer(const std::string& flag, const std::string& text, long long lo, long long hi);
// "x,y,z".
glm::vec3 vec3(const std::string& flag, const std::string& text);

using Valued = std::map<std::string, std::function<void(const std::string& flag, const std::string& value)>>;
using Switches = std::map<std::string, std::function<void()>>;

// Walks argv[1..]: valued flags take the next argument or "=value", switches
// take none, "--help"/"-h" are noted, anything else is the (single) scene
// path. Returns whether help was asked for. Throws Error.
bool walk(int argc, const char* const* argv, const Valued& valued, const Switches& switches, std::string& scene_path);

// The camera flags' combinations that make no camera. Throws Error.
void check_camera(const camera::Overrides& o);

}  // namespace flags
