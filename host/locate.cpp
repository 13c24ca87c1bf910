#include "locate.h"

#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>

// Set by host/CMakeLists.txt.
#ifndef SSAO_BUILD_DIR
#define SSAO_BUILD_DIR ""
#endif
#ifndef SSAO_SOURCE_DATA_DIR
#define SSAO_SOURCE_DATA_DIR ""
#endif
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

bool in_build_tree() {
    const std::string build = real(SSAO_BUILD_DIR);
    const std::string exe = executable_dir();
    if (build.empty() || exe.empty()) return false;
    return exe == build || exe.rfind(build + "/", 0) == 0;
}

std::string data_dir() {
    if (const char* env = std::getenv("SSAO_DATA_DIR"); env && *env) return env;
    const std::string exe = executable_dir();
    if (!exe.empty()) {
        const std::string installed = real(exe + "/" + SSAO_BIN_TO_DATA);
        if (holds_data(installed)) return installed;
    }
    if (in_build_tree() && holds_data(SSAO_SOURCE_DATA_DIR)) return SSAO_SOURCE_DATA_DIR;
    return {};
}

std::string bundled(const std::string& relative) {
    const std::string dir = data_dir();
    return dir.empty() ? relative : dir + "/" + relative;
}

}  // namespace locate
