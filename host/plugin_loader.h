// plugin_loader.h - loads libssao.so with dlopen and negotiates its API table,
// exactly as any engine would: one dlsym, nothing else from the library.
#pragma once

#include <ssao/ssao.h>

#include <string>
#include <vector>

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

    // Opens the first of search_order(explicit_path) that loads; on failure
    // `error` lists every place tried and why each failed.
    bool open_default(const std::string& explicit_path, std::string& error);

    const ssao_api& api() const { return api_; }
    // The file actually loaded (resolved by the dynamic loader), after open.
    const std::string& loaded_path() const { return loaded_; }

    // Where the plugin is looked for, in order:
    //   1. `explicit_path` (a --plugin flag), when not empty: that alone;
    //   2. else $SSAO_PLUGIN, when set: that alone;
    //   3. <executable dir>/../lib/libssao.so.1   (the installed layout);
    //   4. the build tree's libssao.so.1, only when the executable itself
    //      lies in that build tree (an uninstalled build tests its own library,
    //      never an older installed one);
    //   5. "libssao.so.1" through dlopen's own search (LD_LIBRARY_PATH,
    //      the executable's RUNPATH, ld.so.cache, /usr/lib...).
    static std::vector<std::string> search_order(const std::string& explicit_path = {});

    // The first of search_order() that exists as a file, else the bare soname
    // (for code that dlopens it itself, such as the tests).
    static std::string default_path();

private:
    void* handle_ = nullptr;
    ssao_api api_{};
    std::string loaded_;
};

}  // namespace plugin
