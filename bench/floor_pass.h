// floor_pass.h - the bandwidth floor: the cheapest full-screen pass that does
// what every SSAO pass must do at least once per pixel (read its depth and its
// normal, write one R8 value). Timed in the same run as the configurations, it
// is the physical anchor the benchmark reports every time as a multiple of:
// on a given machine no AO pass over the same pixels can be cheaper.
#pragma once

#include <glad/gl.h>

namespace bench {

class FloorPass {
public:
    // An R8 target of width x height; throws gl_util::Error on a GL failure.
    FloorPass(GladGLContext& gl, int width, int height);
    ~FloorPass();
    FloorPass(const FloorPass&) = delete;
    FloorPass& operator=(const FloorPass&) = delete;

    // One full-screen pass over depth and normal into the R8 target.
    void run(GLuint depth_texture, GLuint normal_texture);
    // GPU time of the last run in ms (waits for its queries).
    double last_ms();

private:
    GladGLContext& gl_;
    int width_, height_;
    GLuint target_ = 0, fbo_ = 0, program_ = 0, vao_ = 0;
    GLuint queries_[2] = {};
};

}  // namespace bench
