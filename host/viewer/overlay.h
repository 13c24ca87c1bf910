// overlay.h - the viewer's on-screen text: the active settings and the
// plugin's per-pass GPU milliseconds, drawn with stb_easy_font (quads of
// pixels, no font texture) on a dark band at the top left.
#pragma once

#include "controls.h"

#include <ssao/ssao.h>

#include <glad/gl.h>

#include <string>
#include <vector>

namespace viewer {

// Screen pixels per font pixel for a window of width x height.
int overlay_scale(int width, int height);

// The width in screen pixels of `line` drawn at `scale`, its band's margins included.
int overlay_width(const std::string& line, int scale);

// The overlay's lines for this state (no GL; what the tests read), each as
// wide as a window of width x height shows: a longer line is broken at its
// double spaces (between "name value" groups), its continuation indented.
std::vector<std::string> overlay_lines(const State& state, const ssao_timings& timings, int width, int height);

class Overlay {
public:
    explicit Overlay(GladGLContext& gl);   // throws gl_util::Error
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    // Draws `lines` into framebuffer 0 of size width x height, each font pixel
    // `scale` screen pixels.
    void draw(const std::vector<std::string>& lines, int width, int height, int scale);

private:
    void release();
    GladGLContext& gl_;
    GLuint program_ = 0, vao_ = 0, vertices_ = 0, indices_ = 0;
    size_t index_capacity_ = 0;   // quads the index buffer covers
};

}  // namespace viewer
