#include "renderer.h"

#include <cctype>
#include <initializer_list>
#include <string>

namespace ssao_impl {

bool is_software_rasterizer(const char* renderer) {
    if (!renderer) return false;
    std::string lower(renderer);
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    // Mesa: "llvmpipe (LLVM 15.0.6, 256 bits)", "softpipe", "Software Rasterizer"
    // (swrast); Google's "SwiftShader ..."; Windows: "Microsoft Basic Render
    // Driver" (WARP), "GDI Generic".
    for (const char* name : {"llvmpipe", "softpipe", "software rasterizer", "swiftshader", "microsoft basic render",
                             "gdi generic"})
        if (lower.find(name) != std::string::npos) return true;
    return false;
}

}  // namespace ssao_impl
