// scene_limits.cpp - see scene_limits.h.
#include "scene_limits.h"

namespace scene {

int json_nesting_depth(const unsigned char* text, size_t size, int limit) {
    int depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (size_t i = 0; i < size; ++i) {
        const unsigned char c = text[i];
        if (in_string) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') in_string = false;
            continue;
        }
        if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > deepest) deepest = depth;
            if (deepest > limit) return limit + 1;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return deepest;
}

uint64_t triangles_of(int mode, uint64_t count) {
    constexpr int kTriangles = 4;  // TINYGLTF_MODE_TRIANGLES; strips (5) and fans (6) otherwise
    if (mode == kTriangles || mode < 0) return count / 3;
    return count >= 2 ? count - 2 : 0;
}

}  // namespace scene
