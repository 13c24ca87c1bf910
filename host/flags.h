// flags.h - the one command-line parser of all four tools (ssao-host,
// ssao-reference, ssao-error, ssao-bench): one argv walk (--flag value and
// --flag=value alike, switches, positional arguments, --help/-h, --version)
// and number parsers whose messages name the flag and the text they refused.
#pragma once

#include <glm/glm.hpp>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace flags {

// Thrown by every parser; the tools print `message` and exit with status 2.
struct Error {
    std::string message;
};
[[noreturn]] void fail(const std::string& message);
// `s` fit for a one-line message: control characters written \xNN, and at
// most `max_shown` bytes of it, then "..." (a URI can be megabytes long).
std::string printable(const std::string& s, size_t max_shown = std::string::npos);
// 's' for messages: printable(s) in quotes.
std::string quoted(const std::string& s);

// A finite number ("inf" too when allowed).
double number(const std::string& flag, const std::string& text, bool allow_inf = false);
// A whole number in [lo, hi].
long long integer(const std::string& flag, const std::string& text, long long lo, long long hi);
// "x,y,z".
glm::vec3 vec3(const std::string& flag, const std::string& text);
// Refuses `v` (parsed from `text`) when it is not 0 but smaller in magnitude
// than the smallest normal 32-bit float (1.17549e-38): as a float it becomes 0
// (which the plugin reads as "default") or a denormal, which shaders flush
// to 0. --radius 1e-45 and --power 1e-45 are refused here.
void check_normal_float(const std::string& flag, const std::string& text, double v);

using Valued = std::map<std::string, std::function<void(const std::string& flag, const std::string& value)>>;
using Switches = std::map<std::string, std::function<void()>>;
// Receives each argument that is not a flag, in order; may fail().
using Positional = std::function<void(const std::string& arg)>;

enum class Outcome {
    Run,      // every argument taken
    Help,     // --help or -h was given: print the tool's help, exit 0
    Version,  // --version was given: print version_line(tool), exit 0
    Error,    // refused (only from parse(), never from walk()): print the message, exit 2
};

// Walks argv[1..]: valued flags take the next argument or "=value", switches
// take none; anything else goes to `positional` (an empty Positional refuses
// it). --help wins over --version. An unknown flag is refused with the
// tool's closest flag suggested (suggestion()). Throws Error.
Outcome walk(int argc, const char* const* argv, const Valued& valued, const Switches& switches,
             const Positional& positional);
// The same, for tools whose one optional positional argument is a scene file.
Outcome walk(int argc, const char* const* argv, const Valued& valued, const Switches& switches,
             std::string& scene_path);

// A tool's parse: walk(), then `check` (rules across flags; may fail()). A
// refusal comes back as Outcome::Error with its message in `error`.
Outcome parse(int argc, const char* const* argv, const Valued& valued, const Switches& switches,
              const Positional& positional, std::string& error, const std::function<void()>& check = {});
Outcome parse(int argc, const char* const* argv, const Valued& valued, const Switches& switches,
              std::string& scene_path, std::string& error, const std::function<void()>& check = {});

// The rest of a tool's main() once parsed: --help prints help() and --version
// version_line(tool), exit 0; a refusal prints its line, exit 2; else run(),
// whose exception prints one line (print_error), exit 1.
int finish_main(const std::string& tool, Outcome parsed, const std::string& error,
                const std::function<std::string()>& help, const std::function<int()>& run);

// The flag of `known` that `unknown` most likely meant: the only one it is a
// prefix of, else the only one within 2 edits (insert, delete, replace a
// character); empty when none or several are that close.
std::string suggestion(const std::string& unknown, const std::vector<std::string>& known);

// Every tool's error line on stderr: "TOOL: error: MESSAGE\n", the message's
// line breaks made spaces so that it stays one line.
void print_error(const std::string& tool, const std::string& message);

// "TOOL 1.0.0 (C ABI 1.0)": the project version from CMake's project() and
// the interface version of include/ssao/ssao.h. Ends without a newline.
std::string version_line(const std::string& tool);

}  // namespace flags
