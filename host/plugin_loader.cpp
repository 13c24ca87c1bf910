#include "plugin_loader.h"

#include "input_file.h"
#include "locate.h"

#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>

// Set by host/CMakeLists.txt: relative names, the same in every install prefix.
#ifndef SSAO_PLUGIN_SONAME
#define SSAO_PLUGIN_SONAME "libssao.so.1"
#endif
#ifndef SSAO_BIN_TO_LIB
#define SSAO_BIN_TO_LIB "../lib"
#endif

namespace plugin {

Library::~Library() {
    if (handle_) dlclose(handle_);
}

bool Library::open(const std::string& path, std::string& error) {
    if (handle_) {
        dlclose(handle_);
        handle_ = nullptr;
    }
    // dlopen on a FIFO waits for a writer forever: a path (not a bare name
    // for the loader's search) must name a regular file.
    struct stat st {};
    if (path.find('/') != std::string::npos && ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
        error = "cannot load the SSAO plugin '" + path + "': not a regular file but " + input_file::kind_text(st.st_mode);
        return false;
    }
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
    // The file the dynamic loader picked, symlinks and ".." resolved.
    Dl_info info{};
    loaded_ = dladdr(reinterpret_cast<void*>(get_api), &info) && info.dli_fname ? info.dli_fname : path;
    char real[PATH_MAX];
    if (realpath(loaded_.c_str(), real)) loaded_ = real;
    return true;
}

bool Library::open_default(const std::string& explicit_path, std::string& error) {
    std::string tried;
    for (const std::string& candidate : search_order(explicit_path)) {
        std::string why;
        if (open(candidate, why)) return true;
        tried += (tried.empty() ? " " : "; ") + why;
    }
    error = "cannot load the SSAO plugin (give --plugin PATH or set SSAO_PLUGIN); tried:" + tried;
    return false;
}

std::vector<std::string> Library::search_order(const std::string& explicit_path) {
    if (!explicit_path.empty()) return {explicit_path};
    if (const char* env = std::getenv("SSAO_PLUGIN"); env && *env) return {env};
    std::vector<std::string> order;
    const std::string exe = locate::executable_dir();
    if (!exe.empty()) order.push_back(exe + "/" + SSAO_BIN_TO_LIB + "/" + SSAO_PLUGIN_SONAME);
    if (const std::string built = locate::build_tree_value("plugin"); !built.empty()) order.push_back(built);
    order.push_back(SSAO_PLUGIN_SONAME);
    return order;
}

std::string Library::default_path() {
    const std::vector<std::string> order = search_order();
    for (const std::string& candidate : order)
        if (candidate.find('/') != std::string::npos && access(candidate.c_str(), R_OK) == 0) return candidate;
    return order.back();
}

}  // namespace plugin
