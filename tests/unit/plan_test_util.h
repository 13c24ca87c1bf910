// plan_test_util.h - what the frame-plan and kernel tests build their cases
// from, without GL: settings resolved as set_settings resolves them, and the
// analysed inputs of a viewport as inspect_textures would leave them.
#pragma once

#include "inputs.h"
#include "settings.h"

#include <ssao/ssao.h>

#include <doctest/doctest.h>

#include <string>

namespace plan_test {

// `in` resolved by resolve_settings; REQUIREs that it is accepted.
inline ssao_settings resolve(ssao_settings in) {
    in.size = sizeof in;
    ssao_settings out{};
    out.size = sizeof out;
    std::string why;
    REQUIRE(ssao_impl::resolve_settings(in, out, why) == SSAO_OK);
    return out;
}

// A request for the choices the plan depends on; every other field zero (its default).
inline ssao_settings request(ssao_method method, ssao_resolution res, ssao_blur blur, float strength = 0.0f,
                             ssao_debug_view view = SSAO_DEBUG_VIEW_NONE) {
    ssao_settings in{};
    in.size = sizeof in;
    in.method = method;
    in.resolution = res;
    in.blur = blur;
    in.strength = strength;
    in.debug_view = view;
    return in;
}

// A depth format as inspect_textures reports it.
inline ssao_impl::DepthFormat depth_format(int bits, bool is_float) {
    ssao_impl::DepthFormat d;
    d.bits = bits;
    d.is_float = is_float;
    return d;
}

// The inputs of a w x h viewport at (x, y) in textures that end at its top
// right corner; host_output 0 is the library's own output texture.
inline ssao_impl::AnalysedInputs viewport_inputs(int x, int y, int w, int h, uint32_t host_output = 0,
                                                 ssao_impl::DepthFormat depth = depth_format(32, true)) {
    ssao_impl::AnalysedInputs in;
    in.texture_width = x + w;
    in.texture_height = y + h;
    in.viewport[0] = x;
    in.viewport[1] = y;
    in.viewport[2] = w;
    in.viewport[3] = h;
    in.output_texture = host_output;
    in.depth = depth;
    return in;
}

}  // namespace plan_test
