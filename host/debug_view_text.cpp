#include "debug_view_text.h"

namespace debug_view_text {

static_assert(sizeof kViews / sizeof kViews[0] == static_cast<size_t>(kViewCount), "kViewCount counts kViews");

namespace {

const Entry* find(ssao_debug_view view) {
    for (const Entry& e : kViews)
        if (e.view == view) return &e;
    return nullptr;
}

}  // namespace

const char* name(ssao_debug_view view) {
    const Entry* e = find(view);
    return e ? e->name : "?";
}

std::optional<ssao_debug_view> parse(const std::string& name) {
    for (const Entry& e : kViews)
        if (name == e.name) return e.view;
    return std::nullopt;
}

std::string choices() {
    std::string s;
    for (const Entry& e : kViews) s += std::string(s.empty() ? "" : "|") + e.name;
    return s;
}

bool is_rgb(ssao_debug_view view) {
    const Entry* e = find(view);
    return e && e->rgb;
}

ssao_debug_view next(ssao_debug_view view) {
    for (int i = 0; i < kViewCount; ++i)
        if (kViews[i].view == view) return kViews[(i + 1) % kViewCount].view;
    return kViews[0].view;
}

}  // namespace debug_view_text
