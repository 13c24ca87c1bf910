// gl_state_snapshot.h - reads every piece of GL state the plugin promises to
// leave as it found it (the list in include/ssao/ssao.h), by name, so a test
// can say exactly which one changed.
#pragma once

#include <glad/gl.h>

#include <map>
#include <string>

namespace testgl {

using Snapshot = std::map<std::string, long long>;

inline Snapshot snapshot(GladGLContext& gl, int units = 4) {
    Snapshot s;
    auto geti = [&](const char* name, GLenum e) { GLint v = 0; gl.GetIntegerv(e, &v); s[name] = v; };
    auto getv = [&](const std::string& name, GLenum e, int n) {
        GLint v[4] = {};
        gl.GetIntegerv(e, v);
        for (int i = 0; i < n; ++i) s[name + "[" + std::to_string(i) + "]"] = v[i];
    };
    auto enabled = [&](const char* name, GLenum e) { s[name] = gl.IsEnabled(e); };
    geti("draw_framebuffer", GL_DRAW_FRAMEBUFFER_BINDING);
    geti("read_framebuffer", GL_READ_FRAMEBUFFER_BINDING);
    geti("program", GL_CURRENT_PROGRAM);
    geti("vertex_array", GL_VERTEX_ARRAY_BINDING);
    geti("active_texture", GL_ACTIVE_TEXTURE);
    GLint active = 0;
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (int u = 0; u < units; ++u) {
        gl.ActiveTexture(GL_TEXTURE0 + u);
        GLint t = 0, smp = 0;
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &t);
        gl.GetIntegerv(GL_SAMPLER_BINDING, &smp);
        s["unit" + std::to_string(u) + ".texture_2d"] = t;
        s["unit" + std::to_string(u) + ".sampler"] = smp;
    }
    gl.ActiveTexture(static_cast<GLenum>(active));
    geti("array_buffer", GL_ARRAY_BUFFER_BINDING);
    geti("uniform_buffer", GL_UNIFORM_BUFFER_BINDING);
    geti("pixel_unpack_buffer", GL_PIXEL_UNPACK_BUFFER_BINDING);
    geti("pixel_pack_buffer", GL_PIXEL_PACK_BUFFER_BINDING);
    for (GLuint i = 0; i < 4; ++i) {
        GLint b = 0;
        GLint64 start = 0, size = 0;
        gl.GetIntegeri_v(GL_UNIFORM_BUFFER_BINDING, i, &b);
        gl.GetInteger64i_v(GL_UNIFORM_BUFFER_START, i, &start);
        gl.GetInteger64i_v(GL_UNIFORM_BUFFER_SIZE, i, &size);
        s["uniform_binding" + std::to_string(i)] = b;
        s["uniform_start" + std::to_string(i)] = start;
        s["uniform_size" + std::to_string(i)] = size;
    }
    getv("viewport", GL_VIEWPORT, 4);
    getv("scissor_box", GL_SCISSOR_BOX, 4);
    for (GLuint i = 1; i < 4; ++i) {  // viewport arrays (GL 4.1)
        GLfloat v[4] = {};
        GLint b[4] = {};
        gl.GetFloati_v(GL_VIEWPORT, i, v);
        gl.GetIntegeri_v(GL_SCISSOR_BOX, i, b);
        for (int k = 0; k < 4; ++k) {
            s["viewport" + std::to_string(i) + "[" + std::to_string(k) + "]"] = static_cast<long long>(v[k]);
            s["scissor_box" + std::to_string(i) + "[" + std::to_string(k) + "]"] = b[k];
        }
        s["scissor_test" + std::to_string(i)] = gl.IsEnabledi(GL_SCISSOR_TEST, i);
    }
    enabled("scissor_test", GL_SCISSOR_TEST);
    enabled("depth_test", GL_DEPTH_TEST);
    enabled("stencil_test", GL_STENCIL_TEST);
    enabled("cull_face", GL_CULL_FACE);
    enabled("rasterizer_discard", GL_RASTERIZER_DISCARD);
    enabled("polygon_offset_fill", GL_POLYGON_OFFSET_FILL);
    enabled("color_logic_op", GL_COLOR_LOGIC_OP);
    enabled("sample_mask", GL_SAMPLE_MASK);
    enabled("dither", GL_DITHER);
    enabled("framebuffer_srgb", GL_FRAMEBUFFER_SRGB);
    enabled("multisample", GL_MULTISAMPLE);
    enabled("sample_alpha_to_coverage", GL_SAMPLE_ALPHA_TO_COVERAGE);
    for (GLuint i = 0; i < 8; ++i) {
        s["blend" + std::to_string(i)] = gl.IsEnabledi(GL_BLEND, i);
        GLboolean m[4] = {};
        gl.GetBooleani_v(GL_COLOR_WRITEMASK, i, m);
        s["color_mask" + std::to_string(i)] = m[0] | m[1] << 1 | m[2] << 2 | m[3] << 3;
        s["clip_distance" + std::to_string(i)] = gl.IsEnabled(GL_CLIP_DISTANCE0 + i);
    }
    getv("polygon_mode", GL_POLYGON_MODE, 2);
    GLboolean depth_mask = 0;
    gl.GetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
    s["depth_mask"] = depth_mask;
    geti("stencil_mask", GL_STENCIL_WRITEMASK);
    geti("stencil_back_mask", GL_STENCIL_BACK_WRITEMASK);
    geti("blend_src_rgb", GL_BLEND_SRC_RGB);
    geti("blend_dst_rgb", GL_BLEND_DST_RGB);
    geti("blend_equation", GL_BLEND_EQUATION_RGB);
    if (gl.ClipControl) {
        geti("clip_origin", GL_CLIP_ORIGIN);
        geti("clip_depth_mode", GL_CLIP_DEPTH_MODE);
    }
    const GLenum unpack[] = {GL_UNPACK_SWAP_BYTES, GL_UNPACK_LSB_FIRST, GL_UNPACK_ROW_LENGTH, GL_UNPACK_IMAGE_HEIGHT,
                             GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS, GL_UNPACK_SKIP_IMAGES, GL_UNPACK_ALIGNMENT,
                             GL_PACK_ALIGNMENT, GL_PACK_ROW_LENGTH};
    for (size_t i = 0; i < sizeof unpack / sizeof unpack[0]; ++i) {
        GLint v = 0;
        gl.GetIntegerv(unpack[i], &v);
        s["pixel_store" + std::to_string(i)] = v;
    }
    return s;
}

}  // namespace testgl
