#include "flags.h"

#include <ssao/ssao.h>
#include <ssao_project_version.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace flags {

// Printable however the message was put together: a value echoed raw after
// it parsed (strtod skips leading whitespace, a newline included) must not
// break the one-line error.
void fail(const std::string& message) { throw Error{printable(message)}; }

std::string quoted(const std::string& s) {
    return "'" + printable(s) + "'";
}

std::string printable(const std::string& s, size_t max_shown) {
    std::string out;
    for (size_t i = 0; i < s.size() && i < max_shown; ++i) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c < 0x20 || c == 0x7f) {
            static const char hex[] = "0123456789abcdef";
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
        } else {
            out += static_cast<char>(c);
        }
    }
    if (s.size() > max_shown) out += "...";
    return out;
}

double number(const std::string& flag, const std::string& text, bool allow_inf) {
    if (allow_inf && (text == "inf" || text == "infinity" || text == "+inf"))
        return std::numeric_limits<double>::infinity();
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(begin, &end);
    if (text.empty() || end == begin || *end != '\0' || errno == ERANGE || !std::isfinite(v))
        fail(flag + " expects a finite number" + std::string(allow_inf ? " or 'inf'" : "") + ", got " + quoted(text));
    return v;
}

long long integer(const std::string& flag, const std::string& text, long long lo, long long hi) {
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(begin, &end, 10);
    if (text.empty() || end == begin || *end != '\0' || errno == ERANGE)
        fail(flag + " expects a whole number, got " + quoted(text));
    if (v < lo || v > hi)
        fail(flag + " " + text + " is out of range " + std::to_string(lo) + ".." + std::to_string(hi));
    return v;
}

glm::vec3 vec3(const std::string& flag, const std::string& text) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(text);
    while (std::getline(in, part, ',')) parts.push_back(part);
    if (parts.size() != 3 || (!text.empty() && text.back() == ','))
        fail(flag + " expects three comma-separated numbers x,y,z, got " + quoted(text));
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) {
        const double d = number(flag, parts[static_cast<size_t>(i)]);
        // A finite double beyond float's range would become inf (and the
        // conversion itself is undefined behaviour): refused like inf.
        if (std::abs(d) > static_cast<double>(std::numeric_limits<float>::max()))
            fail(flag + " expects numbers within +-3.4e38, got " + quoted(text));
        v[i] = static_cast<float>(d);
    }
    return v;
}

void check_normal_float(const std::string& flag, const std::string& text, double v) {
    const double smallest = static_cast<double>(std::numeric_limits<float>::min());
    if (v != 0.0 && std::abs(v) < smallest) {
        std::ostringstream s;
        s << smallest;
        fail(flag + " " + text + " is below the smallest normal 32-bit float (" + s.str() +
             "); shaders would read it as 0");
    }
}

namespace {

size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> row(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        size_t diagonal = row[0];
        row[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diagonal = above;
        }
    }
    return row[b.size()];
}

}  // namespace

std::string suggestion(const std::string& unknown, const std::vector<std::string>& known) {
    std::vector<std::string> prefixed;
    for (const auto& k : known)
        if (k.size() > unknown.size() && k.compare(0, unknown.size(), unknown) == 0) prefixed.push_back(k);
    // "--" or "-" alone is a prefix of everything: not a guess.
    // Several: the shortest when the others extend it (--rad: --radius, not --radius-pixels).
    std::sort(prefixed.begin(), prefixed.end(), [](const std::string& a, const std::string& b) { return a.size() < b.size(); });
    const bool nested = std::all_of(prefixed.begin(), prefixed.end(),
                                    [&](const std::string& k) { return !prefixed.empty() && k.rfind(prefixed[0], 0) == 0; });
    if (!prefixed.empty() && nested && unknown.size() > 2) return prefixed[0];
    size_t best = 2;  // within two edits, as the docs promise
    std::vector<std::string> closest;
    for (const auto& k : known) {
        const size_t d = edit_distance(unknown, k);
        if (d > best) continue;
        if (d < best || closest.empty()) {
            best = d;
            closest = {k};
        } else if (d == best) {
            closest.push_back(k);
        }
    }
    return closest.size() == 1 ? closest[0] : std::string();
}

void print_error(const std::string& tool, const std::string& message) {
    std::string m = message;
    for (char& c : m)
        if (c == '\n' || c == '\r') c = ' ';
    while (!m.empty() && m.back() == ' ') m.pop_back();
    std::fprintf(stderr, "%s: error: %s\n", tool.c_str(), m.c_str());
}

Outcome walk(int argc, const char* const* argv, const Valued& valued, const Switches& switches,
             const Positional& positional) {
    bool help = false, version = false;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            help = true;
            continue;
        }
        if (arg == "--version") {
            version = true;
            continue;
        }
        if (arg.size() > 1 && arg[0] == '-') {
            std::string value;
            bool has_value = false;
            const size_t eq = arg.find('=');
            if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
                value = arg.substr(eq + 1);
                arg = arg.substr(0, eq);
                has_value = true;
            }
            if (arg == "--help" || arg == "--version") fail(arg + " takes no value");
            if (auto s = switches.find(arg); s != switches.end()) {
                if (has_value) fail(arg + " takes no value");
                s->second();
                continue;
            }
            auto h = valued.find(arg);
            if (h == valued.end()) {
                std::vector<std::string> known = {"--help", "--version"};
                for (const auto& v : valued) known.push_back(v.first);
                for (const auto& w : switches) known.push_back(w.first);
                const std::string guess = suggestion(arg, known);
                fail("unknown flag " + quoted(arg) + (guess.empty() ? "" : "; did you mean " + guess + "?") +
                     " (see --help)");
            }
            if (!has_value) {
                if (i + 1 >= argc) fail(arg + " needs a value");
                // "--out --gl33" forgot the value: the next flag is not taken as
                // one (a negative number has one dash; --flag=--x still passes).
                const std::string next = argv[i + 1];
                if (next.size() > 2 && next.rfind("--", 0) == 0) fail(arg + " needs a value, got the flag " + quoted(next));
                value = argv[++i];
            }
            h->second(arg, value);
            continue;
        }
        if (!positional) fail("unexpected argument " + quoted(arg) + " (see --help)");
        positional(arg);
    }
    return help ? Outcome::Help : version ? Outcome::Version : Outcome::Run;
}

namespace {

// Takes the one positional argument into scene_path; refuses a second.
Positional one_scene_file(std::string& scene_path) {
    return [&scene_path, seen = false](const std::string& arg) mutable {
        if (seen) fail("more than one scene file given: " + quoted(scene_path) + " and " + quoted(arg));
        // Empty, it would read as "no scene" and render the bundled one.
        if (arg.empty()) fail("the scene file argument is empty");
        scene_path = arg;
        seen = true;
    };
}

}  // namespace

Outcome walk(int argc, const char* const* argv, const Valued& valued, const Switches& switches,
             std::string& scene_path) {
    return walk(argc, argv, valued, switches, one_scene_file(scene_path));
}

Outcome parse(int argc, const char* const* argv, const Valued& valued, const Switches& switches,
              const Positional& positional, std::string& error, const std::function<void()>& check) {
    try {
        const Outcome outcome = walk(argc, argv, valued, switches, positional);
        if (outcome == Outcome::Run && check) check();
        return outcome;
    } catch (const Error& e) {
        error = e.message;
        return Outcome::Error;
    }
}

Outcome parse(int argc, const char* const* argv, const Valued& valued, const Switches& switches,
              std::string& scene_path, std::string& error, const std::function<void()>& check) {
    return parse(argc, argv, valued, switches, one_scene_file(scene_path), error, check);
}

int finish_main(const std::string& tool, Outcome parsed, const std::string& error,
                const std::function<std::string()>& help, const std::function<int()>& run) {
    switch (parsed) {
        case Outcome::Error: print_error(tool, error); return 2;
        case Outcome::Help: std::fputs(help().c_str(), stdout); return 0;
        case Outcome::Version: std::printf("%s\n", version_line(tool).c_str()); return 0;
        case Outcome::Run: break;
    }
    try {
        return run();
    } catch (const std::exception& e) {
        std::fflush(stdout);  // what the run printed comes before its error line
        print_error(tool, e.what());
        return 1;
    }
}

std::string version_line(const std::string& tool) {
    return tool + " " + SSAO_PROJECT_VERSION + " (C ABI " + std::to_string(SSAO_VERSION_MAJOR(SSAO_API_VERSION)) + "." +
           std::to_string(SSAO_VERSION_MINOR(SSAO_API_VERSION)) + ")";
}

}  // namespace flags
