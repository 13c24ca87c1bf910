// test_abi_nogl.cpp - the ABI entry points that need no GL context, through
// the dlopened libssao.so: ssao_get_api, status_string, resolve_settings,
// preset_settings, and every create_context failure that happens before (or
// without) a usable GL context.
#include <cstring>
#include "abi_common.h"
#include "c_caller.h"

#include <glad/gl.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

using namespace unit;

namespace {

const float kNaN = std::numeric_limits<float>::quiet_NaN();

// A settings struct with room after it, so that a test can see that a call
// wrote nothing beyond the size the caller declared.
struct PaddedSettings {
    ssao_settings s;
    unsigned char guard[64];
};

// Whether every byte of `s` from offset `size` to the end of ssao_settings still holds `fill`.
bool untouched_beyond(const ssao_settings& s, uint32_t size, unsigned char fill) {
    const unsigned char* bytes = reinterpret_cast<const unsigned char*>(&s);
    for (size_t i = size; i < sizeof(ssao_settings); ++i)
        if (bytes[i] != fill) return false;
    return true;
}

}  // namespace

TEST_CASE("abi: plugin::Library opens the plugin and the table is complete") {
    plugin::Library lib;
    std::string error;
    REQUIRE_MESSAGE(lib.open(plugin::Library::default_path(), error), error);
    const ssao_api& a = lib.api();
    CHECK(a.size == sizeof(ssao_api));
    CHECK(a.version == SSAO_API_VERSION);
    CHECK((a.status_string != nullptr));
    CHECK((a.resolve_settings != nullptr));
    CHECK((a.preset_settings != nullptr));
    CHECK((a.create_context != nullptr));
    CHECK((a.destroy_context != nullptr));
    CHECK((a.set_settings != nullptr));
    CHECK((a.get_settings != nullptr));
    CHECK((a.execute != nullptr));
    CHECK((a.get_timings != nullptr));
    CHECK((a.get_frame_info != nullptr));
    CHECK((a.last_error != nullptr));
}

TEST_CASE("abi: ssao_get_api rejects NULL and a too-small table and other versions and writes nothing then") {
    const PFN_ssao_get_api get_api = raw_get_api();
    CHECK(get_api(SSAO_API_VERSION, nullptr) == SSAO_ERROR_NULL_POINTER);

    for (uint32_t size : {0u, 4u, 8u, static_cast<uint32_t>(sizeof(ssao_api) - 8), static_cast<uint32_t>(sizeof(ssao_api) - 1)}) {
        CAPTURE(size);
        ssao_api table = sentinel<ssao_api>();
        table.size = size;
        const ssao_api before = table;
        CHECK(get_api(SSAO_API_VERSION, &table) == SSAO_ERROR_STRUCT_SIZE);
        CHECK(same_bytes(table, before));
    }
    const uint32_t refused[] = {SSAO_MAKE_VERSION(0, 0), SSAO_MAKE_VERSION(0, 9), SSAO_MAKE_VERSION(2, 0),
                                SSAO_MAKE_VERSION(2, 5), SSAO_MAKE_VERSION(1, 5), SSAO_MAKE_VERSION(1, 0xffff),
                                0xffffffffu};
    for (uint32_t version : refused) {
        CAPTURE(version);
        ssao_api table = sentinel<ssao_api>();
        const ssao_api before = table;
        CHECK(get_api(version, &table) == SSAO_ERROR_VERSION_MISMATCH);
        CHECK(same_bytes(table, before));
    }
    // 1.0 to 1.4 hosts are all served by this 1.4 library.
    for (uint32_t version : {SSAO_MAKE_VERSION(1, 4), SSAO_MAKE_VERSION(1, 3), SSAO_MAKE_VERSION(1, 2),
                             SSAO_MAKE_VERSION(1, 1), SSAO_MAKE_VERSION(1, 0)}) {
        CAPTURE(version);
        ssao_api t = sentinel<ssao_api>();
        REQUIRE(get_api(version, &t) == SSAO_OK);
        CHECK(t.version == SSAO_MAKE_VERSION(1, 4));
    }
    ssao_api table = sentinel<ssao_api>();
    REQUIRE(get_api(SSAO_MAKE_VERSION(1, 0), &table) == SSAO_OK);
    CHECK(table.version == SSAO_API_VERSION);
    CHECK(SSAO_VERSION_MAJOR(table.version) == 1u);
    CHECK((table.execute != nullptr));
    CHECK((table.last_error != nullptr));
}

TEST_CASE("abi: status_string is a distinct non-empty sentence per status and 'unknown status' otherwise") {
    const ssao_api& a = api();
    std::set<std::string> seen;
    for (int s = SSAO_OK; s <= SSAO_ERROR_WRONG_CONTEXT; ++s) {
        CAPTURE(s);
        ssao_status st;
        set_raw(st, s);
        const char* text = a.status_string(st);
        REQUIRE((text != nullptr));
        CHECK(std::strlen(text) > 0);
        CHECK(std::string(text) != "unknown status");
        CHECK(seen.insert(text).second);
    }
    CHECK(seen.size() == 17);
    for (int32_t s : {17, 18, 100, -1, 0x7fffffff}) {
        CAPTURE(s);
        // From C: a C++ caller cannot pass -1 as an ssao_status without undefined behaviour.
        const char* text = unit_c_status_string_raw(&a, static_cast<uint32_t>(s));
        REQUIRE((text != nullptr));
        CHECK(std::string(text) == "unknown status");
    }
}

TEST_CASE("abi: resolve_settings and preset_settings check pointers and sizes") {
    const ssao_api& a = api();
    ssao_settings in = sized<ssao_settings>();
    ssao_settings out = sized<ssao_settings>();
    CHECK(a.resolve_settings(nullptr, &out) == SSAO_ERROR_NULL_POINTER);
    CHECK(a.resolve_settings(&in, nullptr) == SSAO_ERROR_NULL_POINTER);
    CHECK(a.resolve_settings(nullptr, nullptr) == SSAO_ERROR_NULL_POINTER);
    CHECK(a.preset_settings(SSAO_PRESET_HIGH, nullptr) == SSAO_ERROR_NULL_POINTER);

    for (uint32_t size : {0u, static_cast<uint32_t>(sizeof(ssao_settings) - 2), static_cast<uint32_t>(sizeof(ssao_settings) + 4)}) {
        CAPTURE(size);
        // Wrong size of the input...
        ssao_settings bad_in = sized<ssao_settings>();
        bad_in.size = size;
        ssao_settings o = sentinel<ssao_settings>();
        ssao_settings before = o;
        CHECK(a.resolve_settings(&bad_in, &o) == SSAO_ERROR_STRUCT_SIZE);
        CHECK(same_bytes(o, before));
        // ...and of the output.
        o = sentinel<ssao_settings>();
        o.size = size;
        before = o;
        CHECK(a.resolve_settings(&in, &o) == SSAO_ERROR_STRUCT_SIZE);
        CHECK(same_bytes(o, before));
        o = sentinel<ssao_settings>();
        o.size = size;
        before = o;
        CHECK(a.preset_settings(SSAO_PRESET_LOW, &o) == SSAO_ERROR_STRUCT_SIZE);
        CHECK(same_bytes(o, before));
    }
}

TEST_CASE("abi: a 1.0-sized ssao_settings is read and written only up to its size") {
    // A host compiled against interface 1.0 hands a 64-byte struct: the
    // library reads the 1.1 fields as defaults and never writes past it.
    const ssao_api& a = api();
    PaddedSettings in{}, out{};
    std::memset(&in, 0xab, sizeof in);   // the tail beyond 64 bytes is garbage the library must not read
    std::memset(&out, 0xcd, sizeof out);
    std::memset(&in.s, 0, SSAO_SETTINGS_SIZE_1_0);
    in.s.size = SSAO_SETTINGS_SIZE_1_0;
    in.s.sample_count = 12;
    out.s.size = SSAO_SETTINGS_SIZE_1_0;
    REQUIRE(a.resolve_settings(&in.s, &out.s) == SSAO_OK);
    CHECK(out.s.size == SSAO_SETTINGS_SIZE_1_0);
    CHECK(out.s.sample_count == 12u);
    CHECK(out.s.radius > 0.0f);
    CHECK(untouched_beyond(out.s, SSAO_SETTINGS_SIZE_1_0, 0xcd));
    // The same 1.0 input into a full-size output: the 1.1 fields resolve to their defaults.
    ssao_settings full = sized<ssao_settings>();
    REQUIRE(a.resolve_settings(&in.s, &full) == SSAO_OK);
    ssao_settings zero = sized<ssao_settings>(), defaults = sized<ssao_settings>();
    REQUIRE(a.resolve_settings(&zero, &defaults) == SSAO_OK);
    CHECK(full.method == defaults.method);
    CHECK(full.thickness == defaults.thickness);
    CHECK(full.step_count == defaults.step_count);
    // A 1.0 output of a preset keeps its size too.
    out.s.size = SSAO_SETTINGS_SIZE_1_0;
    CHECK(a.preset_settings(SSAO_PRESET_HIGH, &out.s) == SSAO_OK);
    CHECK(out.s.size == SSAO_SETTINGS_SIZE_1_0);
}

TEST_CASE("abi: a 1.1-sized ssao_settings reads the 1.2 fields as off and is written only up to its size") {
    const ssao_api& a = api();
    PaddedSettings in{}, out{};
    std::memset(&in, 0xab, sizeof in);
    std::memset(&out, 0xcd, sizeof out);
    std::memset(&in.s, 0, SSAO_SETTINGS_SIZE_1_1);
    in.s.size = SSAO_SETTINGS_SIZE_1_1;
    in.s.step_count = 3;
    out.s.size = SSAO_SETTINGS_SIZE_1_1;
    REQUIRE(a.resolve_settings(&in.s, &out.s) == SSAO_OK);
    CHECK(out.s.size == SSAO_SETTINGS_SIZE_1_1);
    CHECK(out.s.step_count == 3u);
    CHECK(untouched_beyond(out.s, SSAO_SETTINGS_SIZE_1_1, 0xcd));
    ssao_settings full = sized<ssao_settings>();
    REQUIRE(a.resolve_settings(&in.s, &full) == SSAO_OK);
    CHECK(full.fade_start == 0.0f);
    CHECK(full.fade_end == 0.0f);
    CHECK(full.radius_pixels == 0.0f);
    CHECK(full.debug_view == SSAO_DEBUG_VIEW_NONE);
    CHECK(full.max_step_texels == 0.0f);  // 1.4's field: off
    // Sizes between the versions are refused.
    for (uint32_t size : {SSAO_SETTINGS_SIZE_1_1 - 4, SSAO_SETTINGS_SIZE_1_1 + 4, SSAO_SETTINGS_SIZE_1_2 - 4,
                          uint32_t(sizeof(ssao_settings)) + 4}) {
        CAPTURE(size);
        in.s.size = size;
        CHECK(a.resolve_settings(&in.s, &full) == SSAO_ERROR_STRUCT_SIZE);
    }
}

TEST_CASE("abi: a 1.2-sized ssao_settings keeps its fields, reads max_step_texels as off, is written up to its size") {
    const ssao_api& a = api();
    PaddedSettings in{}, out{};
    std::memset(&out, 0xcd, sizeof out);
    in.s.size = SSAO_SETTINGS_SIZE_1_2;
    in.s.radius_pixels = 40.0f;
    in.s.max_step_texels = 9.0f;  // beyond the 1.2 struct: must not be read
    out.s.size = SSAO_SETTINGS_SIZE_1_2;
    REQUIRE(a.resolve_settings(&in.s, &out.s) == SSAO_OK);
    CHECK(out.s.size == SSAO_SETTINGS_SIZE_1_2);
    CHECK(out.s.radius_pixels == 40.0f);
    CHECK(untouched_beyond(out.s, SSAO_SETTINGS_SIZE_1_2, 0xcd));
    ssao_settings full = sized<ssao_settings>();
    REQUIRE(a.resolve_settings(&in.s, &full) == SSAO_OK);
    CHECK(full.max_step_texels == 0.0f);
}

TEST_CASE("abi: max_step_texels is validated and kept") {
    const ssao_api& a = api();
    auto resolved = [&](float texels, ssao_status& st) {
        ssao_settings in = sized<ssao_settings>(), out = sized<ssao_settings>();
        in.max_step_texels = texels;
        st = a.resolve_settings(&in, &out);
        return out.max_step_texels;
    };
    ssao_status st{};
    CHECK(resolved(0.0f, st) == 0.0f);  // off
    CHECK(st == SSAO_OK);
    CHECK(resolved(0.5f, st) == 0.5f);
    CHECK(st == SSAO_OK);
    CHECK(resolved(1e6f, st) == 1e6f);
    CHECK(st == SSAO_OK);
    for (float bad : {-1.0f, 2e6f, NAN, INFINITY}) {
        CAPTURE(bad);
        resolved(bad, st);
        CHECK(st == SSAO_ERROR_INVALID_VALUE);
    }
}

TEST_CASE("abi: the 1.2 settings are validated: fade range, radius in pixels, debug view") {
    const ssao_api& a = api();
    auto status_of = [&](void (*edit)(ssao_settings&)) {
        ssao_settings in = sized<ssao_settings>(), out = sized<ssao_settings>();
        edit(in);
        return a.resolve_settings(&in, &out);
    };
    CHECK(status_of([](ssao_settings& s) { s.fade_start = 10.0f, s.fade_end = 20.0f; }) == SSAO_OK);
    CHECK(status_of([](ssao_settings& s) { s.fade_end = 20.0f; }) == SSAO_OK);  // fade from the camera
    CHECK(status_of([](ssao_settings& s) { s.fade_start = 10.0f; }) == SSAO_ERROR_INVALID_VALUE);  // no end
    CHECK(status_of([](ssao_settings& s) { s.fade_start = 20.0f, s.fade_end = 20.0f; }) == SSAO_ERROR_INVALID_VALUE);
    CHECK(status_of([](ssao_settings& s) { s.fade_start = 30.0f, s.fade_end = 20.0f; }) == SSAO_ERROR_INVALID_VALUE);
    CHECK(status_of([](ssao_settings& s) { s.fade_start = -1.0f, s.fade_end = 20.0f; }) == SSAO_ERROR_INVALID_VALUE);
    CHECK(status_of([](ssao_settings& s) { s.fade_end = INFINITY; }) == SSAO_ERROR_INVALID_VALUE);
    CHECK(status_of([](ssao_settings& s) { s.fade_end = NAN; }) == SSAO_ERROR_INVALID_VALUE);
    CHECK(status_of([](ssao_settings& s) { s.radius_pixels = 24.0f; }) == SSAO_OK);
    CHECK(status_of([](ssao_settings& s) { s.radius_pixels = -1.0f; }) == SSAO_ERROR_INVALID_VALUE);
    CHECK(status_of([](ssao_settings& s) { s.radius_pixels = 16385.0f; }) == SSAO_ERROR_INVALID_VALUE);
    CHECK(status_of([](ssao_settings& s) { s.radius_pixels = NAN; }) == SSAO_ERROR_INVALID_VALUE);
    CHECK(status_of([](ssao_settings& s) { s.debug_view = SSAO_DEBUG_VIEW_BLUR_WEIGHTS; }) == SSAO_OK);
    CHECK(status_of([](ssao_settings& s) { s.debug_view = static_cast<ssao_debug_view>(5); }) == SSAO_ERROR_INVALID_ENUM);
    CHECK(status_of([](ssao_settings& s) { s.debug_view = static_cast<ssao_debug_view>(-1); }) == SSAO_ERROR_INVALID_ENUM);
}

TEST_CASE("abi: resolve_settings and preset_settings through the library") {
    const ssao_api& a = api();
    ssao_settings in = sized<ssao_settings>();
    ssao_settings out = sentinel<ssao_settings>();
    REQUIRE(a.resolve_settings(&in, &out) == SSAO_OK);
    ssao_settings medium = sentinel<ssao_settings>();
    REQUIRE(a.preset_settings(SSAO_PRESET_MEDIUM, &medium) == SSAO_OK);
    ssao_settings def = sentinel<ssao_settings>();
    REQUIRE(a.preset_settings(SSAO_PRESET_DEFAULT, &def) == SSAO_OK);
    CHECK(same_bytes(medium, def));
    ssao_settings def_resolved = sentinel<ssao_settings>();
    REQUIRE(a.resolve_settings(&def, &def_resolved) == SSAO_OK);
    CHECK(same_bytes(out, def_resolved));  // a zeroed struct is the DEFAULT preset
    CHECK(out.radius == 0.5f);
    CHECK(def.radius == 0.0f);  // the preset leaves the radius to the host

    in.radius = kNaN;
    ssao_settings o = sentinel<ssao_settings>();
    const ssao_settings before = o;
    CHECK(a.resolve_settings(&in, &o) == SSAO_ERROR_INVALID_VALUE);
    CHECK(same_bytes(o, before));
    in = sized<ssao_settings>();
    set_raw(in.blur, 42);
    CHECK(a.resolve_settings(&in, &o) == SSAO_ERROR_INVALID_ENUM);
    CHECK(same_bytes(o, before));
    for (uint32_t raw : {6u, 0x7fffffffu, 0xffffffffu}) {
        CAPTURE(raw);
        CHECK(unit_c_preset_raw(&a, raw, &o) == SSAO_ERROR_INVALID_ENUM);
        CHECK(same_bytes(o, before));
    }
}

TEST_CASE("abi: create_context validates its arguments before touching GL") {
    const ssao_api& a = api();
    ssao_context* const poison = reinterpret_cast<ssao_context*>(static_cast<uintptr_t>(0x1234));
    LogRecorder log;
    ssao_context_desc desc = sized<ssao_context_desc>();
    desc.get_proc_address = eglctx::Context::get_proc;
    desc.log = LogRecorder::callback;
    desc.log_user = &log;

    CHECK(a.create_context(&desc, nullptr) == SSAO_ERROR_NULL_POINTER);
    ssao_context* ctx = poison;
    CHECK(a.create_context(nullptr, &ctx) == SSAO_ERROR_NULL_POINTER);
    CHECK(ctx == nullptr);

    for (uint32_t size : {0u, static_cast<uint32_t>(sizeof(ssao_context_desc) - 8), static_cast<uint32_t>(sizeof(ssao_context_desc) + 8)}) {
        CAPTURE(size);
        ssao_context_desc d = desc;
        d.size = size;
        ctx = poison;
        CHECK(a.create_context(&d, &ctx) == SSAO_ERROR_STRUCT_SIZE);
        CHECK(ctx == nullptr);
    }

    struct Case {
        const char* what;
        ssao_status expected;
        const char* keyword;
    };
    const Case cases[] = {{"get_proc_address NULL", SSAO_ERROR_NULL_POINTER, "get_proc_address"},
                          {"settings radius NaN", SSAO_ERROR_INVALID_VALUE, "radius"},
                          {"settings blur 9", SSAO_ERROR_INVALID_ENUM, "blur"},
                          {"settings size 0", SSAO_ERROR_STRUCT_SIZE, "size"}};
    for (const Case& c : cases) {
        const std::string what_ = c.what;
        CAPTURE(what_);
        ssao_context_desc d = desc;
        ssao_settings s = sized<ssao_settings>();
        if (std::strcmp(c.what, "get_proc_address NULL") == 0) d.get_proc_address = nullptr;
        if (std::strcmp(c.what, "settings radius NaN") == 0) s.radius = kNaN;
        if (std::strcmp(c.what, "settings blur 9") == 0) set_raw(s.blur, 9);
        if (std::strcmp(c.what, "settings size 0") == 0) s.size = 0;
        d.settings = &s;
        log.entries.clear();
        ctx = poison;
        CHECK(a.create_context(&d, &ctx) == c.expected);
        CHECK(ctx == nullptr);
        // There is no context to ask: the reason goes to the log.
        REQUIRE(log.entries.size() == 1);
        CHECK(log.entries[0].level == SSAO_LOG_ERROR);
        CHECK(contains(log.entries[0].message, c.keyword));
    }
}

namespace {

ssao_gl_proc SSAO_CALL get_proc_null(void*, const char*) { return nullptr; }

const char* g_fake_version = "";
const GLubyte* GLAD_API_PTR fake_get_string(GLenum) { return reinterpret_cast<const GLubyte*>(g_fake_version); }

// Real GL for everything except glGetString, which reports g_fake_version.
ssao_gl_proc SSAO_CALL get_proc_fake_version(void*, const char* name) {
    if (std::strcmp(name, "glGetString") == 0) return reinterpret_cast<ssao_gl_proc>(fake_get_string);
    return eglctx::Context::get_proc(nullptr, name);
}

}  // namespace

TEST_CASE("abi: create_context is GL_LOAD when get_proc_address returns NULL for everything") {
    const ssao_api& a = api();
    LogRecorder log;
    ssao_context_desc desc = sized<ssao_context_desc>();
    desc.get_proc_address = get_proc_null;
    desc.log = LogRecorder::callback;
    desc.log_user = &log;
    ssao_context* ctx = reinterpret_cast<ssao_context*>(static_cast<uintptr_t>(0x1234));
    CHECK(a.create_context(&desc, &ctx) == SSAO_ERROR_GL_LOAD);
    CHECK(ctx == nullptr);
    REQUIRE(log.entries.size() == 1);
    CHECK(log.entries[0].level == SSAO_LOG_ERROR);
    CHECK_FALSE(log.entries[0].message.empty());

    // The same with a GL context current.
    auto egl = make_egl();
    log.entries.clear();
    ctx = reinterpret_cast<ssao_context*>(static_cast<uintptr_t>(0x1234));
    CHECK(a.create_context(&desc, &ctx) == SSAO_ERROR_GL_LOAD);
    CHECK(ctx == nullptr);
    CHECK(log.entries.size() == 1);
}

TEST_CASE("abi: create_context is GL_VERSION when no GL context is current") {
    // No EGL context exists yet in this test (and fixtures of earlier tests
    // release theirs): glGetString through eglGetProcAddress returns NULL.
    const ssao_api& a = api();
    LogRecorder log;
    ssao_context_desc desc = sized<ssao_context_desc>();
    desc.get_proc_address = eglctx::Context::get_proc;
    desc.log = LogRecorder::callback;
    desc.log_user = &log;
    ssao_context* ctx = reinterpret_cast<ssao_context*>(static_cast<uintptr_t>(0x1234));
    CHECK(a.create_context(&desc, &ctx) == SSAO_ERROR_GL_VERSION);
    CHECK(ctx == nullptr);
    REQUIRE(log.entries.size() == 1);
    CHECK(log.entries[0].level == SSAO_LOG_ERROR);
    CHECK_FALSE(log.entries[0].message.empty());
}

TEST_CASE("abi: create_context is GL_VERSION for a GL older than 3.3 or a GL ES context") {
    const ssao_api& a = api();
    auto egl = make_egl();  // real GL behind every other function
    for (const char* version : {"3.2.0 Mesa 23.0", "2.1 Mesa", "1.4", "OpenGL ES 3.2 Mesa 23.0", "garbage"}) {
        const std::string what_ = version;
        CAPTURE(what_);
        g_fake_version = version;
        LogRecorder log;
        ssao_context_desc desc = sized<ssao_context_desc>();
        desc.get_proc_address = get_proc_fake_version;
        desc.log = LogRecorder::callback;
        desc.log_user = &log;
        ssao_context* ctx = reinterpret_cast<ssao_context*>(static_cast<uintptr_t>(0x1234));
        CHECK(a.create_context(&desc, &ctx) == SSAO_ERROR_GL_VERSION);
        CHECK(ctx == nullptr);
        REQUIRE(log.entries.size() == 1);
        CHECK(contains(log.entries[0].message, version));
    }
    // A 3.3 context is accepted.
    g_fake_version = "3.3 (Core Profile) Mesa";
    ssao_context_desc desc = sized<ssao_context_desc>();
    desc.get_proc_address = get_proc_fake_version;
    ssao_context* ctx = nullptr;
    CHECK(a.create_context(&desc, &ctx) == SSAO_OK);
    CHECK((ctx != nullptr));
    CHECK(a.destroy_context(ctx) == SSAO_OK);
}

TEST_CASE("abi: destroy_context(NULL) is OK and last_error(NULL) is a static message") {
    const ssao_api& a = api();
    CHECK(a.destroy_context(nullptr) == SSAO_OK);
    const char* text = a.last_error(nullptr);
    REQUIRE((text != nullptr));
    CHECK(std::strlen(text) > 0);
    CHECK(a.last_error(nullptr) == text);
}
