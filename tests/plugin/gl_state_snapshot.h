// gl_state_snapshot.h - reads every piece of GL state the plugin promises to
// leave as it found it (the list in include/ssao/ssao.h), by name, so a test
// can say exactly which one changed. Beyond that list it reads the state a
// real engine leaves set and execute must not disturb either.
#pragma once

#include <glad/gl.h>

#include <cstdint>
#include <cstring>
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
    // Floats compared by their bits: a viewport of 3.25 must not come back as 3.
    auto getf = [&](const std::string& name, GLenum e, int n) {
        GLfloat v[4] = {};
        gl.GetFloatv(e, v);
        for (int i = 0; i < n; ++i) {
            uint32_t bits = 0;
            std::memcpy(&bits, &v[i], sizeof bits);
            s[name + "[" + std::to_string(i) + "]"] = bits;
        }
    };
    geti("draw_framebuffer", GL_DRAW_FRAMEBUFFER_BINDING);
    geti("read_framebuffer", GL_READ_FRAMEBUFFER_BINDING);
    geti("program", GL_CURRENT_PROGRAM);
    geti("vertex_array", GL_VERTEX_ARRAY_BINDING);
    geti("active_texture", GL_ACTIVE_TEXTURE);
    GLint active = 0;
    gl.GetIntegerv(GL_ACTIVE_TEXTURE, &active);
    for (int u = 0; u < units; ++u) {
        gl.ActiveTexture(GL_TEXTURE0 + u);
        GLint t = 0, smp = 0, ms = 0;
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D, &t);
        gl.GetIntegerv(GL_SAMPLER_BINDING, &smp);
        gl.GetIntegerv(GL_TEXTURE_BINDING_2D_MULTISAMPLE, &ms);  // (1.2) MSAA inputs
        s["unit" + std::to_string(u) + ".texture_2d"] = t;
        s["unit" + std::to_string(u) + ".texture_2d_multisample"] = ms;
        s["unit" + std::to_string(u) + ".sampler"] = smp;
    }
    gl.ActiveTexture(static_cast<GLenum>(active));
    geti("array_buffer", GL_ARRAY_BUFFER_BINDING);
    geti("uniform_buffer", GL_UNIFORM_BUFFER_BINDING);
    geti("pixel_unpack_buffer", GL_PIXEL_UNPACK_BUFFER_BINDING);
    geti("pixel_pack_buffer", GL_PIXEL_PACK_BUFFER_BINDING);
    // Every other buffer binding point, each from the GL version that has it:
    // the library must neither need nor change any of them.
    GLint major = 0, minor = 0;
    gl.GetIntegerv(GL_MAJOR_VERSION, &major);
    gl.GetIntegerv(GL_MINOR_VERSION, &minor);
    const int version = major * 10 + minor;
    geti("element_array_buffer", GL_ELEMENT_ARRAY_BUFFER_BINDING);  // of the bound vertex array
    geti("copy_read_buffer", GL_COPY_READ_BUFFER_BINDING);
    geti("copy_write_buffer", GL_COPY_WRITE_BUFFER_BINDING);
    geti("texture_buffer", GL_TEXTURE_BUFFER_BINDING);
    geti("transform_feedback_buffer", GL_TRANSFORM_FEEDBACK_BUFFER_BINDING);
    if (version >= 40) geti("draw_indirect_buffer", GL_DRAW_INDIRECT_BUFFER_BINDING);
    if (version >= 42) geti("atomic_counter_buffer", GL_ATOMIC_COUNTER_BUFFER_BINDING);
    if (version >= 43) {
        geti("dispatch_indirect_buffer", GL_DISPATCH_INDIRECT_BUFFER_BINDING);
        geti("shader_storage_buffer", GL_SHADER_STORAGE_BUFFER_BINDING);
    }
    if (version >= 44) geti("query_buffer", GL_QUERY_BUFFER_BINDING);
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
        GLfloat range[2] = {};
        gl.GetFloati_v(GL_DEPTH_RANGE, i, range);
        for (int k = 0; k < 2; ++k) {
            uint32_t bits = 0;
            std::memcpy(&bits, &range[k], sizeof bits);
            s["depth_range" + std::to_string(i) + "[" + std::to_string(k) + "]"] = bits;
        }
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
    // What a real engine leaves set between passes.
    getf("viewport_f", GL_VIEWPORT, 4);  // index 0 exactly, sub-pixel included
    enabled("primitive_restart", GL_PRIMITIVE_RESTART);
    enabled("primitive_restart_fixed_index", GL_PRIMITIVE_RESTART_FIXED_INDEX);
    geti("primitive_restart_index", GL_PRIMITIVE_RESTART_INDEX);
    enabled("depth_clamp", GL_DEPTH_CLAMP);
    enabled("program_point_size", GL_PROGRAM_POINT_SIZE);
    getf("depth_range", GL_DEPTH_RANGE, 2);
    getf("line_width", GL_LINE_WIDTH, 1);
    geti("blend_src_alpha", GL_BLEND_SRC_ALPHA);
    geti("blend_dst_alpha", GL_BLEND_DST_ALPHA);
    geti("blend_equation_alpha", GL_BLEND_EQUATION_ALPHA);
    getf("blend_color", GL_BLEND_COLOR, 4);
    for (GLenum e : {GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_FAIL,
                     GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_REF,
                     GL_STENCIL_BACK_VALUE_MASK, GL_STENCIL_BACK_FAIL, GL_STENCIL_BACK_PASS_DEPTH_FAIL,
                     GL_STENCIL_BACK_PASS_DEPTH_PASS})
        geti(("stencil_0x" + std::to_string(e)).c_str(), e);
    getf("clear_color", GL_COLOR_CLEAR_VALUE, 4);
    getf("clear_depth", GL_DEPTH_CLEAR_VALUE, 1);
    geti("clear_stencil", GL_STENCIL_CLEAR_VALUE);
    geti("transform_feedback", GL_TRANSFORM_FEEDBACK_BINDING);
    const GLenum pack[] = {GL_PACK_SWAP_BYTES, GL_PACK_LSB_FIRST, GL_PACK_ROW_LENGTH, GL_PACK_IMAGE_HEIGHT,
                           GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_IMAGES, GL_PACK_ALIGNMENT};
    for (size_t i = 0; i < sizeof pack / sizeof pack[0]; ++i) {
        GLint v = 0;
        gl.GetIntegerv(pack[i], &v);
        s["pack_store" + std::to_string(i)] = v;
    }
    // Draw and read buffers of whatever framebuffer the host has bound.
    GLint max_draw_buffers = 0;
    gl.GetIntegerv(GL_MAX_DRAW_BUFFERS, &max_draw_buffers);
    for (GLint i = 0; i < max_draw_buffers; ++i) {
        GLint v = 0;
        gl.GetIntegerv(GL_DRAW_BUFFER0 + static_cast<GLenum>(i), &v);
        s["draw_buffer" + std::to_string(i)] = v;
        GLboolean m[4] = {};
        gl.GetBooleani_v(GL_COLOR_WRITEMASK, static_cast<GLuint>(i), m);
        s["color_mask_all" + std::to_string(i)] = m[0] | m[1] << 1 | m[2] << 2 | m[3] << 3;
        s["blend_all" + std::to_string(i)] = gl.IsEnabledi(GL_BLEND, static_cast<GLuint>(i));
    }
    geti("read_buffer", GL_READ_BUFFER);
    enabled("texture_cube_map_seamless", GL_TEXTURE_CUBE_MAP_SEAMLESS);
    geti("provoking_vertex", GL_PROVOKING_VERTEX);
    enabled("sample_coverage", GL_SAMPLE_COVERAGE);
    getf("sample_coverage_value", GL_SAMPLE_COVERAGE_VALUE, 1);
    {
        GLboolean invert = 0;
        gl.GetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &invert);
        s["sample_coverage_invert"] = invert;
    }
    {
        GLint mask = 0;  // indexed state: word 0 of the sample mask
        gl.GetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &mask);
        s["sample_mask_value0"] = mask;
    }
    geti("depth_func", GL_DEPTH_FUNC);
    geti("cull_face_mode", GL_CULL_FACE_MODE);
    geti("front_face", GL_FRONT_FACE);
    geti("logic_op_mode", GL_LOGIC_OP_MODE);
    getf("polygon_offset_factor", GL_POLYGON_OFFSET_FACTOR, 1);
    getf("polygon_offset_units", GL_POLYGON_OFFSET_UNITS, 1);
    enabled("polygon_offset_line", GL_POLYGON_OFFSET_LINE);
    enabled("line_smooth", GL_LINE_SMOOTH);
    enabled("polygon_smooth", GL_POLYGON_SMOOTH);
    enabled("sample_alpha_to_one", GL_SAMPLE_ALPHA_TO_ONE);
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

// The entries of `before` that `after` lacks or holds another value for, as
// "name before -> after; ..." (empty when the state was kept).
inline std::string changed_state(const Snapshot& before, const Snapshot& after) {
    std::string changed;
    for (const auto& entry : before) {
        const auto it = after.find(entry.first);
        if (it != after.end() && it->second == entry.second) continue;
        changed += entry.first + " " + std::to_string(entry.second) + " -> " +
                   (it == after.end() ? std::string("(missing)") : std::to_string(it->second)) + "; ";
    }
    return changed;
}

}  // namespace testgl
