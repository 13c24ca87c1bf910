// plugin_loader.h - loads libssao.so with dlopen and negotiates its API table,
// exactly as any engine would: one dlsym, nothing else from the library.
#pragma once

#include <ssao/ssao.h>

#include <string>

namespace plugin {

class Library {
public:
    Library() = default;
    ~Library();
    Library(const Library&) = delete;
    Library& operator=(const Library&) = delete;

    // Opens `path` (a file path or a name dlopen searches for) and fills api().
    // Returns false with `error` set on a missing library, a missing symbol or a
    // refused version.
    bool open(const std::string& path, std::string& error);
    const ssao_api& api() const { return api_; }

    // Where the plugin normally is: $SSAO_PLUGIN, else libssao.so next to the
    // running executable, else the build tree's plugin/ directory.
    static std::string default_path();

private:
    void* handle_ = nullptr;
    ssao_api api_{};
};

}  // namespace plugin
