// fuzz_abi.cpp - libFuzzer target: a byte-decoded sequence of ABI calls on a
// real EGL context (Mesa llvmpipe), as a hostile host would make them:
// create_context (with decoded settings and struct sizes), set_settings,
// execute with decoded textures (a pool of every target and format, deleted
// and random names), sizes, enums, floats, matrices and viewports, the
// getters, destroy; a host that makes another GL context current (an
// unrelated one, one sharing objects with the first, or none) and that
// deletes the library's output texture. After every call: the current
// context's GL state snapshot (tests/plugin/gl_state_snapshot.h) is
// unchanged, KHR_debug reported no GL error there, the status is a documented
// one, no bad input came back OK, and no call that touches GL came back OK on
// a GL context other than the one its ssao_context was created on.
#include "c_caller.h"
#include "gl_fixture.h"
#include "gl_state_snapshot.h"
#include "other_context.h"

#include <ssao/ssao.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <vector>

namespace {

[[noreturn]] void finding(const char* what, const std::string& detail = "") {
    std::fprintf(stderr, "fuzz_abi finding: %s %s\n", what, detail.c_str());
    std::abort();
}

// Reads the fuzz input front to back; zeros once it runs out.
struct Reader {
    const uint8_t* p;
    size_t left;
    bool empty() const { return left == 0; }
    void bytes(void* out, size_t n) {
        const size_t k = std::min(n, left);
        std::memcpy(out, p, k);
        std::memset(static_cast<uint8_t*>(out) + k, 0, n - k);
        p += k;
        left -= k;
    }
    uint8_t u8() { uint8_t v; bytes(&v, 1); return v; }
    uint32_t u32() { uint32_t v; bytes(&v, 4); return v; }
    float f32() { float v; bytes(&v, 4); return v; }
    // A small value most of the time, any 32 bits sometimes (enum fields).
    uint32_t small_or_raw(uint32_t range) {
        const uint8_t k = u8();
        return k < 200 ? k % range : u32();
    }
};

// The GL contexts a host may have current: the first one (where the
// textures live), an unrelated one, one sharing objects with the first, none.
enum Current { kFirst = 0, kUnrelated = 1, kShared = 2, kNone = 3 };

// The library, loaded once for the process (the world below may be rebuilt).
plugin::Library& library() {
    static plugin::Library* lib = [] {
        auto* l = new plugin::Library();
        std::string error;
        if (!l->open(plugin::Library::default_path(), error)) finding("cannot open the plugin", error);
        return l;
    }();
    return *lib;
}

struct World {
    std::unique_ptr<eglctx::Context> egl;
    std::unique_ptr<testgl::DebugErrors> errors;
    plugin::Library& lib = library();
    std::vector<GLuint> textures;  // every kind the decoder picks from
    testgl::Snapshot host_state;
    GLuint host_fbo = 0, host_vao = 0;
    std::unique_ptr<testgl::OtherContext> unrelated, shared;
    testgl::Snapshot unrelated_state, shared_state;
    Current current = kFirst;
    // Destroying the GL contexts frees every GL object made in them (the
    // library's too, after a destroy_context refused on another context).
    ~World() {
        shared.reset();
        unrelated.reset();
        egl.reset();
    }
};

void make_current(World& w, Current c) {
    switch (c) {
        case kFirst: w.unrelated->make_first_current(); break;
        case kUnrelated: w.unrelated->make_current(); break;
        case kShared: w.shared->make_current(); break;
        case kNone: w.unrelated->release_current(); break;
    }
    w.current = c;
}

GLuint texture_2d(GladGLContext& gl, GLenum internal, int w, int h) {
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D, t);
    gl.TexStorage2D(GL_TEXTURE_2D, 1, internal, w, h);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    return t;
}

World* make_world() {
    auto* x = new World();
    x->egl = testgl::make_debug_context(4, 5);
    GladGLContext& gl = x->egl->gl();
    x->errors = std::make_unique<testgl::DebugErrors>(gl);
    // 2D textures of every input and output format, at a few tiny sizes.
    const GLenum formats[] = {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32F,
                              GL_DEPTH24_STENCIL8,  GL_DEPTH32F_STENCIL8, GL_RGBA16F, GL_RGBA8, GL_RGBA32F,
                              GL_RGB10_A2, GL_RGBA8_SNORM, GL_RG8, GL_R8, GL_R16F, GL_R32UI, GL_RGBA8UI,
                              GL_RGBA16I, GL_SRGB8_ALPHA8};
    for (GLenum f : formats)
        for (int s : {1, 7, 16}) x->textures.push_back(texture_2d(gl, f, s, s == 7 ? 5 : s));
    // Other targets.
    GLuint t = 0;
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_3D, t);
    gl.TexStorage3D(GL_TEXTURE_3D, 1, GL_R32F, 16, 16, 2);
    x->textures.push_back(t);
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D_ARRAY, t);
    gl.TexStorage3D(GL_TEXTURE_2D_ARRAY, 1, GL_DEPTH_COMPONENT32F, 16, 16, 1);
    x->textures.push_back(t);
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_CUBE_MAP, t);
    gl.TexStorage2D(GL_TEXTURE_CUBE_MAP, 1, GL_RGBA16F, 16, 16);
    x->textures.push_back(t);
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_RECTANGLE, t);
    gl.TexStorage2D(GL_TEXTURE_RECTANGLE, 1, GL_DEPTH_COMPONENT32F, 16, 16);
    x->textures.push_back(t);
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, t);
    gl.TexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, 4, GL_RGBA8, 16, 16, GL_TRUE);
    x->textures.push_back(t);
    // (1.2) Multisampled inputs: depth and normals of matching and of
    // mismatched sample counts.
    const struct { GLenum format; int samples; } ms[] = {
        {GL_DEPTH_COMPONENT32F, 4}, {GL_DEPTH24_STENCIL8, 2}, {GL_RGBA16F, 4}, {GL_RGBA16F, 2}};
    for (const auto& m : ms) {
        gl.GenTextures(1, &t);
        gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, t);
        gl.TexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, m.samples, m.format, 16, 16, GL_TRUE);
        x->textures.push_back(t);
    }
    gl.BindTexture(GL_TEXTURE_2D_MULTISAMPLE, 0);
    GLuint buffer = 0;
    gl.GenBuffers(1, &buffer);
    gl.BindBuffer(GL_TEXTURE_BUFFER, buffer);
    gl.BufferData(GL_TEXTURE_BUFFER, 1024, nullptr, GL_STATIC_DRAW);
    gl.BindBuffer(GL_TEXTURE_BUFFER, 0);
    gl.GenTextures(1, &t);
    gl.BindTexture(GL_TEXTURE_BUFFER, t);
    gl.TexBuffer(GL_TEXTURE_BUFFER, GL_R32F, buffer);
    gl.BindTexture(GL_TEXTURE_BUFFER, 0);
    x->textures.push_back(t);
    gl.GenTextures(1, &t);  // a name never bound: not a texture yet
    x->textures.push_back(t);
    gl.GenTextures(1, &t);  // a deleted name
    gl.BindTexture(GL_TEXTURE_2D, t);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.DeleteTextures(1, &t);
    x->textures.push_back(t);
    x->textures.push_back(0);
    x->textures.push_back(123456);
    // A host with its own state: framebuffer, VAO, bindings, odd fixed function.
    GLuint color = texture_2d(gl, GL_RGBA8, 8, 8);
    gl.GenFramebuffers(1, &x->host_fbo);
    gl.BindFramebuffer(GL_FRAMEBUFFER, x->host_fbo);
    gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    gl.GenVertexArrays(1, &x->host_vao);
    gl.BindVertexArray(x->host_vao);
    gl.ActiveTexture(GL_TEXTURE2);
    gl.BindTexture(GL_TEXTURE_2D, x->textures[6]);
    gl.ViewportIndexedf(0, 1.5f, 2.25f, 5.75f, 6.5f);
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(1, 1, 3, 3);
    gl.Enable(GL_BLEND);
    gl.BlendFunc(GL_ONE, GL_ONE);
    gl.ColorMaski(0, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthMask(GL_FALSE);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.PixelStorei(GL_UNPACK_ROW_LENGTH, 3);
    gl.ClearColor(0.25f, 0.5f, 0.75f, 1.0f);
    x->host_state = testgl::snapshot(gl);
    if (!x->errors->messages().empty()) finding("GL error while setting up", x->errors->messages()[0]);
    // The other contexts, with state of their own.
    x->unrelated = std::make_unique<testgl::OtherContext>(testgl::OtherContext::Sharing::none);
    x->shared = std::make_unique<testgl::OtherContext>(testgl::OtherContext::Sharing::with_current);
    for (testgl::OtherContext* o : {x->unrelated.get(), x->shared.get()}) {
        o->make_current();
        GLuint vao = 0;
        o->gl().GenVertexArrays(1, &vao);
        o->gl().BindVertexArray(vao);
        o->gl().Enable(GL_BLEND);
        o->gl().Viewport(0, 0, 3, 3);
    }
    x->unrelated->make_current();
    x->unrelated_state = testgl::snapshot(x->unrelated->gl());
    x->shared->make_current();
    x->shared_state = testgl::snapshot(x->shared->gl());
    if (!x->unrelated->gl_errors().empty() || !x->shared->gl_errors().empty())
        finding("GL error while setting up the other contexts");
    x->unrelated->make_first_current();
    return x;
}

World* g_world = nullptr;

World& world() {
    if (!g_world) g_world = make_world();
    return *g_world;
}

// A destroy_context refused on the wrong GL context leaves the library's GL
// objects in the creating context until that context is destroyed (ssao.h):
// after such an input the world is discarded (world() makes a new one), so
// they do not pile up.
void discard_world() {
    delete g_world;
    g_world = nullptr;
}

bool documented(ssao_status st) {
    return st >= SSAO_OK && st <= SSAO_ERROR_WRONG_CONTEXT;
}

void check_after(World& w, const char* call, ssao_status st) {
    if (!documented(st)) finding("undocumented status from", call);
    if (st == SSAO_ERROR_INTERNAL) finding("SSAO_ERROR_INTERNAL from", call);
    if (w.current == kNone) return;  // no GL to look at
    GladGLContext& gl = w.current == kFirst ? w.egl->gl() : w.current == kUnrelated ? w.unrelated->gl() : w.shared->gl();
    const std::vector<std::string>& errors = w.current == kFirst       ? w.errors->messages()
                                             : w.current == kUnrelated ? w.unrelated->gl_errors()
                                                                       : w.shared->gl_errors();
    const testgl::Snapshot& state =
        w.current == kFirst ? w.host_state : w.current == kUnrelated ? w.unrelated_state : w.shared_state;
    if (!errors.empty()) finding("GL error after", std::string(call) + ": " + errors[0]);
    const testgl::Snapshot now = testgl::snapshot(gl);
    if (now != state) {
        for (const auto& e : state)
            if (now.at(e.first) != e.second) finding("GL state changed by", std::string(call) + ": " + e.first);
        finding("GL state changed by", call);
    }
}

// A call that touches GL, on a context created on another GL context: only
// the argument checks (which come first) or WRONG_CONTEXT may answer.
void check_wrong_context(const char* call, ssao_status st) {
    if (st != SSAO_ERROR_WRONG_CONTEXT && st != SSAO_ERROR_NULL_POINTER && st != SSAO_ERROR_STRUCT_SIZE)
        finding("not refused on the wrong GL context:", call);
}

// Settings: raw bytes, or a valid struct with a few decoded fields.
ssao_settings decode_settings(Reader& r) {
    ssao_settings s{};
    const uint8_t mode = r.u8();
    if (mode < 40) {
        r.bytes(&s, sizeof s);
        if (mode < 30) s.size = sizeof s;
        return s;
    }
    // Every published size (1.0, 1.1, 1.2), or any.
    s.size = mode < 200 ? sizeof s : mode < 220 ? SSAO_SETTINGS_SIZE_1_1 : mode < 240 ? SSAO_SETTINGS_SIZE_1_0 : r.u32();
    s.sample_count = r.small_or_raw(70);
    const uint8_t floats = r.u8();
    if (floats & 1) s.radius = r.f32();
    if (floats & 2) s.bias = r.f32();
    if (floats & 4) s.power = r.f32();
    if (floats & 8) s.strength = r.f32();
    if (floats & 16) s.blur_sigma = r.f32();
    if (floats & 32) s.blur_depth_tolerance = r.f32();
    if (floats & 64) s.depth_step_bias = r.f32();
    const uint32_t shape = r.small_or_raw(5), dist = r.small_or_raw(4), rot = r.small_or_raw(5),
                   blur = r.small_or_raw(6), fmt = r.small_or_raw(4);
    std::memcpy(&s.kernel_shape, &shape, 4);
    std::memcpy(&s.distribution, &dist, 4);
    std::memcpy(&s.rotation, &rot, 4);
    std::memcpy(&s.blur, &blur, 4);
    std::memcpy(&s.output_format, &fmt, 4);
    s.seed = r.u8();
    s.blur_radius = r.small_or_raw(18);
    // 1.1 and 1.2 fields.
    const uint32_t method = r.small_or_raw(4), resolution = r.small_or_raw(5), view = r.small_or_raw(6);
    std::memcpy(&s.method, &method, 4);
    std::memcpy(&s.resolution, &resolution, 4);
    std::memcpy(&s.debug_view, &view, 4);
    s.step_count = r.small_or_raw(34);
    const uint8_t more = r.u8();
    if (more & 1) s.thickness = r.f32();
    if (more & 2) s.fade_start = r.f32();
    if (more & 4) s.fade_end = r.f32();
    if (more & 8) s.radius_pixels = r.f32();
    return s;
}

void decode_matrix(Reader& r, float out[16]) {
    const uint8_t kind = r.u8();
    glm::mat4 m;
    switch (kind % 6) {
        case 0: m = glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f); break;
        case 1: m = glm::perspectiveRH_ZO(glm::radians(40.0f), 1.5f, 0.5f, 1e6f); break;
        case 2: m = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 50.0f); break;
        case 3: m = glm::infinitePerspective(glm::radians(75.0f), 0.75f, 0.01f); break;
        case 4: m = glm::perspectiveLH(glm::radians(60.0f), 1.0f, 0.1f, 100.0f); break;
        default: m = glm::mat4(0.0f); break;
    }
    std::memcpy(out, glm::value_ptr(m), sizeof(float) * 16);
    // Perturb a few elements with any float (denormals, huge, NaN, inf).
    for (int n = kind / 6 % 4; n > 0; --n) {
        const uint8_t at = r.u8() % 16;
        out[at] = r.f32();
    }
}

GLuint pick_texture(World& w, Reader& r) {
    const uint8_t k = r.u8();
    if (k == 255) return r.u32();
    return w.textures[k % w.textures.size()];
}

ssao_inputs decode_inputs(World& w, Reader& r) {
    ssao_inputs in{};
    const uint8_t size_mode = r.u8();
    in.size = size_mode < 230 ? sizeof in : size_mode < 250 ? SSAO_INPUTS_SIZE_1_1 : r.u32();
    in.depth_texture = pick_texture(w, r);
    in.normal_texture = pick_texture(w, r);
    in.output_texture = r.u8() < 160 ? 0 : pick_texture(w, r);
    const uint32_t space = r.small_or_raw(3), packing = r.small_or_raw(3), clip = r.small_or_raw(3);
    std::memcpy(&in.normal_space, &space, 4);
    std::memcpy(&in.normal_packing, &packing, 4);
    std::memcpy(&in.clip_range, &clip, 4);
    decode_matrix(r, in.projection);
    const glm::mat4 view(1.0f);
    std::memcpy(in.view_matrix, glm::value_ptr(view), sizeof in.view_matrix);
    if (r.u8() > 240) in.view_matrix[r.u8() % 16] = r.f32();
    const uint8_t vp = r.u8();
    if (vp >= 128) {
        for (int i = 0; i < 4; ++i) in.viewport[i] = vp >= 240 ? static_cast<int32_t>(r.u32()) : r.u8() % 20 - 2;
    }
    // 1.2: the sample read, the output mode, the TAA frame index.
    in.sample_index = r.small_or_raw(6);
    const uint32_t mode = r.small_or_raw(4);
    std::memcpy(&in.output_mode, &mode, 4);
    in.frame_index = r.u8() < 128 ? 0u : r.u32();
    return in;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    World& w = world();
    const ssao_api& a = w.lib.api();
    Reader r{data, size};
    ssao_context* ctx[2] = {nullptr, nullptr};
    Current creator[2] = {kFirst, kFirst};  // the GL context each was created on
    GLuint owned_output[2] = {0, 0};        // the library's output texture, as execute last returned it
    bool gl_objects_left = false;           // a destroy_context was refused on the wrong GL context
    if (w.current != kFirst) make_current(w, kFirst);
    for (int op = 0; op < 48 && !r.empty(); ++op) {
        const uint8_t code = r.u8();
        const int which = code >> 7;
        ssao_context* c = ctx[which];
        const bool wrong = c && creator[which] != w.current;
        switch ((code & 0x7f) % 11) {
            case 0: {  // create
                ssao_context*& slot = ctx[code >> 7];
                if (slot) break;
                ssao_context_desc desc{};
                desc.size = r.u8() < 250 ? sizeof desc : r.u32();
                desc.get_proc_address = &eglctx::Context::get_proc;
                ssao_settings s{};
                const bool with_settings = r.u8() & 1;
                if (with_settings) {
                    s = decode_settings(r);
                    desc.settings = &s;
                }
                const ssao_status st = a.create_context(&desc, &slot);
                check_after(w, "create_context", st);
                if ((st == SSAO_OK) != (slot != nullptr)) finding("create_context: status and context disagree");
                if (w.current == kNone && st == SSAO_OK) finding("create_context OK with no GL context current");
                creator[which] = w.current;
                owned_output[which] = 0;
                break;
            }
            case 1: {  // destroy: freed even when refused on the wrong GL context
                const ssao_status st = a.destroy_context(c);
                check_after(w, "destroy_context", st);
                if (wrong && st != SSAO_ERROR_WRONG_CONTEXT) finding("destroy_context not refused on the wrong GL context");
                if (wrong) gl_objects_left = true;
                ctx[which] = nullptr;
                break;
            }
            case 2: {  // set_settings
                const ssao_settings s = decode_settings(r);
                ssao_settings before{};
                before.size = sizeof before;
                if (c) a.get_settings(c, &before);
                const ssao_status st = a.set_settings(c, &s);
                check_after(w, "set_settings", st);
                if (c && st != SSAO_OK) {
                    ssao_settings after{};
                    after.size = sizeof after;
                    a.get_settings(c, &after);
                    if (std::memcmp(&before, &after, sizeof after) != 0) finding("refused settings were applied");
                }
                break;
            }
            case 3:
            case 4:
            case 5: {  // execute
                const ssao_inputs in = decode_inputs(w, r);
                ssao_output out{};
                out.size = r.u8() < 250 ? sizeof out : r.u32();
                const bool with_out = r.u8() >= 20;  // `out` may be NULL (ssao.h)
                const ssao_status st = a.execute(c, &in, with_out ? &out : nullptr);
                check_after(w, "execute", st);
                if (wrong) check_wrong_context("execute", st);
                if (st == SSAO_OK && with_out && in.output_texture == 0 && out.size == sizeof out)
                    owned_output[which] = out.texture;
                if (st == SSAO_OK) {
                    // 0 is "none" for the normal and "the library's own" for the output, so it matches nothing.
                    const GLuint written =
                        in.output_texture != 0 ? in.output_texture : (with_out && out.size == sizeof out ? out.texture : 0);
                    if (written != 0 && (in.depth_texture == written || in.normal_texture == written))
                        finding("execute OK with the output as an input");
                    GladGLContext& gl = w.egl->gl();
                    if (with_out && out.size == sizeof out && out.texture == 0)
                        finding("execute OK without an output texture");
                    if (with_out && in.output_texture != 0 && out.size == sizeof out && out.texture != in.output_texture)
                        finding("execute OK but wrote elsewhere than output_texture");
                    for (float v : in.projection)
                        if (!std::isfinite(v)) finding("execute OK with a non-finite projection");
                    (void)gl;
                }
                break;
            }
            case 6: {  // the getters
                ssao_timings t{};
                t.size = r.u8() < 240 ? sizeof t : r.u32();
                const ssao_status st = a.get_timings(c, &t);
                check_after(w, "get_timings", st);
                if (wrong) check_wrong_context("get_timings", st);
                ssao_frame_info fi{};
                fi.size = r.u8() < 240 ? sizeof fi : r.u32();
                check_after(w, "get_frame_info", a.get_frame_info(c, &fi));
                const char* e = a.last_error(c);
                if (!e) finding("last_error returned NULL");
                break;
            }
            case 7: {  // settings without a context
                const ssao_settings s = decode_settings(r);
                ssao_settings out{};
                out.size = sizeof out;
                check_after(w, "resolve_settings", a.resolve_settings(&s, &out));
                check_after(w, "preset_settings", unit_c_preset_raw(&a, r.small_or_raw(7), &out));
                break;
            }
            case 9: {  // the host makes another GL context current (or none)
                make_current(w, static_cast<Current>(r.u8() % 4));
                break;
            }
            case 10: {  // the host deletes the library's output texture (where that name is the texture)
                const bool sees_it = creator[which] == w.current || (creator[which] == kFirst && w.current == kShared) ||
                                     (creator[which] == kShared && w.current == kFirst);
                if (c && owned_output[which] != 0 && sees_it) {
                    GladGLContext& gl = w.current == kFirst ? w.egl->gl() : w.shared->gl();
                    gl.DeleteTextures(1, &owned_output[which]);
                    owned_output[which] = 0;
                    check_after(w, "glDeleteTextures(output)", SSAO_OK);
                }
                break;
            }
            default: {
                const char* text = a.status_string(static_cast<ssao_status>(r.u8() % 18));
                if (!text || !*text) finding("empty status string");
                break;
            }
        }
    }
    for (int i = 0; i < 2; ++i) {
        if (!ctx[i]) continue;
        make_current(w, creator[i]);
        const ssao_status st = a.destroy_context(ctx[i]);
        check_after(w, "destroy_context", st);
        if (st != SSAO_OK) finding("destroy_context refused on its own GL context");
    }
    make_current(w, kFirst);
    if (gl_objects_left) discard_world();
    return 0;
}
