// renderer.h - what the library reads from the GL_RENDERER string. No GL
// here: create_context passes the string in, and tests/unit/test_renderer.cpp
// passes known renderers' strings.
#pragma once

namespace ssao_impl {

// Whether `renderer` (glGetString(GL_RENDERER); null reads as a GPU) names
// a software rasteriser: Mesa's llvmpipe, softpipe and swrast, SwiftShader,
// Microsoft's WARP and GDI renderers. Such a renderer runs a batch of pixels
// in SIMD lanes and runs every instruction even when all of the batch's lanes
// are masked off; a GPU's SIMD group skips code no lane of it takes.
bool is_software_rasterizer(const char* renderer);

}  // namespace ssao_impl
