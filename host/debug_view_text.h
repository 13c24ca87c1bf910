// debug_view_text.h - the debug views (ssao_settings.debug_view) by name: one
// table for ssao-host's --debug-view flag and its --help text, ssao-viewer's
// cycling key and its overlay, and the tests. The order is the cycle's order.
#pragma once

#include <ssao/ssao.h>

#include <optional>
#include <string>

namespace debug_view_text {

struct Entry {
    ssao_debug_view view;
    const char* name;  // as --debug-view spells it
    bool rgb;          // the picture is the RGB normal image (else grey, one channel)
};

constexpr Entry kViews[] = {
    {SSAO_DEBUG_VIEW_NONE, "none", false},
    {SSAO_DEBUG_VIEW_NORMALS, "normals", true},
    {SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS, "reconstructed-normals", true},
    {SSAO_DEBUG_VIEW_RAW_AO, "raw-ao", false},
    {SSAO_DEBUG_VIEW_BLUR_WEIGHTS, "blur-weights", false},
};
constexpr int kViewCount = 5;

// "none", "normals", ... ("?" for a value not in the table).
const char* name(ssao_debug_view view);
// The view of a name, or nothing.
std::optional<ssao_debug_view> parse(const std::string& name);
// "none|normals|reconstructed-normals|raw-ao|blur-weights".
std::string choices();
// Whether the view's picture has three channels (the normal views).
bool is_rgb(ssao_debug_view view);
// The view after `view` in the table's order, wrapping to none.
ssao_debug_view next(ssao_debug_view view);

}  // namespace debug_view_text
