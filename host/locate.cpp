#include "locate.h"

#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <fstream>

// Set by host/CMakeLists.txt: a relative path, the same in every install prefix.
#ifndef SSAO_BIN_TO_DATA
#define SSAO_BIN_TO_DATA "../share/ssao"
#endif

namespace locate {

namespace {

bool is_dir(const std::string& p) {
    struct stat st;
    return !p.empty() && stat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// The real path of `p`, or "" (so that a symlinked build directory compares equal).
std::string real(const std::string& p) {
    char buf[PATH_MAX];
    return realpath(p.c_str(), buf) ? std::string(buf) : std::string();
}

// The bundled data is there when the default scene is.
bool holds_data(const std::string& dir) {
    struct stat st;
    return is_dir(dir) && stat((dir + "/models/spot-on-ground.glb").c_str(), &st) == 0;
}

}  // namespace

std::string executable_dir() {
    char self[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0) return {};
    self[n] = '\0';
    std::string path(self);
    return path.substr(0, path.find_last_of('/'));
}

namespace {

// The build tree file in the executable's directory or the nearest one above, or "".
std::string build_tree_file() {
    std::string dir = executable_dir();
    while (!dir.empty()) {
        const std::string candidate = dir + "/" + kBuildTreeFile;
        struct stat st;
        if (stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode)) return candidate;
        dir = dir.substr(0, dir.find_last_of('/'));
    }
    return {};
}

}  // namespace

bool in_build_tree() { return !build_tree_file().empty(); }

std::string build_tree_value(const std::string& key) {
    const std::string file = build_tree_file();
    if (file.empty()) return {};
    std::ifstream in(file);
    const std::string prefix = key + "=";
    for (std::string line; std::getline(in, line);)
        if (line.rfind(prefix, 0) == 0) return line.substr(prefix.size());
    return {};
}

std::string data_dir() {
    if (const char* env = std::getenv("SSAO_DATA_DIR"); env && *env) return env;
    const std::string exe = executable_dir();
    if (!exe.empty()) {
        const std::string installed = real(exe + "/" + SSAO_BIN_TO_DATA);
        if (holds_data(installed)) return installed;
    }
    if (const std::string source = build_tree_value("data"); holds_data(source)) return source;
    return {};
}

std::string bundled(const std::string& relative) {
    const std::string dir = data_dir();
    return dir.empty() ? relative : dir + "/" + relative;
}

}  // namespace locate
