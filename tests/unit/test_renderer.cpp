// test_renderer.cpp - which GL_RENDERER strings name a software rasteriser
// (plugin/renderer.h), the renderers whose plan copies the host's depth to
// skip the sky at the output.
#include "renderer.h"

#include <doctest/doctest.h>

#include <initializer_list>

using ssao_impl::is_software_rasterizer;

TEST_CASE("renderer: software rasterisers are told from GPUs by their GL_RENDERER string") {
    for (const char* software : {"llvmpipe (LLVM 15.0.6, 256 bits)", "LLVMPIPE", "softpipe",
                                 "Mesa X11 Software Rasterizer", "Google SwiftShader",
                                 "SwiftShader Device (Subzero)",
                                 "ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), "
                                 "SwiftShader driver-5.0.0)",
                                 "zink Vulkan 1.3(llvmpipe (LLVM 15.0.6, 256 bits) (MESA_LLVMPIPE))",
                                 "Microsoft Basic Render Driver", "GDI Generic"}) {
        CAPTURE(software);
        CHECK(is_software_rasterizer(software));
    }
    for (const char* gpu : {"NVIDIA H200/PCIe/SSE2", "NVIDIA GeForce RTX 4090/PCIe/SSE2",
                            "AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7, DRM 3.54, 6.5.0)",
                            "Mesa Intel(R) UHD Graphics 630 (CFL GT2)", "Apple M2", "ANGLE (NVIDIA, Vulkan 1.3)",
                            "virgl (llvm)", "", "pipe"}) {
        CAPTURE(gpu);
        CHECK_FALSE(is_software_rasterizer(gpu));
    }
    CHECK_FALSE(is_software_rasterizer(nullptr));
}
