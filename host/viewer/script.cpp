#include "script.h"

#include "input_file.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <sstream>

namespace viewer {

namespace {

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

// A whole number in [lo, hi], or false.
bool whole(const std::string& text, long lo, long hi, long& out) {
    if (text.empty()) return false;
    errno = 0;
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (errno != 0 || *end != '\0' || v < lo || v > hi) return false;
    out = v;
    return true;
}

const struct {
    const char* name;
    int key;
} kNamedKeys[] = {
    {"SPACE", GLFW_KEY_SPACE}, {"ESCAPE", GLFW_KEY_ESCAPE}, {"ESC", GLFW_KEY_ESCAPE}, {"TAB", GLFW_KEY_TAB},
    {"UP", GLFW_KEY_UP},       {"DOWN", GLFW_KEY_DOWN},     {"LEFT", GLFW_KEY_LEFT},  {"RIGHT", GLFW_KEY_RIGHT},
};

constexpr long kMaxFrame = 100000000;   // about three weeks at 60 frames a second
constexpr long kMaxSize = 16384;

}  // namespace

int key_from_name(const std::string& name) {
    const std::string n = upper(name);
    if (n.size() == 1 && n[0] >= 'A' && n[0] <= 'Z') return GLFW_KEY_A + (n[0] - 'A');
    if (n.size() == 1 && n[0] >= '0' && n[0] <= '9') return GLFW_KEY_0 + (n[0] - '0');
    long f = 0;
    if (n.size() >= 2 && n[0] == 'F' && whole(n.substr(1), 1, 12, f)) return GLFW_KEY_F1 + static_cast<int>(f - 1);
    for (const auto& k : kNamedKeys)
        if (n == k.name) return k.key;
    return GLFW_KEY_UNKNOWN;
}

std::string key_name(int key) {
    if (key >= GLFW_KEY_A && key <= GLFW_KEY_Z) return std::string(1, static_cast<char>('A' + (key - GLFW_KEY_A)));
    if (key >= GLFW_KEY_0 && key <= GLFW_KEY_9) return std::string(1, static_cast<char>('0' + (key - GLFW_KEY_0)));
    if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12) return "F" + std::to_string(key - GLFW_KEY_F1 + 1);
    for (const auto& k : kNamedKeys)
        if (key == k.key) return k.name;
    return "?";
}

bool parse_script(const std::string& text, std::vector<ScriptEvent>& events, std::string& error) {
    std::vector<ScriptEvent> out;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        const size_t hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string s; words >> s;) w.push_back(s);
        if (w.empty()) continue;
        const std::string where = std::to_string(number) + ": ";
        ScriptEvent e;
        if (!whole(w[0], 0, kMaxFrame, e.frame)) {
            error = where + "'" + w[0] + "' is not a frame number (0.." + std::to_string(kMaxFrame) + ")";
            return false;
        }
        const std::string verb = w.size() > 1 ? upper(w[1]) : "";
        auto key_at = [&](size_t i, int& key) {
            key = key_from_name(w[i]);
            if (key != GLFW_KEY_UNKNOWN) return true;
            error = where + "unknown key '" + w[i] + "' (A..Z, 0..9, F1..F12, SPACE, ESCAPE, TAB, UP, DOWN, LEFT, RIGHT)";
            return false;
        };
        auto arity = [&](size_t n, const char* form) {
            if (w.size() == n) return true;
            error = where + "expected '" + form + "'";
            return false;
        };
        if (verb == "RESIZE") {
            if (!arity(4, "FRAME resize WIDTH HEIGHT")) return false;
            long width = 0, height = 0;
            if (!whole(w[2], 1, kMaxSize, width) || !whole(w[3], 1, kMaxSize, height)) {
                error = where + "resize needs a width and a height in 1.." + std::to_string(kMaxSize);
                return false;
            }
            e.kind = ScriptEvent::Kind::Resize;
            e.width = static_cast<int>(width);
            e.height = static_cast<int>(height);
            out.push_back(e);
        } else if (verb == "MEMORY" || verb == "QUIT") {
            if (!arity(2, verb == "MEMORY" ? "FRAME memory" : "FRAME quit")) return false;
            e.kind = verb == "MEMORY" ? ScriptEvent::Kind::Memory : ScriptEvent::Kind::Quit;
            out.push_back(e);
        } else if (verb == "HOLD") {
            long frames = 0;
            if (!arity(4, "FRAME hold KEY FRAMES") || !key_at(2, e.key)) return false;
            if (!whole(w[3], 1, kMaxFrame, frames)) {
                error = where + "hold needs a number of frames in 1.." + std::to_string(kMaxFrame);
                return false;
            }
            out.push_back(e);
            e.kind = ScriptEvent::Kind::Release;
            e.frame += frames;
            out.push_back(e);
        } else {
            if (!arity(2, "FRAME KEY") || !key_at(1, e.key)) return false;
            out.push_back(e);
            e.kind = ScriptEvent::Kind::Release;
            e.frame += 1;
            out.push_back(e);
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const ScriptEvent& a, const ScriptEvent& b) { return a.frame < b.frame; });
    events = std::move(out);
    return true;
}

bool load_script(const std::string& path, std::vector<ScriptEvent>& events, std::string& error) {
    // Through the tools' one reader: a FIFO or a device is refused, not read.
    constexpr uint64_t kMaxScriptBytes = uint64_t(16) << 20;
    std::vector<unsigned char> bytes;
    std::string why;
    if (!input_file::read(path, kMaxScriptBytes, bytes, why)) {
        if (!why.empty() && why.back() == '.') why.pop_back();
        error = "cannot read the script: " + why;
        return false;
    }
    if (!parse_script(std::string(bytes.begin(), bytes.end()), events, error)) {
        error = "script " + path + ":" + error;
        return false;
    }
    return true;
}

}  // namespace viewer
