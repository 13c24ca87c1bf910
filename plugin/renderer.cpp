#include "renderer.h"

#include <cctype>
#include <cstddef>
#include <cstring>

namespace ssao_impl {

namespace {

// `needle` (lower case) in `hay`, ignoring the case of `hay`.
bool contains_lower(const char* hay, const char* needle) {
    const size_t n = std::strlen(needle);
    for (; *hay; ++hay) {
        size_t i = 0;
        while (i < n && hay[i] && std::tolower(static_cast<unsigned char>(hay[i])) == needle[i]) ++i;
        if (i == n) return true;
    }
    return false;
}

}  // namespace

bool is_software_rasterizer(const char* renderer) {
    if (!renderer) return false;
    // Mesa: "llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Software Rasterizer"
    // (swrast); Google's "SwiftShader ..."; Windows: "Microsoft Basic Render
    // Driver" (WARP), "GDI Generic".
    const char* const names[] = {"llvmpipe", "softpipe", "software rasterizer", "swiftshader",
                                 "microsoft basic render", "gdi generic"};
    for (const char* name : names)
        if (contains_lower(renderer, name)) return true;
    return false;
}

}  // namespace ssao_impl
