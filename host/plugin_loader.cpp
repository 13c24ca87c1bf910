#include "plugin_loader.h"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>

#ifndef SSAO_PLUGIN_BUILD_PATH
#define SSAO_PLUGIN_BUILD_PATH "libssao.so"
#endif

namespace plugin {

Library::~Library() {
    if (handle_) dlclose(handle_);
}

bool Library::open(const std::string& path, std::string& error) {
    handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) {
        const char* why = dlerror();
        error = "cannot load the SSAO plugin '" + path + "': " + (why ? why : "unknown reason");
        return false;
    }
    auto get_api = reinterpret_cast<PFN_ssao_get_api>(dlsym(handle_, "ssao_get_api"));
    if (!get_api) {
        error = "'" + path + "' does not export ssao_get_api; is it the SSAO plugin?";
        return false;
    }
    api_ = ssao_api{};
    api_.size = sizeof(ssao_api);
    const ssao_status status = get_api(SSAO_API_VERSION, &api_);
    if (status != SSAO_OK) {
        error = "the SSAO plugin '" + path + "' refused interface version 1.0 (status " +
                std::to_string(static_cast<int>(status)) + ")";
        return false;
    }
    return true;
}

std::string Library::default_path() {
    if (const char* env = std::getenv("SSAO_PLUGIN")) return env;
    char self[PATH_MAX];
    const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n > 0) {
        self[n] = '\0';
        std::string dir(self);
        dir = dir.substr(0, dir.find_last_of('/'));
        const std::string beside = dir + "/libssao.so";
        if (access(beside.c_str(), R_OK) == 0) return beside;
    }
    return SSAO_PLUGIN_BUILD_PATH;
}

}  // namespace plugin
